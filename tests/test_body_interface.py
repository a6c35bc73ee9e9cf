"""The Body behind its interface (include/body.h): its struct is private to
src/body/ (src/body/bodyimpl.h), and what differs between an elastic and a
rigid body is the body's table of operations, not a test of its kind in the
caller. Read from the sources, so that a new caller that reaches into the
struct, or branches on a rigid flag, fails here rather than in a review."""
import re

from conftest import ROOT

SRC = ROOT / "src"


def outside_body():
    return sorted(p for p in SRC.rglob("*.[ch]") if p.parent.name != "body")


def test_struct_private_to_src_body():
    """No source file outside src/body/ includes the private header, and no
    public header defines the Body's struct or its rigid part's."""
    including = [str(p.relative_to(ROOT)) for p in outside_body() if "bodyimpl.h" in re.sub(r"/\*.*?\*/", "", p.read_text(), flags=re.S)]
    assert including == []
    defining = [str(p.relative_to(ROOT)) for p in (ROOT / "include").glob("*.h") if re.search(r"struct _n_Body(Rigid)?\s*\{", p.read_text())]
    assert defining == []


def test_no_rigid_flag_outside_src_body():
    """No member named rigid is read outside src/body/ (a force control's
    rigid-motion unknown is named motion, the body is asked BodyHasCells or
    BodyGetRigidMotion, and the rest dispatches through the body)."""
    hits = [f"{p.relative_to(ROOT)}:{i + 1}" for p in outside_body() for i, line in enumerate(p.read_text().splitlines()) if re.search(r"->rigid\b", line)]
    assert hits == []
