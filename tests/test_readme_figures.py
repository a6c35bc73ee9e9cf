"""The README's tables of measured figures are rendered from committed results
(scripts/readme_figures.py): a table typed by hand, or results committed
without their table, fail here."""
import subprocess
import sys

from conftest import ROOT


def test_readme_tables_match_results():
    p = subprocess.run([sys.executable, str(ROOT / "scripts" / "readme_figures.py"), "--check"],
                       cwd=ROOT, capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
