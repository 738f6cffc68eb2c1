# Study: vibrations of chains (Lamb, Higher Mechanics, ch. XI-XII). Scenes: workflow/scenes/chains/.


rule chains:
    """Every scene of the chains study."""
    input:
        scene_outputs("chains"),
