"""Type hints of candela's C++ extension; the package candela wraps it (use that)."""
import os
from typing import Callable, Dict, List, Optional, Tuple, Union

import numpy as np

PathLike = Union[str, "os.PathLike[str]"]
__version__: str

class SceneError(ValueError):
    """Bad input: a scene file, a scene document, a keyword's value or an image file.

    str(e) is the line the command line prints after "candela: error: ",
    'FILE:LINE:COL: /json/pointer: message', leaving out the parts that are unknown.
    """

    file: str
    """The file the error is in; '' when the scene came from a dict or the error is a keyword's."""
    line: int
    """1-based; 0 when unknown."""
    column: int
    """1-based; 0 when unknown."""
    pointer: str
    """The JSON pointer into the scene document (e.g. '/shapes/3/radius'); '' when none."""
    message: str
    """What is wrong, without the location."""

class Scene:
    """A scene: its JSON document (docs/SCENE_FORMAT.md) and what loading it needs besides.

    Immutable: change a scene by editing its dict and making a new one, e.g.
    Scene.from_dict(d, like=scene).
    """

    @staticmethod
    def from_dict(d: Dict[str, object], *, folder: Optional[PathLike] = None,
                  like: Optional["Scene"] = None) -> "Scene":
        """A scene from a scene document (a dict as to_dict returns, or one written by hand).

        folder: where relative file names (meshes, images) resolve; default: like's folder,
        else the current folder. like: a scene whose folder, and for a pbrt-v4 scene whose meshes
        held in memory, the document may use; while d equals like's document, errors point at
        like's file. Raises SceneError (located by JSON pointer) for a document that does not
        load, TypeError for a value no JSON document holds.
        """
    def to_dict(self) -> Dict[str, object]:
        """The scene document as a new dict (lists, str, float, int, bool, None): edit it freely."""
    @property
    def file(self) -> Optional[str]:
        """The file it was loaded from; None for a scene made from a dict."""

def load(path: PathLike) -> Scene:
    """Loads a scene file: candela's JSON, or pbrt-v4's (.pbrt, .pbrt.gz), with all it names.

    Raises SceneError with the file, line and column of the problem, as the CLI reports it.
    """

def render(scene: Scene, *, spp: Optional[int] = None, seed: Optional[int] = None,
           spectral: Optional[bool] = None, resolution: Optional[Tuple[int, int]] = None,
           threads: int = 0, aovs: Optional[List[str]] = None, target_error: Optional[float] = None,
           time_limit: Optional[float] = None, integrator: Optional[str] = None,
           sampler: Optional[str] = None, progress: Optional[Callable[[float], None]] = None,
           progress_bar: bool = False
           ) -> Tuple[np.ndarray, Dict[str, np.ndarray], Dict[str, object], Dict[str, object]]:
    """Renders through the render job: (image, AOV layers, statistics, display settings)."""

def write(path: PathLike, image: np.ndarray, aovs: Dict[str, np.ndarray],
          display: Optional[Dict[str, object]]) -> None:
    """Writes an image and its AOV layers through the library's image writers."""

def read(path: PathLike) -> np.ndarray:
    """Reads an image file as a float32 array (height, width, 3)."""

def png_bytes(image: np.ndarray, display: Optional[Dict[str, object]]) -> bytes:
    """The PNG file the library writes for `image`, as bytes."""
