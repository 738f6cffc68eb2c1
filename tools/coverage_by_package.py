"""Branch coverage of src/ per package, from the data `make coverage` collected (coverage.py's JSON report,
grouped by the package each file is in).

    python tools/coverage_by_package.py [--under 80]    # exit 1 if a package is below the figure
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path


def package_of(path: str) -> str:
    """classical_dynamics.studies.chains for src/classical_dynamics/studies/chains/discrete.py."""
    parts = Path(path).parts
    start = parts.index("classical_dynamics")
    return ".".join(parts[start:-1])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--under", type=float, default=None, help="fail if a package is below this percent")
    args = parser.parse_args(argv)
    subprocess.run([sys.executable, "-m", "coverage", "combine", "--append", "--quiet"], check=False)
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch) / "coverage.json"
        # only this checkout's src/: tests also run copies of it in temporary folders, gone by now
        include = str(Path(__file__).resolve().parents[1] / "src" / "*")
        command = [sys.executable, "-m", "coverage", "json", "--quiet", "--include", include, "-o", str(out)]
        subprocess.run(command, check=True)
        files = json.loads(out.read_text())["files"]
    totals = defaultdict(lambda: [0, 0, 0, 0])  # branches, covered branches, statements, covered statements
    for path, data in files.items():
        s = data["summary"]
        t = totals[package_of(path)]
        t[0] += s["num_branches"]
        t[1] += s["covered_branches"]
        t[2] += s["num_statements"]
        t[3] += s["covered_lines"]
    low = []
    print(f"{'package':45s} {'branches':>9s} {'branch %':>9s} {'lines %':>8s}")
    for name in sorted(totals):
        b, cb, n, cn = totals[name]
        branch = 100.0 * cb / b if b else 100.0
        print(f"{name:45s} {b:9d} {branch:9.1f} {100.0 * cn / n if n else 100.0:8.1f}")
        if args.under is not None and branch < args.under:
            low.append(name)
    b, cb = sum(t[0] for t in totals.values()), sum(t[1] for t in totals.values())
    print(f"{'all of src/':45s} {b:9d} {100.0 * cb / b:9.1f}")
    if low:
        print(f"under {args.under:g} %: {', '.join(low)}")
    return 1 if low else 0


if __name__ == "__main__":
    sys.exit(main())
