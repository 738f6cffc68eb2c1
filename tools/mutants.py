"""Mutation testing as a measured figure (make mutants): mutmut mutates the studies' and models' Python code
(pyproject.toml's [tool.mutmut]; functions under a decorator, the compiled loops among them, are left alone),
runs the fast tests that reach each mutant, and this prints the score per package and the surviving mutants.

    python tools/mutants.py [--max-children N] [--sample N] [--seed S] [--results-only]

A benchmark, not a gate: it takes long (every mutant reruns the tests that cover it). Score: killed (a test
failed, or the mutant timed out) over the mutants checked; "no tests" counts as not killed: no fast test
reaches it. The studies and models make about 59 000 mutants, days of CPU: --sample N checks N mutants of each
package drawn at random (a fixed seed, so two runs check the same ones), and the score of a package is then an
estimate, printed with its 95 % interval (Wilson's).
"""

from __future__ import annotations

import argparse
import functools
import os
import re
import subprocess
import sys
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
KILLED = {"killed", "timeout"}


def package_of(mutant: str) -> str:
    """classical_dynamics.studies.chains for classical_dynamics.studies.chains.planar.x_modes__mutmut_3 (a
    method's name reads module.xǁClassǁmethod__mutmut_n)."""
    module = re.split(r"\.x[_ǁ]", mutant, maxsplit=1)[0]
    return module.rsplit(".", 1)[0]


def function_of(mutant: str) -> str:
    """planar.x_modes for classical_dynamics.studies.chains.planar.x_modes__mutmut_3."""
    return ".".join(mutant.rsplit("__mutmut_", 1)[0].split(".")[-2:])


def statuses() -> dict[str, str]:
    out = subprocess.run(
        [sys.executable, "-m", "mutmut", "results", "--all", "true"],
        cwd=ROOT,
        env=environment(),
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    return dict(re.findall(r"^\s*(\S+__mutmut_\d+): (.+?)\s*$", out, re.M))


# Functions that draw a figure (matplotlib calls: colours, widths, label places) rather than compute: their
# mutants are counted apart and not drawn into the sample. What a figure draws is data the computing functions
# record (figure_data's tables), and those are scored; a moved label has no reference to be tested against.
DRAWING = re.compile(
    r"^(?!_?record)(.*figure|_?draw|_?plot|.*_ticks$|.+_panels$|panel_title$|legend_|axes_labels$)"
)


def drawing(mutant: str) -> bool:
    """The mutant sits in a function that draws (planar.x__mode_shape_figure__mutmut_3, or a method's)."""
    return bool(DRAWING.search(re.split(r"[ǁ.]", function_of(mutant))[-1].removeprefix("x_")))


def _function_source(mutant: str, which: str) -> str | None:
    """The source of a mutant's function (which: the mutant's own name, or its function's __mutmut_orig) in
    mutmut's copy of the module."""
    module = re.split(r"\.x[_ǁ]", mutant, maxsplit=1)[0]
    path = ROOT / "mutants" / "src" / (module.replace(".", "/") + ".py")
    if not path.exists():
        path = path.with_suffix("") / "__init__.py"
    return _functions(path).get(which.rsplit(".", 1)[-1])


@functools.lru_cache(maxsize=None)
def _functions(path: Path) -> dict[str, str]:
    """{name: source} of every function (and method) in one of mutmut's module copies."""
    lines, found = path.read_text(encoding="utf-8").splitlines(), {}
    for i, line in enumerate(lines):
        head = re.match(r"\s*def (\w+)\(", line)
        if head:
            indent = len(line) - len(line.lstrip())
            end = i + 1
            while end < len(lines) and (
                not lines[end].strip() or len(lines[end]) - len(lines[end].lstrip()) > indent
            ):
                end += 1
            found[head[1]] = "\n".join(lines[i:end])
    return found


def _prose(node) -> bool:
    """A string a reader sees: it holds a space or a $ (a formula), as no key or name of ours does; an
    f-string with such a part."""
    import ast

    if isinstance(node, ast.JoinedStr):
        return any(_prose(part) for part in node.values)
    return (
        isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and bool(re.search(r"[ $]", node.value))
    )


@functools.lru_cache(maxsize=4096)
def _shape(source: str) -> str:
    """The syntax tree with every prose string (a note, caption, title, label) and every None made one
    placeholder, every note= dropped (prose for the reader, None by default), and the function's name."""
    import ast
    import textwrap

    class Placeholders(ast.NodeTransformer):
        def visit_JoinedStr(self, node):
            return ast.Constant("·") if _prose(node) else self.generic_visit(node)

        def visit_Constant(self, node):
            return ast.Constant("·") if node.value is None or _prose(node) else node

        def visit_Call(self, node):
            node.keywords = [k for k in node.keywords if k.arg != "note"]
            return self.generic_visit(node)

    tree = Placeholders().visit(ast.parse(textwrap.dedent(source)))
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            node.name = "f"
    return ast.dump(tree)


def prose_only(mutant: str) -> bool:
    """The mutant changes only prose a reader sees (a string with a space or a $, or it to None, or a note):
    text no test can check against a reference. A changed key (a number's or a table's name) is scored."""
    try:
        original = _function_source(mutant, mutant.rsplit("__mutmut_", 1)[0] + "__mutmut_orig")
        changed = _function_source(mutant, mutant)
        return bool(original and changed) and _shape(original) == _shape(changed)
    except (OSError, SyntaxError):
        return False


def set_apart(mutant: str) -> str:
    """Why a mutant is not scored ("" if it is): it sits in a function that draws, or changes prose only."""
    return "draws a figure" if drawing(mutant) else "changes prose only" if prose_only(mutant) else ""


def drawn(found: dict[str, str], per_package: int, seed: int) -> list[str]:
    """`per_package` mutant names of each package, drawn at random with `seed` (all of a smaller package),
    from the computing functions only."""
    import random

    by_package = defaultdict(list)
    for name in sorted(found):
        if not set_apart(name):
            by_package[package_of(name)].append(name)
    draw = random.Random(seed)
    return [
        name
        for package in sorted(by_package)
        for name in draw.sample(by_package[package], min(per_package, len(by_package[package])))
    ]


def wilson(killed: int, n: int) -> tuple[float, float]:
    """The 95 % interval of killed/n (Wilson's score interval: sound for small n, and near 0 and 1)."""
    if not n:
        return 0.0, 1.0
    z, p = 1.96, killed / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * ((p * (1 - p) / n + z * z / (4 * n * n)) ** 0.5) / (1 + z * z / n)
    return centre - half, centre + half


def environment() -> dict:
    # mutmut copies src/ into mutants/ and runs there: its copy must come before the editable install's
    return {**os.environ, "PYTHONPATH": "src" + os.pathsep + os.environ.get("PYTHONPATH", "")}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-children", type=int, default=os.cpu_count())
    parser.add_argument("--sample", type=int, default=0, help="mutants per package, drawn at random (0: all)")
    parser.add_argument("--seed", type=int, default=1964, help="the draw's seed")
    parser.add_argument("--results-only", action="store_true", help="print the last run's figures")
    args = parser.parse_args(argv)
    if not args.results_only:
        # mutmut copies files, not links: the report's files (report/, linked into the package) are linked
        # into its copy by hand, to its copy of report/ (pyproject's also_copy)
        link = ROOT / "mutants/src/classical_dynamics/report/files"
        link.parent.mkdir(parents=True, exist_ok=True)
        if not link.is_symlink():
            link.symlink_to(os.readlink(ROOT / "src/classical_dynamics/report/files"))
        run = [sys.executable, "-m", "mutmut", "run", "--max-children", str(args.max_children)]
        if args.sample:
            # mutmut makes every mutant first (a run of a name that matches none, which it then refuses: no
            # check), then runs the drawn ones
            subprocess.run(run + ["none.x_none__mutmut_0"], cwd=ROOT, env=environment(), check=False)
            run += drawn(statuses(), args.sample, args.seed)
        subprocess.run(run, cwd=ROOT, env=environment(), check=True)
    found = statuses()
    apart = {name: set_apart(name) for name in found}
    found = {name: status for name, status in found.items() if not apart[name]}
    if args.sample:
        found = {name: status for name, status in found.items() if status != "not checked"}
    by_package: dict[str, Counter] = defaultdict(Counter)
    survivors = defaultdict(Counter)
    for mutant, status in found.items():
        by_package[package_of(mutant)][status] += 1
        if status == "survived":
            survivors[package_of(mutant)][function_of(mutant)] += 1
    # score: killed over the mutants checked so far ("not checked": a run still going, or stopped early)
    header = ("package", "mutants", "checked", "killed", "survived", "no tests", "score", "95 %")
    print(f"{header[0]:40} " + " ".join(f"{h:>9}" for h in header[1:-1]) + f" {header[-1]:>13}")
    total = Counter()
    for package in sorted(by_package) + ["all"]:
        c = total if package == "all" else by_package[package]
        if package != "all":
            total += c
        n, killed = sum(c.values()), sum(c[s] for s in KILLED)
        checked = n - c["not checked"]
        score = f"{killed / checked:9.1%}" if checked else f"{'—':>9}"
        low, high = wilson(killed, checked)
        row = (n, checked, killed, c["survived"], c["no tests"])
        interval = f"{low:6.0%}–{high:<6.0%}" if checked else ""
        print(f"{package:40} " + " ".join(f"{v:9d}" for v in row) + " " + score + f" {interval:>13}")
    for why in ("draws a figure", "changes prose only"):
        counts = Counter(package_of(name) for name, reason in apart.items() if reason == why)
        listed = ", ".join(f"{package.rsplit('.', 1)[-1]} {n}" for package, n in sorted(counts.items()))
        print(f"\nNot scored, {why}: {sum(counts.values())} mutants ({listed or 'none'}).")
    print("\nSurviving mutants by function (mutmut show <name>__mutmut_<k> prints one change):")
    for package in sorted(survivors):
        listed = ", ".join(f"{name} {count}" for name, count in survivors[package].most_common())
        print(f"  {package}: {listed}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
