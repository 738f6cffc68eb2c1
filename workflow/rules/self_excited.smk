# Study: the self-excited rigid body (Lee 1964): phase planes of Euler's equations under body-fixed torques.
# Scenes: workflow/scenes/self_excited/ (one portrait each).


rule self_excited:
    """Every scene of the self-excited rigid body study."""
    input:
        scene_outputs("self_excited"),
