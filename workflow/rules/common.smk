# Shared by every study: the list of studies, scene discovery, and validation of every scene
# before anything runs. (Rules live in their own files: Snakemake's linter wants them apart.)

import sys
from pathlib import Path

from classical_dynamics.io import ResultError, check_result_folder
from classical_dynamics.scenes import SceneError
from classical_dynamics.scenes.loader import is_leftover
from classical_dynamics.scenes.validated import validate_all
from classical_dynamics.studies import STUDIES, validate

PY = sys.executable
QUICK = "--quick" if int(config.get("quick", 0)) else ""
PACKAGE = Path("src/classical_dynamics")


def scenes(study):
    """Every scene file of a study: dropping a YAML file in workflow/scenes/<study>/ adds it."""
    return sorted(p.stem for p in Path("workflow/scenes", study).glob("*.yaml") if not is_leftover(p))


def scene_outputs(study):
    return expand("results/{study}/{scene}", study=study, scene=scenes(study))


def result_state(wc):
    """'whole' for a scene folder that is absent or matches the checksums its provenance records, else why not:
    a params value, so that Snakemake reruns a scene whose result was truncated or edited since it ran."""
    folder = Path("results", wc.study, wc.scene)
    if not folder.exists():
        return "whole"
    try:
        check_result_folder(folder, deep=False)
    except ResultError as error:
        return f"corrupted: {error}"
    return "whole"


def code(*parts):
    """Source files a result depends on, so that changing them reruns it."""
    files = []
    for part in parts:
        path = PACKAGE / part
        files += sorted(str(p) for p in path.rglob("*.py")) if path.is_dir() else [str(path)]
    return files


SHARED_CODE = code("solvers", "models", "scenes", "io.py", "provenance.py", "cli.py", "formatting.py",
                   "units.py", "studies/__init__.py", "studies/results.py", "figure_style.py")


# Validate every scene of every study before any job is scheduled: a bad scene stops the
# build with one line (file, field, expectation) and nothing under results/ is touched.
# A scene valid with its present bytes, schema and code is not validated again (scenes/validated.py).
# `snakemake --unlock` runs no job, so a bad scene does not stand in its way.
try:
    if "--unlock" not in sys.argv:
        validate_all([(_study, _scene, Path(f"workflow/schemas/{_study}.schema.yaml"))
                      for _study in STUDIES for _scene in sorted(Path("workflow/scenes", _study).glob("*"))
                      if not is_leftover(_scene)],          # an editor's swap or backup file
                     validate, Path(".snakemake/validated-scenes.json"))
except SceneError as _error:
    sys.stderr.write(f"{_error}\n")
    sys.exit(1)
except Exception as _error:        # a fault of ours, not the user's; still one line
    sys.stderr.write(f"a scene could not be validated ({type(_error).__name__}: {_error})\n")
    sys.exit(1)
