"""The validation report: ``cosim validate ... --report DIR [--from FILE.jsonl]``.

From the records of :func:`cosim.validation.run` (the JSON lines ``cosim validate``
prints, and the curves of ``series`` saved beside them in ``DIR/series/``) it writes:

- ``index.md`` and ``index.html``: one table row per case (name, description, the target
  as stated, the measured values of what was judged, pass or fail, wall time, particles,
  steps), then the criteria that depart from their stated target, with both values;
- ``CASE.md`` and ``CASE.html`` per case: its set-up (the first paragraph of its
  docstring), the target as stated and what the record was judged against, the measured
  values, pass or fail, the departure from the stated target if any, the plots of ours
  against the reference (``CASE_*.png``, from ``series``), its measured trade (the tables
  of ``docs/validation/CASE_trade.md``, and for the cases of
  :mod:`cosim.validations.trade` the table and Pareto plot of ``cosim study`` on the case's
  scene, from ``docs/validation/trade/CASE/``) and its history
  (``docs/validation/CASE_history.md``, copied to ``history/`` and included);
- ``records.jsonl``: the records, from which ``--from`` builds the same report again.

The HTML is the same content through a small Markdown subset converter (:func:`md_to_html`):
headings, paragraphs, tables, lists, code, images and links; no web framework.
"""

from __future__ import annotations

import html
import inspect
import json
import math
import re
import shutil
import sys
from pathlib import Path

from cosim.validations.folders import DOCS, HISTORY_DIR

RECORDS = "records.jsonl"
SERIES = "series"


# ------------------------------------------------------------------------------- records
def _plain(o):
    """JSON-ready copy of ``o`` (numpy arrays and scalars to lists and numbers)."""
    if isinstance(o, dict):
        return {str(k): _plain(v) for k, v in o.items()}
    if isinstance(o, (list, tuple)):
        return [_plain(v) for v in o]
    if hasattr(o, "tolist"):
        return _plain(o.tolist())
    return o


def series_file(folder: Path | str, name: str, quick: bool) -> Path:
    return Path(folder) / f"{name}.{'quick' if quick else 'full'}.json"


def prepare(folder: Path | str) -> None:
    """Make the report folder and start an empty ``records.jsonl`` in it."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    (folder / RECORDS).write_text("")


def save_record(folder: Path | str, record: dict, line: str) -> None:
    """Append a record's JSON ``line`` to ``records.jsonl`` and save its ``series`` (if any)
    to ``series/NAME.quick.json`` (or ``.full.json``)."""
    folder = Path(folder)
    with open(folder / RECORDS, "a", encoding="utf-8") as f:
        f.write(line.rstrip("\n") + "\n")
    if record.get("series"):
        (folder / SERIES).mkdir(exist_ok=True)
        series_file(folder / SERIES, record["name"], record["quick"]).write_text(
            json.dumps(_plain(record["series"])), encoding="utf-8")


def read_records(path: Path | str) -> list[dict]:
    """The records of a JSON-lines file (lines that are not JSON objects are skipped);
    a later record of the same case and variant replaces an earlier one."""
    out: dict[tuple, dict] = {}
    for line in Path(path).read_text(encoding="utf-8").splitlines():
        line = line.strip()
        if not line.startswith("{"):
            continue
        rec = json.loads(line)
        out[(rec["name"], rec.get("quick"))] = rec
    return list(out.values())


# ------------------------------------------------------------------------------- formatting
def fmt(v) -> str:
    """A measured value, short."""
    if isinstance(v, bool) or v is None:
        return str(v).lower() if isinstance(v, bool) else "—"
    if isinstance(v, int):
        return f"{v:,}".replace(",", " ") if abs(v) >= 10000 else str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            return str(v)
        if v == 0:
            return "0"
        if abs(v) >= 1e6 or abs(v) < 1e-3:
            return f"{v:.3g}"
        s = f"{v:.{max(0, 3 - math.floor(math.log10(abs(v))))}f}"
        return s.rstrip("0").rstrip(".") if "." in s else s
    if isinstance(v, str):
        return v
    if isinstance(v, (list, tuple)):
        if v and isinstance(v[0], (list, tuple, dict)):
            return f"({len(v)} rows)"
        if len(v) > 6:
            return "[" + ", ".join(fmt(x) for x in v[:4]) + f", … ({len(v)} values)]"
        return "[" + ", ".join(fmt(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {fmt(x)}" for k, x in v.items()) + "}"
    return str(v)


def fmt_bound(b) -> str:
    """A tolerance, in words (see :func:`cosim.validation.within`)."""
    if isinstance(b, bool):
        return "true" if b else "false"
    if isinstance(b, str):
        return f"= {b}"
    if isinstance(b, (list, tuple)):
        lo, hi = b
        if lo is None:
            return f"≤ {fmt(hi)}"
        if hi is None:
            return f"≥ {fmt(lo)}"
        return f"{fmt(lo)} … {fmt(hi)}"
    return f"|x| ≤ {fmt(b)}"


def flatten(d: dict, prefix: str = "") -> dict:
    out = {}
    for k, v in d.items():
        key = f"{prefix}{k}"
        if isinstance(v, dict) and v:
            out.update(flatten(v, key + "."))
        else:
            out[key] = v
    return out


def cell(text) -> str:
    """Text for a Markdown table cell."""
    return str(text).replace("|", "\\|").replace("\n", " ")


def md_table(header: list, rows: list[list]) -> str:
    lines = ["| " + " | ".join(cell(h) for h in header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cell(c) for c in r) + " |" for r in rows]
    return "\n".join(lines)


def slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "plot"


# ------------------------------------------------------------------------------- docstrings
_ROLE = re.compile(r":(?:func|data|meth|class|mod|attr|obj):`~?([^`]+)`")


def rst_inline(text: str) -> str:
    """RST inline markup as Markdown: roles and ``literals`` to `code`."""
    text = _ROLE.sub(r"`\1`", text)
    return re.sub(r"``([^`]+)``", r"`\1`", text)


def paragraphs(doc: str) -> list[str]:
    """The blank-line separated blocks of a (dedented) docstring."""
    return [b for b in re.split(r"\n\s*\n", doc.strip()) if b.strip()]


_BORDER = re.compile(r"^\s*=+(\s+=+)*\s*$")


def is_rst_table(block: str) -> bool:
    return bool(_BORDER.match(block.splitlines()[0]))


def rst_table(block: str) -> tuple[list[str], list[list[str]]]:
    """(header, rows) of an RST simple table. A line whose first cell is empty, or whose
    other cells are all empty, continues the row above it (its text appended cell by
    cell)."""
    lines = block.splitlines()
    borders = [i for i, s in enumerate(lines) if _BORDER.match(s)]
    spans = [m.start() for m in re.finditer(r"=+", lines[borders[0]])]

    def cells(s):
        return [s[a:(spans[k + 1] if k + 1 < len(spans) else len(s))].strip() for k, a in enumerate(spans)]

    def rows(chunk):
        out = []
        for s in chunk:
            if not s.strip():
                continue
            c = cells(s)
            if out and (not c[0] or not any(c[1:])):
                out[-1] = [f"{a} {b}".strip() for a, b in zip(out[-1], c)]
            else:
                out.append(c)
        return out

    if len(borders) >= 3:
        head = rows(lines[borders[0] + 1:borders[1]])
        header = [" ".join(r[k] for r in head).strip() for k in range(len(spans))]
        body = rows(lines[borders[1] + 1:borders[2]])
    else:
        header, body = [""] * len(spans), rows(lines[borders[0] + 1:borders[-1]])
    return header, body


def rst_to_md(block: str) -> str:
    """One docstring block as Markdown: a table, a bullet list, or a paragraph."""
    if is_rst_table(block):
        return md_table(*rst_table(block))
    lines = block.splitlines()
    if lines[0].lstrip().startswith(("* ", "- ")):
        items, cur = [], []
        for s in lines:
            if s.lstrip().startswith(("* ", "- ")) and (not cur or s[:len(s) - len(s.lstrip())] == ""):
                if cur:
                    items.append(" ".join(cur))
                cur = [s.lstrip()[2:].strip()]
            else:
                cur.append(s.strip())
        items.append(" ".join(cur))
        return "\n".join(f"- {rst_inline(i)}" for i in items)
    return rst_inline(" ".join(s.strip() for s in lines))


def case_setup(fn) -> str:
    """The set-up of a case: the first paragraph of its docstring, preceded by the first
    paragraph of a function it refers to with "see :func:`X`" (a ``run_`` helper)."""
    doc = inspect.getdoc(fn) or ""
    paras = paragraphs(doc)
    if not paras:
        return "(no docstring)"
    first = paras[0]
    out = []
    mod = sys.modules.get(fn.__module__)
    for ref in re.findall(r"[Ss]ee :func:`~?(\w+)`", first):
        other = getattr(mod, ref, None)
        if other is not None and inspect.getdoc(other):
            out.append(rst_to_md(paragraphs(inspect.getdoc(other))[0]))
    out.append(rst_to_md(first))
    return "\n\n".join(out)


def trade_file(name: str) -> Path:
    return HISTORY_DIR / f"{name}_trade.md"


def case_trade(name: str) -> str | None:
    """The measured trade of case ``name``: ``docs/validation/NAME_trade.md`` (tables of
    error against cost, measured by hand or by a benchmark), without its title; None if the
    case has none (or docs/ is not here)."""
    path = trade_file(name)
    if not path.exists():
        return None
    text = path.read_text(encoding="utf-8")
    return re.sub(r"\A# [^\n]*\n+", "", text).strip() or None


def history_file(name: str) -> Path:
    return HISTORY_DIR / f"{name}_history.md"


def stated_rows() -> list[str]:
    """The case names of the tables of docs/VALIDATION.md (empty if it is not here)."""
    path = DOCS / "VALIDATION.md"
    if not path.exists():
        return []
    return [n for n in re.findall(r"^\| ([a-z0-9][a-z0-9-]*) \|", path.read_text(encoding="utf-8"), re.M)
            if n != "name"]


# ------------------------------------------------------------------------------- plots
def plot_series(series: dict, folder: Path, name: str) -> list[tuple[str, str]]:
    """One PNG per plot of ``series`` ({title: {xlabel, ylabel, curves: {label: {x, y,
    style}}, invert_y}}): [(title, file name)]."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = []
    for title, p in series.items():
        fig, ax = plt.subplots(figsize=(7.0, 4.2))
        for label, c in p.get("curves", {}).items():
            x, y = c.get("x") or [], c.get("y") or []
            if not len(x):
                continue
            style = c.get("style", "-")
            if style in ("o", "s", "^", "x", "."):
                ax.plot(x, y, style, ms=2 if style == "." else 4, label=label, mfc="none" if style != "." else None)
            else:
                ax.plot(x, y, style, lw=1.2, ms=3, label=label)
        ax.set_xlabel(p.get("xlabel", ""))
        ax.set_ylabel(p.get("ylabel", ""))
        if p.get("invert_y"):
            ax.invert_yaxis()
        ax.set_title(f"{name}: {title}", fontsize=10)
        ax.grid(alpha=0.3)
        if ax.lines:
            ax.legend(fontsize=7)
        fig.tight_layout()
        file = f"{name}_{slug(title)}.png"
        fig.savefig(folder / file, dpi=100, metadata={"Software": None})
        plt.close(fig)
        out.append((title, file))
    return out


# ------------------------------------------------------------------------------- pages
def _count(v) -> str:
    return fmt(v) if v else "—"


def _wall(v) -> str:
    return "—" if v is None else f"{v:.2f}" if v < 10 else f"{v:.0f}"


def _result(rec) -> str:
    return "pass" if rec["passed"] else "**FAIL**"


def _variant(rec) -> str:
    return "quick" if rec.get("quick") else "full"


def judged_values(rec) -> str:
    """The measured values of what was judged, for the index."""
    from cosim.validation import lookup, within

    parts = []
    for key, bound in rec.get("tolerances", {}).items():
        try:
            v = lookup(rec.get("metrics", {}), key)
        except KeyError:
            parts.append(f"{key}: missing ✗")
            continue
        parts.append(f"{key} = {fmt(v)}" + ("" if within(v, bound) else " ✗"))
    return "; ".join(parts) or "—"


def tolerance_table(metrics: dict, tolerances: dict) -> str:
    from cosim.validation import lookup, within

    rows = []
    for key, bound in tolerances.items():
        try:
            v = lookup(metrics, key)
            ok = "yes" if within(v, bound) else "**no**"
        except KeyError:
            v, ok = None, "**missing**"
        rows.append([f"`{key}`", fmt_bound(bound), fmt(v), ok])
    return md_table(["metric", "tolerance", "measured", "within"], rows)


def case_page(rec: dict, case, plots: list[tuple[str, str]], history: str | None) -> str:
    name = rec["name"]
    out = [f"# {name}", "", "[← index](index.md)", ""]
    if case is not None:
        out += [f"*{case.description}*", ""]
    out += [f"**Result: {_result(rec)}** ({_variant(rec)} variant). Wall time {_wall(rec.get('wall_s'))} s, "
            f"{_count(rec.get('particles'))} particles, {_count(rec.get('steps'))} steps.", ""]
    out += ["## Set-up", "", case_setup(case.fn) if case is not None else "(case not registered)", ""]
    row = case.row if case is not None else None
    where = (f"docs/VALIDATION.md, row `{row}`" if row else "declared: no row in docs/VALIDATION.md")
    out += ["## Target", "", f"**As stated** ({where}): {rec.get('stated_target') or '—'}", "",
            f"**Judged against**: {rec.get('target', '—')}", "",
            "`passed` means every metric below is within its tolerance.", "",
            tolerance_table(rec.get("metrics", {}), rec.get("tolerances", {})), ""]
    stated = rec.get("stated")
    dep = rec.get("departure")
    if dep:
        out += ["## Departure from the stated target", "", f"**Stated**: {stated['target']}", ""]
    elif stated:
        out += ["## The stated target on this run", "", f"**Stated**: {stated['target']}", ""]
    if stated:
        met = {True: "yes", False: "**no**", None: "not measured"}[stated.get("met")]
        if stated.get("tolerances"):
            rows = [[f"`{k}`", fmt_bound(b), fmt(stated.get("measured", {}).get(k)),
                     "—" if stated.get("measured", {}).get(k) is None else
                     ("yes" if _within(stated["measured"][k], b) else "**no**")]
                    for k, b in stated["tolerances"].items()]
            out += [md_table(["metric", "stated tolerance", "measured", "within"], rows), ""]
        out += [f"Stated target met: {met}" + (f" ({stated['source']})" if stated.get("source") else "") + ".", ""]
    if dep:
        out += [f"**Criterion used**: {dep['criterion']}", "", f"**Why**: {dep['why']}", ""]
    out += ["## Measured values", ""]
    flat = flatten(rec.get("metrics", {}))
    out += [md_table(["metric", "value"], [[f"`{k}`", fmt(v)] for k, v in flat.items()]) if flat else "—", ""]
    out += ["## Ours against the reference", ""]
    if plots:
        for title, file in plots:
            out += [f"![{title}]({file})", ""]
    else:
        out += ["(no plot: the case returns no series, or they were not saved with these records)", ""]
    trade = case_trade(name)
    if trade:
        out += ["## Measured trade", "", trade, ""]
    study = study_section(name)
    if study:
        out += [study, ""]
    if history is not None:
        out += ["## History", "", f"What was tried, session by session: [{name}_history.md](history/{name}_history.md) "
                "(docs/validation/), included here.", "", _demote(history), ""]
    return "\n".join(out).rstrip() + "\n"


def has_study(name: str) -> bool:
    """Whether case ``name`` has a committed ``cosim study`` (:mod:`cosim.validations.trade`)."""
    from cosim.validations.trade import STUDIES, study_dir

    return name in STUDIES and (study_dir(name) / "study.md").exists()


def study_section(name: str) -> str | None:
    """The case's trade measured by ``cosim study`` (:mod:`cosim.validations.trade`), from
    its committed study folder: the command, what it measures, the table, the Pareto plot
    (``trade/NAME_pareto.png`` beside the page, copied by :func:`write_report`)."""
    from cosim.validations.trade import STUDIES, study_dir

    if not has_study(name):
        return None
    s = STUDIES[name]
    table = (study_dir(name) / "study.md").read_text(encoding="utf-8").split("\n", 1)[1].strip()
    out = ["## Trade measured by `cosim study`", "",
           f"What it compares: {s.quantity}. Reference values and their source: "
           f"`{s.reference.relative_to(s.reference.parents[3])}`. Re-measure with:", "",
           "```", s.command(), "```", "", table, ""]
    if (study_dir(name) / "pareto.png").exists():
        out += [f"![error against cost, the Pareto front marked](trade/{name}_pareto.png)", ""]
    return "\n".join(out).rstrip()


def _within(v, b) -> bool:
    from cosim.validation import within

    return within(v, b)


def _demote(md: str, by: int = 2) -> str:
    out, fence = [], False
    for s in md.splitlines():
        if s.startswith("```"):
            fence = not fence
        if not fence and re.match(r"#{1,6} ", s):
            s = "#" * by + s
        out.append(s)
    return "\n".join(out)


def index_page(records: list[dict], known: dict) -> str:
    kinds = {_variant(r) for r in records}
    what = "quick variants" if kinds == {"quick"} else "full variants" if kinds == {"full"} else "quick and full variants"
    n_pass = sum(r["passed"] for r in records)
    out = [f"# Validation report ({what})", "",
           f"{len(records)} case(s): {n_pass} passed, {len(records) - n_pass} failed.", "",
           "A case passes when every metric named in its tolerances is within it. A quick variant is judged "
           "against its own declared tolerances, a full one against the stated target of docs/VALIDATION.md "
           "(or a criterion that departs from it, listed below with both values); each case's page says which. "
           "Measured: the judged metrics (✗: outside its tolerance).", ""]
    rows = []
    for r in records:
        c = known.get(r["name"])
        rows.append([f"[{r['name']}]({r['name']}.md)" + (f" ({_variant(r)})" if len(kinds) > 1 else ""),
                     c.description if c else "", r.get("stated_target") or "—", judged_values(r), _result(r),
                     _wall(r.get("wall_s")), _count(r.get("particles")), _count(r.get("steps"))])
    out += [md_table(["case", "description", "target as stated", "measured", "result", "wall [s]", "particles",
                      "steps"], rows), ""]
    deps = [r for r in records if r.get("departure")]
    if deps:
        out += ["## Criteria that depart from the stated target", ""]
        rows = []
        for r in deps:
            st = r["stated"]
            meas = "; ".join(f"{k} = {fmt(v)}" for k, v in st.get("measured", {}).items()) or "—"
            if st.get("source"):
                meas += f" ({st['source']})"
            met = {True: "yes", False: "no", None: "not measured"}[st.get("met")]
            rows.append([f"[{r['name']}]({r['name']}.md)", st["target"], meas, met, r["departure"]["criterion"],
                         _result(r)])
        out += [md_table(["case", "stated target", "measured against it", "met", "criterion used", "result"], rows),
                ""]
    missing = [n for n in dict.fromkeys(stated_rows()) if n not in known and not any(
        c.row == n for c in known.values())]
    if missing:
        out += ["## Rows of docs/VALIDATION.md without a case", "", ", ".join(f"`{n}`" for n in missing), ""]
    return "\n".join(out).rstrip() + "\n"


def write_report(folder: Path | str, records: list[dict], series_from: Path | str | None = None,
                 source: Path | str | None = None) -> Path:
    """Write the report of ``records`` into ``folder``; the series are read from
    ``series_from`` (default ``folder/series``). Returns the index.md path."""
    from cosim.validation import cases
    from cosim.validations.trade import study_dir

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    series_dir = Path(series_from) if series_from is not None else folder / SERIES
    known = cases()
    records = sorted(records, key=lambda r: (r["name"], bool(r.get("quick"))))
    own = folder / RECORDS
    if source is None or Path(source).resolve() != own.resolve():
        own.write_text("".join(json.dumps(r) + "\n" for r in records), encoding="utf-8")
    pages = {}
    for rec in records:
        name = rec["name"]
        sfile = series_file(series_dir, name, bool(rec.get("quick")))
        plots = []
        if sfile.exists():
            series = json.loads(sfile.read_text(encoding="utf-8"))
            if series_dir.resolve() != (folder / SERIES).resolve():
                (folder / SERIES).mkdir(exist_ok=True)
                shutil.copyfile(sfile, series_file(folder / SERIES, name, bool(rec.get("quick"))))
            plots = plot_series(series, folder, name)
        history = None
        if history_file(name).exists():
            history = history_file(name).read_text(encoding="utf-8")
            (folder / "history").mkdir(exist_ok=True)
            (folder / "history" / f"{name}_history.md").write_text(history, encoding="utf-8")
            (folder / "history" / f"{name}_history.html").write_text(
                html_page(f"{name}: history", md_to_html(history)), encoding="utf-8")
        pages[name] = case_page(rec, known.get(name), plots, history)
        pareto = study_dir(name) / "pareto.png"
        if has_study(name) and pareto.exists():
            (folder / "trade").mkdir(exist_ok=True)
            shutil.copyfile(pareto, folder / "trade" / f"{name}_pareto.png")
    for name, md in pages.items():
        (folder / f"{name}.md").write_text(md, encoding="utf-8")
        (folder / f"{name}.html").write_text(html_page(name, md_to_html(md)), encoding="utf-8")
    index = index_page(records, known)
    (folder / "index.md").write_text(index, encoding="utf-8")
    (folder / "index.html").write_text(html_page("Validation report", md_to_html(index)), encoding="utf-8")
    return folder / "index.md"


# ------------------------------------------------------------------------------- HTML
_CSS = ("body{font-family:sans-serif;max-width:75em;margin:1em auto;padding:0 1em;line-height:1.4}"
        "table{border-collapse:collapse;margin:0.5em 0;font-size:0.9em}td,th{border:1px solid #bbb;"
        "padding:0.2em 0.4em;vertical-align:top;text-align:left}th{background:#eee}code{background:#f4f4f4}"
        "pre{background:#f4f4f4;padding:0.5em;overflow:auto}img{max-width:100%}")


def html_page(title: str, body: str) -> str:
    return (f"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{html.escape(title)}</title>"
            f"<style>{_CSS}</style></head><body>\n{body}</body></html>\n")


def _link(target: str) -> str:
    return re.sub(r"\.md(#|$)", r".html\1", target) if not re.match(r"\w+://", target) else target


def inline_html(text: str) -> str:
    """Inline Markdown (code, images, links, bold, italic) as HTML."""
    parts = re.split(r"(`[^`]+`)", text)
    out = []
    for p in parts:
        if p.startswith("`") and p.endswith("`") and len(p) > 1:
            out.append(f"<code>{html.escape(p[1:-1])}</code>")
            continue
        p = html.escape(p, quote=False)
        p = re.sub(r"!\[([^\]]*)\]\(([^)]+)\)", lambda m: f'<img alt="{m[1]}" src="{m[2]}">', p)
        p = re.sub(r"\[([^\]]+)\]\(([^)]+)\)", lambda m: f'<a href="{_link(m[2])}">{m[1]}</a>', p)
        p = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", p)
        p = re.sub(r"(?<![\w*])\*(?!\s)(.+?)(?<!\s)\*(?![\w*])", r"<em>\1</em>", p)
        out.append(p)
    return "".join(out)


def _table_cells(line: str) -> list[str]:
    s = line.strip()
    s = s[1:] if s.startswith("|") else s
    s = s[:-1] if s.endswith("|") and not s.endswith("\\|") else s
    return [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", s)]


def md_to_html(md: str) -> str:
    """The Markdown subset of these reports as HTML: ATX headings, tables, bullet lists,
    fenced code, paragraphs and inline markup."""
    lines = md.splitlines()
    out, i = [], 0
    while i < len(lines):
        s = lines[i]
        if not s.strip():
            i += 1
        elif s.startswith("```"):
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            out.append("<pre>" + html.escape("\n".join(lines[i + 1:j])) + "</pre>")
            i = j + 1
        elif m := re.match(r"(#{1,6}) (.*)", s):
            n = len(m[1])
            out.append(f"<h{n}>{inline_html(m[2])}</h{n}>")
            i += 1
        elif s.lstrip().startswith("|"):
            j = i
            while j < len(lines) and lines[j].lstrip().startswith("|"):
                j += 1
            rows = [_table_cells(r) for r in lines[i:j]]
            head, body = rows[0], [r for r in rows[1:] if not all(re.fullmatch(r":?-+:?", c or "-") for c in r)]
            t = ["<table><tr>" + "".join(f"<th>{inline_html(c)}</th>" for c in head) + "</tr>"]
            t += ["<tr>" + "".join(f"<td>{inline_html(c)}</td>" for c in r) + "</tr>" for r in body]
            out.append("\n".join(t) + "</table>")
            i = j
        elif re.match(r"\s*[-*] ", s):
            items = []
            while i < len(lines) and lines[i].strip():
                if re.match(r"\s*[-*] ", lines[i]):
                    items.append(re.sub(r"^\s*[-*] ", "", lines[i]))
                else:
                    items[-1] += " " + lines[i].strip()
                i += 1
            out.append("<ul>" + "".join(f"<li>{inline_html(t)}</li>" for t in items) + "</ul>")
        else:
            j = i
            while (j < len(lines) and lines[j].strip() and not lines[j].startswith(("#", "```", "|"))
                   and not (j > i and re.match(r"\s*[-*] ", lines[j]))):
                j += 1
            out.append("<p>" + inline_html(" ".join(x.strip() for x in lines[i:j])) + "</p>")
            i = j
    return "\n".join(out) + "\n"
