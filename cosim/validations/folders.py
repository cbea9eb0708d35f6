"""Where the validation cases' committed material lives, for the report and the studies.

A leaf: it imports nothing of the project, so that the report (:mod:`cosim.report`), the
studies (:mod:`cosim.validations.trade`) and the CLI can all read these folders without
importing one another (imports run one way: CLI, then report, then the cases' data).

- ``SCENES``: the cases' scene files (``CASE.toml``) and references (``CASE.reference.json``),
  shipped beside this module;
- ``DOCS``: ``docs/`` of the source tree (absent in an installed copy);
- ``HISTORY_DIR``: ``docs/validation/``, each case's history (``CASE_history.md``) and its
  measured trade (``CASE_trade.md``), which the report shows on the case's page;
- ``TRADE_DIR``: ``docs/validation/trade/CASE/``, the committed ``cosim study`` of a case.
"""

from pathlib import Path

SCENES = Path(__file__).resolve().with_name("scenes")
DOCS = Path(__file__).resolve().parents[2] / "docs"
HISTORY_DIR = DOCS / "validation"
TRADE_DIR = HISTORY_DIR / "trade"
