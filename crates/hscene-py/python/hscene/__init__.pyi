from . import geom as geom
from ._hscene import (
    Diagnostic as Diagnostic,
    Picture as Picture,
    Scene as Scene,
    SceneError as SceneError,
    SceneWarning as SceneWarning,
    Space as Space,
    __version__ as __version__,
)
