"""Physical models assembled from a scene's effects."""
