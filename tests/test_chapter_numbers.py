"""Every number a chapter cites by name is one its study records: a key renamed in the code (or misspelt in
the template) shows here in a second, not only when the full build renders the chapter. Read statically: each
name of a num(...) or value(...) call in a chapter must be one its study's modules pass to results.number,
literally or through an f-string's pattern (f"best_{error}_{name}" as best_.+_.+). Per study, not per scene:
a name two modules record passes even if one of them stops."""

import ast
import re
from pathlib import Path

import pytest

STUDIES = Path(__file__).resolve().parents[1] / "src/classical_dynamics/studies"
CITED = re.compile(r'\b(?:num|value)\(\s*[^,()]+,\s*"([A-Za-z0-9_]+)"')


def _pattern(node) -> re.Pattern | None:
    """A string constant as itself, an f-string as a pattern (None for one with under 4 fixed characters:
    f"{name}" alone would match any name)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return re.compile(re.escape(node.value))
    if isinstance(node, ast.JoinedStr):
        fixed = [v.value for v in node.values if isinstance(v, ast.Constant)]
        if sum(map(len, fixed)) >= 4:
            return re.compile(
                "".join(re.escape(v.value) if isinstance(v, ast.Constant) else ".+" for v in node.values)
            )
    return None


def _written(package: Path) -> list[re.Pattern]:
    """The names a study's modules record: the first argument of each results.number(...) call; where that is
    a variable, every string of the function around it (a name picked from a table of names)."""
    patterns = []
    for path in package.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for function in [n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.Module))]:
            for call in ast.walk(function):
                if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute)):
                    continue
                if call.func.attr != "number" or not call.args:
                    continue
                pattern = _pattern(call.args[0])
                if pattern:
                    patterns.append(pattern)
                elif not isinstance(function, ast.Module):
                    patterns += [p for n in ast.walk(function) if (p := _pattern(n))]
    return patterns


@pytest.mark.parametrize("study", sorted(p.parent.name for p in STUDIES.glob("*/chapter.html.j2")))
def test_each_number_a_chapter_cites_is_one_its_study_writes(study):
    template = (STUDIES / study / "chapter.html.j2").read_text(encoding="utf-8")
    cited = set(CITED.findall(template))
    assert len(cited) >= 10, "the pattern no longer finds the chapter's citations"
    patterns = _written(STUDIES / study)
    missing = sorted(n for n in cited if not any(p.fullmatch(n) for p in patterns))
    assert not missing, f"{study}'s chapter cites numbers its modules never write: {missing}"
