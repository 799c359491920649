"""hscene: exact ray tracing of hyperbolic 3-space (Poincaré ball).

    import hscene
    scene = hscene.Scene.from_file("scenes/thesis-appendix-a.hsc")
    rgb = scene.render(resolution=(160, 120))        # linear float32, H x W x 3
    scene.save("out.png")

The geometry (points, isometries, lines, planes, honeycombs) is in
`hscene.geom`; manifolds from SnapPy come in with `hscene.Space.from_snappy`.
See docs/python.md.
"""

from ._hscene import (
    Diagnostic,
    Picture,
    Scene,
    SceneError,
    SceneWarning,
    Space,
    __version__,
)
from . import geom

__all__ = [
    "Diagnostic",
    "Picture",
    "Scene",
    "SceneError",
    "SceneWarning",
    "Space",
    "geom",
    "__version__",
]
