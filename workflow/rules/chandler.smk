# Study: the Chandler wobble, from Euler's rigid Earth to the observed polar motion.
# Scenes: workflow/scenes/chandler/ (model Earths, and the IERS C04 observations).


rule chandler:
    """Every scene of the Chandler wobble study."""
    input:
        scene_outputs("chandler"),
