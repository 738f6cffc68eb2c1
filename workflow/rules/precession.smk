# Study: the precession of the equinoxes, from Lamb's secular formula to a spin-resolved Earth.
# Scenes: workflow/scenes/precession/ (secular, averaged and full rungs).


rule precession:
    """Every scene of the precession study."""
    input:
        scene_outputs("precession"),
