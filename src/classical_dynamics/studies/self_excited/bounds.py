"""What Lee's cases share (largest_axis.py, middle_axis.py, accuracy.py): the bounds their hard cases are held
to, and how long the huge excursion of the middle axis is integrated."""

OVERLAY_BOUND = 1e-8  # hard case: Euler's equations mapped into the plane against the plane system
INVARIANT_BOUND = 1e-8  # hard case: relative spread of E or C1 along the plane's trajectories
EXCURSION_PERIODS = 10  # periods of the closed form over which the huge excursion is integrated
PLANE_DEPARTURE = 1e-10  # the overlay in plane I or II stops where Euler's state has left the plane by this
