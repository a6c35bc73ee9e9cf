"""The documentation (README.md, docs/*.md, bench/README.md): its tables of
measured figures, and the phrases of the README's prose quoting them, are
rendered from committed results (scripts/readme_figures.py), so that a table
or phrase typed by hand, or results committed without it, fail here; and every link between its pages
reaches a file and, where it names one, a heading of that file."""
import re
import subprocess
import sys

import pytest

from conftest import ROOT

PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md")) + [ROOT / "bench" / "README.md"]
FIGURES = ROOT / "scripts" / "readme_figures.py"


def test_readme_tables_match_results():
    p = subprocess.run([sys.executable, str(FIGURES), "--check"], cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    for page in ("docs/formulations.md", "docs/solver.md", "bench/README.md"):
        assert page in p.stdout, p.stdout


def test_pages_are_the_documentation():
    """The pages the script reads are the ones this test checks."""
    sys.path.insert(0, str(ROOT / "scripts"))
    import readme_figures
    assert [ROOT / p for p in readme_figures.pages()] == PAGES
    assert (ROOT / readme_figures.PICTURE).is_file()


@pytest.mark.parametrize("page, change, message", [
    ("docs/solver.md", lambda text: text.replace("<!-- figures:solver:end -->", ""),
     "docs/solver.md: table solver has no end marker"),
    ("README.md", lambda text: text + "\n<!-- figures:solver:begin -->\n<!-- figures:solver:end -->\n",
     "table solver has markers on two pages: README.md and docs/solver.md"),
    ("bench/README.md", lambda text: text.replace("<!-- figures:stress:begin -->", "").replace("<!-- figures:stress:end -->", ""),
     "no page (README.md, docs/"),
    ("README.md", lambda text: text.replace(" <!-- figures:solver-speed:begin -->", "\n<!-- figures:solver-speed:begin -->"),
     "README.md: phrase solver-speed's begin marker must stand inside a line"),
    ("README.md", lambda text: text.replace("<!-- figures:lmvm-ratio:end -->", ""),
     "README.md: phrase lmvm-ratio has no end marker"),
    ("README.md", lambda text: text.replace("<!-- figures:speed-targets:end -->", "\n\n<!-- figures:speed-targets:end -->"),
     "README.md: phrase speed-targets runs over a paragraph's end"),
])
def test_marker_errors_name_the_page(page, change, message, tmp_path):
    """A table's markers left unclosed, on two pages or on none stop the
    check with a line naming the page (the script and a copy of the pages in
    tmp_path)."""
    (tmp_path / "scripts").mkdir()
    (tmp_path / "scripts" / "readme_figures.py").write_text(FIGURES.read_text())
    for p in PAGES:
        dest = tmp_path / p.relative_to(ROOT)
        dest.parent.mkdir(parents=True, exist_ok=True)
        dest.write_text(p.read_text())
    (tmp_path / page).write_text(change((ROOT / page).read_text()))
    p = subprocess.run([sys.executable, str(tmp_path / "scripts" / "readme_figures.py"), "--check"],
                       cwd=tmp_path, capture_output=True, text=True)
    assert p.returncode != 0
    assert message in p.stdout + p.stderr, p.stdout + p.stderr


def test_phrases_compare_word_by_word():
    """A phrase's line breaks and indentation are the page's; its words, and a
    table's every character, are the results'."""
    sys.path.insert(0, str(ROOT / "scripts"))
    import readme_figures
    assert not readme_figures.differs("lmvm-ratio", "0.75 to 1.35 times\n  Newton's time", "0.75 to 1.35 times Newton's time")
    assert readme_figures.differs("lmvm-ratio", "0.75 to 1.34 times Newton's time", "0.75 to 1.35 times Newton's time")
    assert readme_figures.differs("scenes", "| a |\n| b |\n", "| a | | b |\n")


def test_phrases_keep_the_page_layout():
    """--update lays a phrase's new words out as the page's prose: on from its
    column, then on lines indented as its second line was (or as a list
    item's text continues), each within the prose width; the words are the
    rendering's."""
    sys.path.insert(0, str(ROOT / "scripts"))
    import readme_figures
    words = " ".join(f"w{k}" for k in range(60))
    for text, indent in [("- L-BFGS: <!-- b -->old<!-- e --> (table); more\n  text\n", "  "),
                         ("Some prose <!-- b -->old words\n   on two lines<!-- e -->.\n", "   ")]:
        i, j = text.index("-->") + 3, text.index("<!-- e")
        out = text[:i] + readme_figures.wrap_phrase(text, i, j, words) + text[j:]
        phrase = out[i:out.index("<!-- e")]
        assert phrase.split() == words.split()
        assert all(len(line) <= readme_figures.PROSE_WIDTH for line in out[:out.index("<!-- e")].splitlines())
        assert all(line.startswith(indent) and not line.startswith(indent + " ") for line in phrase.splitlines()[1:])
        assert len(phrase.splitlines()) > 1


def anchor(heading):
    """GitHub's anchor of a heading: lower case, punctuation but - and _
    dropped, spaces as hyphens."""
    text = re.sub(r"`([^`]*)`", r"\1", heading.strip().lower())
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def headings(path):
    """The anchors of a Markdown file's headings (outside code), a repeated
    heading numbered as GitHub numbers it."""
    out, seen, fenced = set(), {}, False
    for line in path.read_text().splitlines():
        if line.startswith("```"):
            fenced = not fenced
        m = re.match(r"(#{1,6}) +(.*?) *#* *$", line)
        if m and not fenced:
            a = anchor(m.group(2))
            n = seen.get(a, 0)
            seen[a] = n + 1
            out.add(a if n == 0 else f"{a}-{n}")
    return out


def links(path):
    """(line number, target) of every Markdown link and image of a page,
    code (indented blocks, fences and spans) left out."""
    fenced = False
    for k, line in enumerate(path.read_text().splitlines(), 1):
        if line.startswith("```"):
            fenced = not fenced
        if fenced or line.startswith("    "):
            continue
        for m in re.finditer(r"\]\(([^)\s]+)\)", re.sub(r"`[^`]*`", "", line)):
            yield k, m.group(1)


def broken_links():
    bad = []
    for page in PAGES:
        for k, target in links(page):
            if re.match(r"[a-z]+:", target):
                continue
            path, _, frag = target.partition("#")
            dest = (page.parent / path).resolve() if path else page
            where = f"{page.relative_to(ROOT)}:{k}: {target}"
            if not dest.exists():
                bad.append(where + " (no such file)")
            elif frag and (dest.suffix != ".md" or frag not in headings(dest)):
                bad.append(where + " (no such heading)")
    return bad


def test_links_resolve():
    assert broken_links() == []


def test_link_check_finds_a_broken_anchor(tmp_path, monkeypatch):
    page = tmp_path / "page.md"
    page.write_text("# A page\n\n## Its `-accuracy` part\n\n[ok](#its--accuracy-part) [bad](#nowhere)\n"
                    "[file](other.md) [code](`no`)\n\n    [indented](#code)\n")
    monkeypatch.setattr(sys.modules[__name__], "PAGES", [page])
    monkeypatch.setattr(sys.modules[__name__], "ROOT", tmp_path)
    assert broken_links() == ["page.md:5: #nowhere (no such heading)", "page.md:6: other.md (no such file)"]


def test_readme_is_a_guide():
    """The README stays a guide (the reference is in docs/ and bench/): at
    most 400 lines, opening with the two commands, showing the picture."""
    sys.path.insert(0, str(ROOT / "scripts"))
    import readme_figures
    text = (ROOT / "README.md").read_text()
    assert len(text.splitlines()) <= 400
    commands = [l.split()[:2] for l in text.splitlines()[:6] if l.startswith("    make ")]
    assert commands == [["make", "run"], ["make", "test"]]
    assert f"]({readme_figures.PICTURE})" in text


def test_files_page_names_every_file(tmp_path):
    """docs/files.md, the list of the repository's files (the README points to
    it), is what scripts/files_doc.py makes of the files' own headers: a file
    added, removed or re-described without it fails here. And it names every
    C source, script and test helper module (against the file system, not
    the script's own list)."""
    script = ROOT / "scripts" / "files_doc.py"
    p = subprocess.run([sys.executable, str(script), "--check"], cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    text = (ROOT / "docs" / "files.md").read_text()
    wanted = sorted(ROOT.glob("src/*/*.c")) + sorted(ROOT.glob("scripts/*.py")) + sorted(ROOT.glob("scripts/*.sh"))
    wanted += [f for f in sorted(ROOT.glob("tests/*.py")) if not f.name.startswith(("test_", "conftest"))]
    missing = [str(f.relative_to(ROOT)) for f in wanted if f"| `{f.name}` |" not in text]
    assert not missing, missing


def test_force_control_table():
    """results/force_control.json (scripts/force_control_table.py), which the
    docs quote, is what they say of it: on every scene and rank count the
    coupled type converged, found the imposed displacements (within 1e-8;
    the displacement run's own stop at -tao_gttol 1e-8 is the reference's
    error) and took at most 1.5 times the displacement run's Newton
    iterations plus 2. The roller rows (a body held by contact alone) find
    it within 1e-4 (the committed rows: 6.6e-7 at h = 0.02, 1.5e-5 at
    0.03): where the roller rests along its flat races is not determined by
    the scene (unheld.c leaves that motion where it is), so the two runs'
    contacts meet other elements (test_roller.py's
    test_displacement_is_the_force_runs_reference). A check of committed
    results: it runs nothing."""
    import json
    rows = json.loads((ROOT / "results" / "force_control.json").read_text())["rows"]
    assert {(r["scene"], r["ranks"]) for r in rows} >= {(s, n) for s in ("hertz", "softdisc-fine", "sphere", "pinch")
                                                       for n in (1, 2)}
    for r in rows:
        c = r["coupled"]
        bound = 1e-4 if r["scene"].startswith("roller") else 1e-8
        assert c["status"] == 0 and c["relative_error"] <= bound, (r["scene"], r["ranks"], c)
        assert c["iterations"] <= 1.5 * r["displacement_run"]["iterations"] + 2, (r["scene"], r["ranks"], c["iterations"])
