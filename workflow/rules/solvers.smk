# The solver layer: work-precision on classical test problems, long horizons, hard cases.
# Scenes: workflow/scenes/solvers/.


rule solvers:
    """Every scene of the solver-layer study."""
    input:
        scene_outputs("solvers"),
