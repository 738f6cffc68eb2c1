"""The source ledger: every quantitative statement of a source, and what in the report checks it.

report/ledger/<source>.yaml lists a source's statements (where, what it states, its value as
printed). Each maps to exactly one of: a claim (claim: <study>/<claim id>), a figure (figure: <label>), a
reason it is out of scope (out_of_scope: why), or, until the report checks it, missing: what would. A
statement that maps to nothing, to two things, or to a claim or figure that does not exist stops the build.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..scenes.loader import project_yaml

KINDS = ("claim", "figure", "out_of_scope", "missing")


class LedgerError(ValueError):
    pass


@dataclass
class Statement:
    source: str
    id: str
    where: str
    states: str
    printed: str
    kind: str  # one of KINDS
    target: str  # the claim or figure label, the reason, or what is missing

    @property
    def study(self) -> str | None:
        return self.target.split("/", 1)[0] if self.kind == "claim" else None


@dataclass
class Source:
    key: str
    title: str
    statements: list

    def count(self, kind: str) -> int:
        return sum(s.kind == kind for s in self.statements)

    @property
    def in_scope(self) -> int:
        return len(self.statements) - self.count("out_of_scope")

    @property
    def covered(self) -> int:
        return self.count("claim") + self.count("figure")


def claim_ids(claims_files: dict[str, Path]) -> set[str]:
    """study/id of every claim declared in the studies' claims files ({study: its claims.yaml})."""
    ids = set()
    for study, path in claims_files.items():
        if Path(path).is_file():
            for claim in project_yaml(path) or []:
                ids.add(f"{study}/{claim['id']}")
    return ids


def read_ledger(ledger_dir: Path, claims_files: dict[str, Path]) -> list[Source]:
    """Every source's ledger, checked: each statement maps to exactly one existing thing."""
    known_claims = claim_ids(claims_files)
    sources = []
    for path in sorted(Path(ledger_dir).glob("*.yaml")):
        data = project_yaml(path) or {}
        key = data.get("source", {}).get("key", path.stem)
        statements, seen = [], set()
        for entry in data.get("statements") or []:
            sid = entry.get("id", "?")
            where = f"{path.name}: statement '{sid}'"
            if sid in seen:
                raise LedgerError(f"{where} appears twice")
            seen.add(sid)
            kinds = [k for k in KINDS if entry.get(k)]
            if len(kinds) != 1:
                raise LedgerError(
                    f"{where} must map to exactly one of {', '.join(KINDS)}; it maps to "
                    f"{', '.join(kinds) or 'nothing'}"
                )
            kind, target = kinds[0], str(entry[kinds[0]])
            if kind == "claim" and target not in known_claims:
                raise LedgerError(f"{where} maps to claim '{target}', which no study's claims.yaml declares")
            statements.append(
                Statement(
                    source=key,
                    id=sid,
                    where=str(entry.get("where", "")),
                    states=str(entry.get("states", "")),
                    printed=str(entry.get("printed", "")),
                    kind=kind,
                    target=target,
                )
            )
        sources.append(Source(key=key, title=data.get("source", {}).get("title", key), statements=statements))
    return sources


def require_figures(sources: list[Source], labels: set[str]) -> None:
    """A statement mapped to a figure names one the report draws (checked once the report is numbered)."""
    for source in sources:
        for s in source.statements:
            if s.kind == "figure" and s.target not in labels:
                raise LedgerError(
                    f"{source.key}: statement '{s.id}' maps to figure '{s.target}', which the report "
                    "does not draw"
                )
