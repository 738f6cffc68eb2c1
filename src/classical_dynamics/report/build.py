"""Render results/ into one self-contained HTML file through the Jinja templates in report/.

The report reads results files only (summary.json, provenance.json, CSV, SVG), never study code.
Every number shown goes through `num` (one formatting rule) and carries its provenance.
"""

from __future__ import annotations

import base64
import html
import json
import math
import re
import shutil
from collections import defaultdict
from pathlib import Path

import jinja2
import pandas as pd
from jinja2.ext import Extension
from markupsafe import Markup

from .. import io, scene_results
from ..formatting import (
    exact_figures,
    format_column,
    format_decimals,
    format_number,
    measured_and_bound,
    shortest,
)
from ..inline_math import plain_text, render_markup, render_text
from ..provenance import git_state, machine, package_versions, sha256_file
from ..studies import STUDIES
from ..units import UnknownUnit, unit_text
from . import assets
from . import claims as claims_mod
from .bib import Citations, format_entry, read_bib
from .citation import citation, commit_date
from .dist import results_archive_name
from .ledger import read_ledger, require_figures
from .math import PHONE_EM, keep_in, latex_image, stacked, width_em
from .navigation import add_navigation
from .numbering import NAMES, Numbering


def _split_columns(frame, columns, split):
    """One column per value of `by` for each column in split (see table): "setting" with kind "tolerance"
    and "step" becomes "setting:tolerance" and "setting:step", empty where the row is of the other kind."""
    columns = list(columns or frame.columns)
    for column, by in split.items():
        parts = [f"{column}:{v}" for v in dict.fromkeys(frame[by])]
        for part in parts:
            value = part.split(":", 1)[1]
            frame = frame.assign(**{part: frame[column].where(frame[by] == value)})
        at = columns.index(column)
        columns[at : at + 1] = parts
        frame = frame.drop(columns=[column, by])
        columns = [c for c in columns if c != by]
    return frame, columns


class ResultsIndex:
    """Everything under results/: summaries, provenance, timing tables."""

    def __init__(self, results_dir: Path):
        self.dir = Path(results_dir)
        # whole results only (io.ResultError otherwise), read as any user reads them (scene_results)
        self.results = scene_results.load_folder(self.dir, STUDIES)
        self.summaries = {key: r.summary for key, r in self.results.items()}
        self.provenance = {key: r.provenance for key, r in self.results.items()}

    def studies(self):
        present = {study for study, _ in self.summaries}
        return [s for s in STUDIES if s in present]  # in the registry's order

    def scenes(self, study):
        """A study's scenes. A step drawn from other scenes' results (its provenance lists them as
        input_scenes, as the self-excited gallery's does) is no scene: its figures are shown, its provenance
        listed, but not counted."""
        return sorted(
            scene
            for s, scene in self.summaries
            if s == study and "input_scenes" not in self.provenance[(s, scene)]
        )

    def summary(self, study, scene):
        try:
            return self.summaries[(study, scene)]
        except KeyError:
            raise KeyError(f"no results for {study}/{scene} (is workflow/scenes/{study}/{scene}.yaml there?)")

    def entry(self, study, scene, number):
        numbers = self.summary(study, scene)["numbers"]
        if number not in numbers:
            raise KeyError(f"{study}/{scene} has no number {number!r}")
        return numbers[number]

    def csv(self, study, scene, name, timing=False):
        return self.results[(study, scene)].table(name, timing)

    def svg_uri(self, study, scene, name, timing=False):
        folder = self.dir / study / ("timings/" + scene if timing else scene)
        return svg_data_uri((folder / f"{name}.svg").read_bytes())


def svg_data_uri(svg: bytes) -> str:
    """An SVG file as a data: URI: the report carries its figures inside it."""
    return "data:image/svg+xml;base64," + base64.b64encode(svg).decode("ascii")


def figure_html(
    label: str,
    number,
    uri: str,
    alt: str,
    caption: str,
    source: str,
    rebuild: str,
    full: str,
    kind: str = "figure",
) -> Markup:
    """A numbered figure: the image (a tap or click opens its SVG at full size, where a phone shrinks it), its
    caption, then where it comes from and how to make it again."""
    return Markup(
        f'<figure id="{label}" class="{kind}">'
        f'<a class="full-size" href="{full}" title="the figure at full size">'
        f'<img src="{uri}" alt="{alt}"></a>'
        f'<figcaption><span class="label">Figure {number}.</span> {caption} '
        f'<span class="source">{source}<span class="rebuild">; {rebuild}</span>.'
        f"</span>"
        f"</figcaption></figure>"
    )


def unit_html(key, value=None) -> Markup:
    """A unit from the registry, typeset, with its leading (thin) space: "&#8239;d", "″/yr"."""
    return Markup(render_text(unit_text(key, value)))


class InlineMath(Extension):
    """$...$ in a template's text becomes typeset HTML once, when the template is compiled."""

    def preprocess(self, source, name, filename=None):
        return render_markup(source)


_UNIT = re.compile(r" (\([^()]*\))$")
_IDENTIFIER = re.compile(r"^(\+ )?[a-z][a-z0-9]*(_[a-z0-9]+)+$")


def _header_html(text: str) -> str:
    """A header as HTML: $math$ typeset (one typed in a template was typeset when it was compiled),
    its "(unit)" kept on one line."""
    html_text = text if "<span class=math" in text else render_text(text)
    return _UNIT.sub(r' <span class="unit">\1</span>', html_text)


def _cell_html(text: str) -> str:
    """A text cell: an identifier such as node_regression reads as words."""
    return render_text(text.replace("_", " ") if _IDENTIFIER.match(text) else text)


_CODE = re.compile(r"<code>(.*?)</code>", re.S)


def break_points(page: str) -> str:
    """Identifiers and commands may break only after '/', '_' or '-' (a <wbr> there), never mid-word."""
    return _CODE.sub(
        lambda m: "<code>" + re.sub(r"(?<=[/_-])(?=[^<>\s])", "<wbr>", m.group(1)) + "</code>", page
    )


# A table the chapter marks long stands in the appendix of long tables only past this many rows
LONG_TABLE_ROWS = 12


class Report:
    def __init__(self, index: ResultsIndex, root: Path, quick: bool, cache: Path | None = None):
        self.index, self.root, self.quick = index, Path(root), quick
        self.numbering = Numbering()
        self.citations = Citations(read_bib(assets.BIBLIOGRAPHY))
        self.claim_results = {}
        self.ledger = read_ledger(assets.LEDGER, {study: assets.claims_file(study) for study in STUDIES})
        self._count, self.cited = 0, {}  # numbers shown so far; per scene, where each is first cited
        self.long_tables = {}  # {study: [table markup]}: shown in the appendix of long tables
        self.env = jinja2.Environment(
            loader=jinja2.FileSystemLoader(assets.template_folders()),
            autoescape=jinja2.select_autoescape(["html", "j2"]),
            undefined=jinja2.StrictUndefined,
            trim_blocks=True,
            lstrip_blocks=True,
            extensions=[InlineMath],
            # compiled templates kept between runs (Jinja checks each against its source): a third of a second
            bytecode_cache=None if cache is None else _bytecode_cache(Path(cache)),
        )
        keep_in(cache)
        self.env.filters["fmt"] = lambda v, sig=4: format_number(v, sig)
        # a column of deviations in one notation, relative or absolute: 2.4 × 10⁻³ beside 3.0 × 10⁻⁴ and
        # 1.7 d, 22 mas or −0.19 d, never 0.0024 beside them
        self.env.filters["fmt_power"] = lambda v, sig=2: format_number(v, sig, fixed_range=(-1, 3))
        # "ours" that is not a result of our model: a source's value set beside today's (an input or a
        # reference's value) stands in the modern column; a fit to observed data stays ours
        self.env.globals["BESIDE"] = ("input", "reference")
        self.env.filters["math"] = lambda text: Markup(render_text(str(text)))
        # a check's bound as printed, but below 10⁻² as a power of ten (≤ 1 × 10⁻³ beside ≤ 1 × 10⁻¹³)
        self.env.filters["bound"] = lambda v: (
            format_number(v, exact_figures(float(v)), fixed_range=(-2, 5))
            if isinstance(v, float) and 0 < abs(v) < 1e-2
            else shortest(v)
        )
        self.env.globals.update(
            num=self.num,
            value=self.value,
            shortest=shortest,
            column=format_column,
            measured_and_bound=measured_and_bound,
            claim_digits=claims_mod.shown_digits,
            source_means=claims_mod.source_means,
            evaluated_text=claims_mod.evaluated_text,
            prints_a_bare_number=claims_mod.prints_a_bare_number,
            unit=unit_html,
            label_number=self.numbering.label,
            fig=self.fig,
            table=self.table,
            long_table=self.long_table,
            eq=self.eq,
            ref=self.ref,
            cite=self.cite,
            benchmark_fig=self.benchmark_fig,
            claims=self.claims,
            count_by_kind=claims_mod.count_by_kind,
            by_kind=claims_mod.by_kind,
            count_briefly=claims_mod.count_briefly,
            shown_not_met=claims_mod.shown_not_met,
            shown_kinds=claims_mod.SHOWN_NOT_MET,
            independent_checks=claims_mod.independent_checks,
            effect_names=lambda study: STUDIES[study].effect_names(),
            long_tables=lambda study: Markup("".join(self.long_tables.get(study, []))),
            stability=self.stability,
            scenes=self.scenes_table,
            effects=self.effects_table,
            summary=self.index.summary,
            rebuild=self.rebuild,
            study_scenes=self.index.scenes,
            all_claims=self.all_claims,
            claim=self.claim,
            provenance_json=self.provenance_json,
            ledger=self.ledger,
            cited=lambda study, scene: self.cited.get((study, scene), {}),
            study_title=lambda study: STUDIES[study].title,
            every_study=list(STUDIES),
            chapter_template=assets.chapter_template,
            ledger_folder=assets.LEDGER_SHOWN,
        )

    # --- numbers ---------------------------------------------------------------------------
    def _number_link(self, study, scene, name, value, text, unit_key=None):
        """A number as a link that opens its provenance (click, tap or keyboard; see report.js); without
        script it leads to its scene's row of the provenance appendix. Its full-precision value and key
        travel with it, the scene's commit and hash in the page's provenance table (provenance_json)."""
        self._count += 1
        anchor = f"n{self._count}"
        self.cited.setdefault((study, scene), {}).setdefault(name, anchor)
        try:  # a number shown bare (unit=False) may carry a unit the registry lacks
            unit = plain_text(unit_text(unit_key, value)).strip() if unit_key else ""
        except UnknownUnit:
            unit = str(unit_key)
        full = repr(value) if isinstance(value, float) else str(value)
        return (
            f'<a class="num" id="{anchor}" href="#prov-{study}-{scene}" role="button" '
            f'aria-haspopup="dialog" data-scene="{study}/{scene}" data-key="{html.escape(name, quote=True)}" '
            f'data-value="{html.escape(full, quote=True)}" data-unit="{html.escape(unit, quote=True)}">'
            f"{text}</a>"
        )

    def num(self, where: str, name: str, i=None, sig: int = 4, unit: bool = True, scale: float = 1.0):
        """A computed number with its unit, linked to its provenance. where = 'study/scene'."""
        study, scene = where.split("/")
        entry = self.index.entry(study, scene, name)
        value = entry["value"]
        if i is not None:
            value = value[i]
        if scale != 1.0 and value is not None:
            value = value * scale
        out = self._number_link(
            study,
            scene,
            name if i is None else f"{name}[{i}]",
            value,
            format_number(value, sig),
            entry.get("unit"),
        )
        if unit:
            out += str(unit_html(entry.get("unit"), value))
        return Markup(out)

    def value(self, where: str, name: str, value, sig: int = 4):
        """A value derived from a results number (an element, a maximum), linked to its provenance."""
        study, scene = where.split("/")
        return Markup(self._number_link(study, scene, name, value, format_number(value, sig)))

    def provenance_json(self) -> Markup:
        """Per scene: what the provenance panel of each of its numbers shows."""
        data = {}
        for (study, scene), prov in sorted(self.index.provenance.items()):
            data[f"{study}/{scene}"] = {
                "commit": prov.get("commit", "unknown"),
                "dirty": bool(prov.get("dirty")),
                "input": prov.get("scene_sha256", ""),
                "file": f"results/{study}/{scene}/summary.json",
                "scene": self._scene_file(study, scene),
                "link": self._scene_link(study, scene),
                "command": self.rebuild(study, scene),
                "finished": prov.get("finished", ""),
            }
        # </ cannot end the script early: json escapes no slash, so escape it here.
        return Markup(json.dumps(data, sort_keys=True, ensure_ascii=False).replace("</", "<\\/"))

    # --- numbered things -------------------------------------------------------------------
    def ref(self, label: str) -> Markup:
        """Figure 3, Table 2, Eq. (12): the report's own numbers; a source's are cited as Lee (3.19)."""
        kind = label.split(":", 1)[0]
        number = self.numbering.ref(label)
        text = f"Eq.&nbsp;({number})" if kind == "eq" else f"{NAMES[kind]}&nbsp;{number}"
        return Markup(f'<a class="xref" href="#{html.escape(label)}">{text}</a>')

    def rebuild(self, study, scene=None):
        return f"snakemake -c all results/{study}/{scene}" if scene else f"snakemake -c all {study}"

    def fig(self, where: str, name: str, label: str, timing: bool = False, extra: str = ""):
        study, scene = where.split("/")
        summary = self.index.summary(study, scene)
        meta = (summary["timings"]["figures"] if timing else summary["figures"])[name]
        number = self.numbering.label(label)
        uri = self.index.svg_uri(study, scene, name, timing)
        caption = render_text(meta["caption"])
        if extra:
            caption += " " + str(extra)
        note = " Measured times: they vary from run to run." if timing else ""
        alt = html.escape(plain_text(meta["caption"]), quote=True)
        folder = f"{study}/{'timings/' if timing else ''}{scene}"  # relative to report.html in results/
        data = meta.get("data")
        links = (
            f'<a href="{folder}/{meta["file"]}">SVG</a>'
            + (f' · <a href="{folder}/{data}">data (CSV)</a>' if data else "")
            + f' · scene <a href="{self._scene_link(study, scene)}"><code>{study}/{scene}</code></a>'
        )
        return figure_html(
            label,
            number,
            uri,
            alt,
            caption + note,
            links,
            f"rebuild: <code>{self.rebuild(study, scene)}</code>",
            f"{folder}/{meta['file']}",
        )

    def benchmark_fig(self, name: str, label: str, caption: str):
        """A figure a benchmark measured and saved beside its data in benchmarks/results/ (not a build result:
        its caption says where and when it was measured)."""
        folder = "measured"  # results/measured/: the workflow copies data and script beside the results
        uri = svg_data_uri((self.root / "benchmarks" / "results" / f"{name}.svg").read_bytes())
        links = (
            f'<a href="{folder}/{name}.svg">SVG</a> · <a href="{folder}/{name}.json">data (JSON)</a>'
            f' · measured by <a href="{folder}/{name}.py"><code>benchmarks/{name}.py</code></a>'
        )
        return figure_html(
            label,
            self.numbering.label(label),
            uri,
            html.escape(plain_text(caption), quote=True),
            render_text(caption) + " Measured times.",
            links,
            f"remeasure: <code>python benchmarks/{name}.py</code>",
            f"{folder}/{name}.svg",
            kind="figure benchmark",
        )

    def _scene_link(self, study, scene) -> str:
        """Where the report links a results folder's input, inside results/: the copy of its scene file that
        travels with it, or for a step drawn from other scenes (the gallery) its provenance."""
        listed = self.index.provenance[(study, scene)].get("files", {})
        return f"{study}/{scene}/{'scene.yaml' if 'scene.yaml' in listed else 'provenance.json'}"

    def _scene_file(self, study, scene) -> str:
        """The input a results folder was computed from, relative to the checkout: its scene file, or for a
        step drawn from other scenes (the gallery) the code that draws it."""
        return self.index.provenance[(study, scene)].get(
            "scene_file", f"workflow/scenes/{study}/{scene}.yaml"
        )

    def table(
        self,
        where: str,
        name: str,
        label: str,
        columns=None,
        timing: bool = False,
        sig: int = 4,
        rename=None,
        keep=None,
        sigs=None,
        long: bool = False,
        together=(),
        decimals=None,
        split=None,
        powers=(),
    ):
        """A results table: headers as the study declared them ("quantity (unit)", with math), numbers
        right-aligned to `sig` figures (per column in `sigs`), columns of whole numbers printed as such;
        the columns of each group in `together` (ours beside a reference's) share one notation.
        keep = {column: [values]} shows the rows whose values are listed (by value, not position, so a
        reduced build that has fewer rows shows fewer). decimals = {column: n} prints that column as plain
        decimals to n places (a quantity known to an absolute resolution: a change below it reads 0).
        split = {column: by} shows a column that holds different quantities by row (a tolerance in one, a step
        in days in the next, told apart by the column `by`) as one column per value of `by`, "—" elsewhere,
        headed by rename["column:value"]; `by` itself is then not shown. powers = columns always written as
        mantissa × 10ⁿ to `sigs` figures (a predicted count of 2.5 × 10⁸, not 250 000 000)."""
        study, scene = where.split("/")
        summary = self.index.summary(study, scene)
        meta = (summary["timings"]["tables"] if timing else summary["tables"])[name]
        frame = self.index.csv(study, scene, name, timing)
        for column, allowed in (keep or {}).items():
            if pd.api.types.is_numeric_dtype(frame[column]):
                mask = frame[column].map(lambda v: any(math.isclose(v, a, rel_tol=1e-9) for a in allowed))
            else:
                mask = frame[column].isin(allowed)
            frame = frame[mask]
        headers = {**meta.get("headers", {}), **(rename or {})}
        frame, columns = _split_columns(frame, columns, split or {})
        left_out = [c for c in frame.columns if columns and c not in columns]
        if columns:
            frame = frame[columns]
        number = self.numbering.label(label)
        head, numeric = [], {}
        for c in frame.columns:
            numeric[c] = pd.api.types.is_numeric_dtype(frame[c]) and not pd.api.types.is_bool_dtype(frame[c])
            cls = ' class="n"' if numeric[c] else ""
            head.append(f"<th{cls}>{_header_html(headers.get(c, c.replace('_', ' ')))}</th>")
        whole = {
            c: numeric[c] and frame[c].dropna().map(float.is_integer).all()
            for c in frame.columns
            if pd.api.types.is_float_dtype(frame[c])
        }
        body = []
        texts = {}
        for c in frame.columns:  # per column: ints stay ints
            column = [
                None
                if v is None or (isinstance(v, float) and math.isnan(v))
                else (int(v) if isinstance(v, float) and whole.get(c) else v)
                for v in frame[c].tolist()
            ]
            if c in powers:
                figures = (sigs or {}).get(c, sig)
                texts[c] = [
                    format_number(v) if v is None else format_number(float(v), figures, fixed_range=(0, 1))
                    for v in column
                ]
            elif c in (decimals or {}):
                places = int(decimals[c])
                texts[c] = [
                    format_number(v) if v is None or isinstance(v, str) else format_decimals(v, places)
                    for v in column
                ]
            else:
                texts[c] = format_column(column, (sigs or {}).get(c, sig))
        for group in together:  # one notation across the group: format its columns as one, then split
            joined = [v for c in group for v in frame[c].tolist()]
            shared = format_column(joined, (sigs or {}).get(group[0], sig))
            for k, c in enumerate(group):
                texts[c] = shared[k * len(frame) : (k + 1) * len(frame)]
        for i in range(len(frame)):
            cells = []
            for c in frame.columns:
                text = texts[c][i]
                cells.append(
                    f'<td class="n">{html.escape(text)}</td>'
                    if numeric[c]
                    else f"<td>{_cell_html(text)}</td>"
                )
            body.append("<tr>" + "".join(cells) + "</tr>")
        note = " Measured times: they vary from run to run." if timing else ""
        if left_out:  # the caption names every column the study wrote: say which this table leaves to the CSV
            names = ", ".join(_header_html(headers.get(c, c.replace("_", " "))) for c in left_out)
            note += f" Not shown here, in the CSV: {names}."
        csv = f"results/{study}/{'timings/' if timing else ''}{scene}/{name}.csv"
        long = long and len(frame) > LONG_TABLE_ROWS  # a short one stays where it is read
        markup = Markup(
            f'<figure id="{label}" class="table{" long" if long else ""}"><figcaption><span '
            f'class="label">Table {number}.</span> '
            f'{render_text(meta["caption"])}{note} <span class="source">Scene <code>{study}/{scene}</code>, '
            f"<code>{csv}</code>.</span></figcaption>"
            f'<div class="scroll"><table><thead><tr>{"".join(head)}</tr></thead>'
            f"<tbody>{''.join(body)}</tbody>"
            f"</table></div></figure>"
        )
        if not long:
            return markup
        # A long table stands in the appendix of long tables, in both editions, so that a chapter reads on;
        # where it was called, one line says what it holds and links to it.
        self.long_tables.setdefault(study, []).append(markup)
        return Markup(
            f'<p class="long-table">{self.ref(label)}, in the appendix (Long tables in full): '
            f"{render_text(meta['caption'])}</p>"
        )

    def long_table(self, study: str, label: str, says: str, caller=None):
        """{% call long_table(study, label, says) %}<figure ...>{% endcall %}: a table written in a chapter
        that is too long to stand there, put in the appendix of long tables as table(..., long=True) puts
        one; where it was called, one line says what it holds (`says`) and links to it."""
        self.long_tables.setdefault(study, []).append(Markup(caller()))
        return Markup(
            f'<p class="long-table">{self.ref(label)}, in the appendix (Long tables in full): {says}</p>'
        )

    def eq(self, label: str | None = None, caller=None):
        """{% call eq("eq:name") %}LaTeX{% endcall %}: a displayed, numbered equation."""
        latex = " ".join(str(caller()).split())
        number = self.numbering.label(label) if label else None
        uri, height_em = latex_image(latex)
        # --em: the screen sets the image's height in em of the text (screen.css); print keeps its own size
        img = f'<img class="math" src="{uri}" style="--em: {height_em:.3f}em" alt="{html.escape(latex)}">'
        # too wide for a phone and made of formulas side by side: a phone shows them one under the other
        narrow = stacked(latex) if width_em(latex) > PHONE_EM else None
        if narrow:
            uri, height_em = latex_image(narrow)
            img += f'<img class="math phone" src="{uri}" style="--em: {height_em:.3f}em" alt="">'
        tag = f'<span class="eqno">({number})</span>' if number else ""
        anchor = f' id="{label}"' if label else ""
        kinds = (" numbered" if number else "") + (" stacks" if narrow else "")
        return Markup(f'<div class="equation{kinds}"{anchor}>{img}{tag}</div>')

    def cite(self, *keys):
        # a claim's source may cite several: cite: [a, b]
        keys = [k for key in keys for k in ([key] if isinstance(key, str) else key)]
        links = [f'<a class="cite" href="#bib-{k}">{self.citations.cite(k)}</a>' for k in keys]
        return Markup("[" + ", ".join(links) + "]")

    # --- per-study blocks ------------------------------------------------------------------
    def claims(self, study):
        if study not in self.claim_results:
            path = assets.claims_file(study)
            self.claim_results[study] = (
                claims_mod.evaluate(study, path, self.index.entry) if path.exists() else []
            )
        return self.claim_results[study]

    def all_claims(self):
        """Every claim of the studies present, in report order."""
        return [c for study in self.index.studies() for c in self.claims(study)]

    def claim(self, study, claim_id):
        """One claim by its id, or None when its study is not in this build."""
        return next((c for c in self.claims(study) if c.id == claim_id), None)

    def stability(self, study):
        rows = []
        for scene in self.index.scenes(study):
            for case in self.index.summary(study, scene).get("stability", []):
                bound, measured = case.get("bound"), case.get("measured")
                margin = abs(measured) / bound if bound and measured is not None else 0.0
                rows.append({"scene": scene, **case, "margin": margin})
        return rows

    def scenes_table(self, study):
        rows = []
        for scene in self.index.scenes(study):
            prov = self.index.provenance[(study, scene)]
            rows.append(
                {
                    "scene": scene,
                    "title": self.index.summary(study, scene)["title"],
                    "effects": ", ".join(prov.get("effects_simulated", [])),
                    "seconds": prov.get("wall_seconds"),
                }
            )
        return rows

    def effects_table(self, study):
        """The effects the study's scenes list, as its registry describes them (each scene's job records them
        in its provenance): name, kind, what it adds, and the scenes that simulate it."""
        effects = {}
        for scene in self.index.scenes(study):
            for name, entry in self.index.provenance[(study, scene)].get("effects_registry", {}).items():
                effects.setdefault(name, {"name": name, **entry, "scenes": []})["scenes"].append(scene)
        return sorted(effects.values(), key=lambda effect: (effect["kind"], effect["name"]))

    # --- the whole --------------------------------------------------------------------------
    def context(self):
        studies = self.index.studies()
        build_times = defaultdict(float)
        for (study, _), prov in self.index.provenance.items():
            build_times[study] += prov.get("wall_seconds", 0.0)
        first = next(iter(self.index.provenance.values()), {})
        git = git_state()
        path = results_archive_name(self.index.dir, self.root)
        archive = {"name": path.name, "sha256": sha256_file(path)} if path.is_file() else None
        # The report's date: its commit's, so a rebuild does not change it; outside git, its newest result's.
        date = commit_date(self.root) or max(
            (p.get("finished", "") for p in self.index.provenance.values()), default=""
        )
        css = {
            name: (assets.TEMPLATES / f"{name}.css").read_text(encoding="utf-8")
            for name in ("report", "screen", "print")
        }
        return {
            "studies": studies,
            "quick": self.quick,
            "css": css,
            "script": (assets.TEMPLATES / "report.js").read_text(encoding="utf-8"),
            "git": git,
            "packages": package_versions(),
            "machine": machine(),
            "results_archive": archive,
            "cite_this": citation(
                self.root, git["commit"], bool(git["dirty"]), archive and archive["sha256"], date
            ),
            "commit_date": date,
            "results_packages": first.get("packages", {}),
            "results_commit": first.get("commit", "unknown"),
            "build_times": dict(build_times),
            "provenance": self.index.provenance,
            "scaling": self._benchmark("pipeline_scaling"),
            "bibliography": lambda: [
                (i + 1, k, Markup(format_entry(self.citations.entries[k])))
                for i, k in enumerate(self.citations.order)
            ],
        }

    def _benchmark(self, name: str):
        """A benchmark's saved measurement (benchmarks/results/<name>.json and .svg), or None if it has
        none."""
        path = self.root / "benchmarks" / "results" / f"{name}.json"
        if not (path.is_file() and path.with_suffix(".svg").is_file()):
            return None
        return json.loads(path.read_text(encoding="utf-8"))

    def render(self) -> str:
        template = self.env.get_template("report.html.j2")
        context = self.context()
        for _ in range(2):
            self.numbering.start_pass()
            self.citations.order = []
            self._count, self.cited, self.long_tables = 0, {}, {}
            text = template.render(**context)
        if self.numbering.missing:
            raise ValueError("unresolved cross-references: " + ", ".join(sorted(self.numbering.missing)))
        claims_mod.require([r for rs in self.claim_results.values() for r in rs])
        if set(self.index.studies()) == set(STUDIES):  # a partial build lacks some figures
            require_figures(self.ledger, set(self.numbering.numbers))
        return break_points(add_navigation(text))


def _bytecode_cache(cache: Path) -> jinja2.FileSystemBytecodeCache:
    """The templates compiled by this code (InlineMath rewrites them as they compile) and this Jinja."""
    folder = cache / f"jinja{jinja2.__version__}"
    folder.mkdir(parents=True, exist_ok=True)
    return jinja2.FileSystemBytecodeCache(str(folder))


def forget_others(cache: Path) -> None:
    """Remove the folders beside `cache`: what was kept for other code, which this code will not read."""
    for other in cache.parent.glob("*"):
        if other.is_dir() and other.name != cache.name:
            shutil.rmtree(other, ignore_errors=True)


def build_report(
    results_dir: Path, html_path: Path, *, quick=False, root: Path = Path("."), cache: Path | None = None
) -> None:
    """Render the report. `cache`: a folder for this code alone (the job's is named by its code digest), where
    what does not change from run to run (the typeset equations, the compiled templates) is kept; the other
    folders beside it, kept for other code, are removed."""
    if cache is not None:
        forget_others(Path(cache))
    report = Report(ResultsIndex(results_dir), root, quick, cache)
    io.atomic_write_text(html_path, report.render())


def main(argv=None) -> int:
    """Render the HTML report; what the report's data say is wrong (a failed claim, a bad ledger) is one line.
    The report job's command (`python -m classical_dynamics.report.build`), apart from cli.py, whose other
    commands it does not run; `python -m classical_dynamics report` comes here too. The PDF is a job of its
    own (report/pdf.py)."""
    import argparse
    import sys

    from .claims import ClaimFailure
    from .ledger import LedgerError

    parser = argparse.ArgumentParser(prog="python -m classical_dynamics.report.build")
    parser.add_argument("results")
    parser.add_argument("html")
    parser.add_argument("--root", default=".")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--cache", type=Path, help="a folder for this code's equations and templates")
    args = parser.parse_args(argv)
    try:
        build_report(
            Path(args.results), Path(args.html), quick=args.quick, root=Path(args.root), cache=args.cache
        )
    except (ClaimFailure, LedgerError) as error:
        print(f"report: {error}", file=sys.stderr)
        return 1
    except OSError as error:  # a full disk: the last good report stays (written atomically)
        if (line := io.no_space_line(error)) is None:
            raise
        print(f"report: {line}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
