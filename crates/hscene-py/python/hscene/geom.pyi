from ._hscene import (
    Honeycomb as Honeycomb,
    Isometry as Isometry,
    Line as Line,
    Plane as Plane,
    Point as Point,
    Space as Space,
    distance as distance,
    midpoint as midpoint,
)
