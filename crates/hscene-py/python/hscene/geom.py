"""hgeom's exact hyperbolic geometry (Poincaré ball model).

Points are given by ball coordinates, or on the hyperboloid as
(x, y, z, t) with the time coordinate last (hgeom's order; pass
time="first" for SnapPy's). `distance(a, b)` also takes two N x 3 numpy
arrays of ball coordinates and computes the N distances in parallel.
"""

from ._hscene import Honeycomb, Isometry, Line, Plane, Point, Space, distance, midpoint

__all__ = ["Honeycomb", "Isometry", "Line", "Plane", "Point", "Space", "distance", "midpoint"]
