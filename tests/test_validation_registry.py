"""Every validation case is registered once, listed, and run (quick) by some test."""

import re
from pathlib import Path

from cosim import validation

TESTS = Path(__file__).resolve().parent


def test_every_case_has_a_quick_run_in_the_fast_tier():
    texts = [p.read_text() for p in TESTS.glob("test_*.py") if p.name != Path(__file__).name]
    # run("NAME", quick=True), or the name in a file whose cases run quick from a list or
    # a parameter (run(name, quick=True), run(..., quick=quick))
    quick_call = re.compile(r"""run\(\s*\w+\s*,\s*quick\s*=\s*(True|quick)""")
    missing = [name for name in validation.cases()
               if not any(re.search(rf"""["']{re.escape(name)}["']\s*,\s*quick\s*=\s*True""", t)
                          or (re.search(rf"""["']{re.escape(name)}["']""", t) and quick_call.search(t))
                          for t in texts)]
    assert not missing, f"validation cases with no quick run in tests/: {missing}"


def test_cases_have_descriptions_and_unique_names():
    cases = validation.cases()
    assert len(cases) >= 4
    for name, c in cases.items():
        assert c.name == name and c.description and callable(c.fn)
