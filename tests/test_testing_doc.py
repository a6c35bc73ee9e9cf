"""docs/tests.md, the suite's figures and bounds test by test, is generated
from the tests' docstrings and decorators (scripts/testing_doc.py), so that it
cannot say what a test no longer says: a stale page fails here, naming the
first test file that differs."""
import ast
import shutil
import subprocess
import sys

from conftest import ROOT

SCRIPT = ROOT / "scripts" / "testing_doc.py"


def check(root):
    return subprocess.run([sys.executable, str(root / "scripts" / "testing_doc.py"), "--check"],
                          cwd=root, capture_output=True, text=True)


def test_tests_page_is_current():
    p = check(ROOT)
    assert p.returncode == 0, p.stdout + p.stderr


def copy(tmp_path):
    """The script, the test files and the page in tmp_path."""
    (tmp_path / "scripts").mkdir()
    shutil.copy(SCRIPT, tmp_path / "scripts")
    (tmp_path / "tests").mkdir()
    for f in sorted((ROOT / "tests").glob("test_*.py")):
        shutil.copy(f, tmp_path / "tests")
    (tmp_path / "docs").mkdir()
    shutil.copy(ROOT / "docs" / "tests.md", tmp_path / "docs")
    return tmp_path


def changed_docstring(path):
    """The first test of a file with a docstring, its docstring's first line
    changed: (file name, test name)."""
    text = path.read_text()
    tree = ast.parse(text)
    test = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name.startswith("test")
                and ast.get_docstring(n))
    doc = test.body[0].value
    lines = text.splitlines(keepends=True)
    line = lines[doc.lineno - 1]
    at = doc.col_offset + 3
    assert line[doc.col_offset:at] in ('"""', "'''"), line
    lines[doc.lineno - 1] = line[:at] + "Changed. " + line[at:]
    path.write_text("".join(lines))
    return path.name, test.name


def test_stale_page_names_first_file(tmp_path):
    """A docstring changed in a test file: --check fails naming that file
    (the first of two changed), and --update makes the page current; a test
    file added or removed is named too, and a changed test by its name."""
    root = copy(tmp_path)
    files = sorted(root.glob("tests/test_*.py"))
    for f in (files[-1], files[1]):
        f.write_text(f.read_text().replace('"""', '"""A changed docstring: ', 1))
    p = check(root)
    assert p.returncode == 1
    assert f"first at tests/{files[1].name} " in p.stdout, p.stdout
    subprocess.run([sys.executable, str(root / "scripts" / "testing_doc.py"), "--update"], cwd=root, check=True)
    assert check(root).returncode == 0
    files[2].rename(root / "tests" / "test_zz_added.py")
    p = check(root)
    assert p.returncode == 1
    assert f"first at tests/{files[2].name} (in docs/tests.md, but no such test file)" in p.stdout, p.stdout
    (root / "tests" / "test_zz_added.py").rename(files[2])
    name, test = changed_docstring(files[3])
    p = check(root)
    assert f"first at tests/{name}, {test} " in p.stdout, p.stdout
    files[3].write_text((ROOT / "tests" / name).read_text())
    (root / "tests" / "test_zz_new.py").write_text('"""New."""\n\ndef test_new():\n    """Checks."""\n')
    p = check(root)
    assert "first at tests/test_zz_new.py (missing from docs/tests.md)" in p.stdout, p.stdout


def test_page_records_decorators(tmp_path):
    """The count of test functions, parametrisations (literal values, a
    module-level list, pytest.param with a mark, ids) and marks, docstrings
    whose characters Markdown would take for markup, and the regression
    cases under test_cases.py."""
    sys.path.insert(0, str(ROOT / "scripts"))
    import testing_doc
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "test_x.py").write_text('''"""Module: -<body>_load, E* and R*.

- an item
  - 1 / 2, a continuation
- another item

  key   value
        more

Refused:
- one
  more
- two
After, a value
- 1 and no list.
"""
import pytest

CASES = [(0.1, "a"), pytest.param(0.2, "b", marks=pytest.mark.stress)]


@pytest.mark.parametrize("h, name", CASES)
@pytest.mark.parametrize("q", [0, 1], ids=["tri6", "quad9"])
def test_one(h, name, q, tmp_path):
    """First line.
    # not a heading
    > not a quote
    see [a](b) and `k_p*2`"""


@pytest.mark.xfail(strict=True, reason="not yet")
@pytest.mark.parametrize("opts", sorted({"x": 1}))
def test_two(opts):
    pass


def helper():
    """Not a test."""
''')
    (tmp_path / "tests" / "test_cases.py").write_text('"""Cases."""\n\ndef test_case(path):\n    pass\n')
    (tmp_path / "tests" / "cases").mkdir()
    (tmp_path / "tests" / "cases" / "one.toml").write_text(
        'description = "A case."\noptions_file = "s.opts"\nranks = [1, 2]\n\n[[expect]]\nkey = "energy"\n'
        'value = 1.0\nrtol = 1e-10\nsource = "exact, *measured* 1e-12"\n\n[compare_ranks]\nkeys = ["energy"]\nrtol = 1e-12\n')
    text = testing_doc.join(testing_doc.render(tmp_path))
    assert ("#### `cases/one.toml`\n\nA case.\n\n- scene `s.opts`\n- ranks 1, 2\n"
            "- `energy` = `1.0`, rtol 1e-10: exact, \\*measured\\* 1e-12\n"
            "- the rank counts agree in `energy` to rtol 1e-12\n") in text
    assert "## `test_x.py`: 2 test functions\n" in text
    assert "Module: -\\<body>\\_load, E\\* and R\\*." in text
    assert "- an item\n  \\- 1 / 2, a continuation\n- another item\n" in text
    assert "\n    key   value\n          more\n" in text
    assert "Refused:\n\n- one\n  more\n- two\n\nAfter, a value\n\\- 1 and no list.\n" in text
    assert ('- `h, name` (from `CASES`): `(0.1, "a")`, `(0.2, "b")` (marked `stress`)\n'
            '- `q`: `0` (`tri6`), `1` (`quad9`)\n') in text
    assert "\\# not a heading\n\\> not a quote\nsee [a]\\(b) and `k_p*2`\n" in text
    assert "- `opts`: the values of `sorted({\"x\": 1})`\n- marked `xfail`, strict, not yet\n\n(no docstring)" in text
    assert "helper" not in text
    assert text == testing_doc.join(testing_doc.render(tmp_path))
