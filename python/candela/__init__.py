"""candela from Python: load a scene, change it, render it to a numpy array.

    import candela
    scene = candela.load("scenes/cornell-box/scene.json")
    d = scene.to_dict()
    d["materials"]["white"]["albedo"] = [0.5, 0.5, 0.5]
    image = candela.render(candela.Scene.from_dict(d, like=scene), spp=64, seed=1)
    candela.write(image, "cbox.exr")

The heavy lifting is the C++ library (the render job, the loaders, the image files), through the
extension ``candela._candela``; this file adds the ``Image`` array, the progress bar and the
signatures.
"""
from __future__ import annotations

import os
from typing import Callable, Dict, Iterable, Optional, Sequence, Tuple, Union

import numpy as np

from . import _candela
from ._candela import Scene, SceneError, load

__all__ = ["Image", "Scene", "SceneError", "load", "render", "read", "write", "__version__"]
__version__: str = _candela.__version__

PathLike = Union[str, "os.PathLike[str]"]

# What a display dict holds: the scene's film keys that turn linear values into a PNG's.
_DEFAULT_DISPLAY = {"tonemap": "clamp", "exposure": 0.5, "transfer": "srgb", "gamma": 2.2}


class Image(np.ndarray):
    """A linear RGB image: a float32 numpy array of shape (height, width, 3), row 0 at the top.

    Besides the pixels it carries:
      display -- the scene's tone map and transfer curve (its film's "tonemap", "exposure",
                 "transfer", "gamma"), used by a notebook's display (_repr_png_) and for .png/.ppm
      aovs    -- the AOV layers asked for, by name: float32 arrays (height, width, channels)
      stats   -- the render's statistics (times, samples, rays), as `candela render --stats`
    Arithmetic and slicing give Images that keep them; np.asarray(image) is the plain array.
    """

    display: Dict[str, object]
    aovs: Dict[str, np.ndarray]
    stats: Dict[str, object]

    def __new__(cls, pixels, display: Optional[dict] = None, aovs: Optional[dict] = None,
                stats: Optional[dict] = None) -> "Image":
        image = np.asarray(pixels, dtype=np.float32).view(cls)
        image.display = dict(display or _DEFAULT_DISPLAY)
        image.aovs = dict(aovs or {})
        image.stats = dict(stats or {})
        return image

    def __array_finalize__(self, obj) -> None:
        self.display = getattr(obj, "display", dict(_DEFAULT_DISPLAY))
        self.aovs = getattr(obj, "aovs", {})
        self.stats = getattr(obj, "stats", {})

    def _repr_png_(self) -> Optional[bytes]:
        """The image as a PNG, tone mapped as the scene says: what a notebook shows."""
        if self.ndim not in (2, 3) or (self.ndim == 3 and self.shape[2] not in (1, 3)) or self.size == 0:
            return None
        return _candela.png_bytes(np.ascontiguousarray(self, dtype=np.float32), self.display)


def _tqdm_progress() -> Tuple[Optional[Callable[[float], None]], Callable[[], None]]:
    """A tqdm bar as a progress callback, and the function that closes it; (None, nothing) without tqdm."""
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None, lambda: None
    bar = tqdm(total=100, unit="%", bar_format="{l_bar}{bar}| {elapsed}<{remaining}")

    def update(fraction: float) -> None:
        bar.update(round(100 * fraction) - bar.n)

    return update, bar.close


def render(scene: Scene, *, spp: Optional[int] = None, seed: Optional[int] = None,
           spectral: Optional[bool] = None, resolution: Optional[Tuple[int, int]] = None,
           threads: int = 0, aovs: Optional[Iterable[str]] = None,
           target_error: Optional[float] = None, time_limit: Optional[float] = None,
           integrator: Optional[str] = None, sampler: Optional[str] = None,
           progress: Union[bool, Callable[[float], None]] = False) -> Image:
    """Renders `scene` and returns its image, bit for bit what `candela render` writes.

    Each keyword overrides the scene's setting as the command line's flag does (None keeps the
    scene's): spp (--spp), seed (--seed), spectral (True --spectral, False --rgb),
    resolution=(width, height) (--resolution), threads (0: all cores), aovs (layer names:
    albedo, normal, depth, position, variance, spp; the arrays are in image.aovs),
    target_error (--target-error), time_limit (seconds, --time-limit), integrator, sampler.

    progress: a callable, called with the fraction of the samples done after each pass; True
    shows a tqdm bar when tqdm is installed, else the library's bar on stderr.

    The GIL is released while rendering, so other Python threads run (and may render too).
    Ctrl-C stops the render at its next tile and raises KeyboardInterrupt. Bad input raises
    SceneError, whose text is the CLI's error line (file:line:col: /json/pointer: message).
    """
    callback: Optional[Callable[[float], None]] = None
    close: Callable[[], None] = lambda: None
    progress_bar = False
    if callable(progress):
        callback = progress
    elif progress:
        callback, close = _tqdm_progress()
        progress_bar = callback is None
    try:
        pixels, layers, stats, display = _candela.render(
            scene, spp=spp, seed=seed, spectral=spectral, resolution=resolution, threads=threads,
            aovs=None if aovs is None else list(aovs), target_error=target_error,
            time_limit=time_limit, integrator=integrator, sampler=sampler, progress=callback,
            progress_bar=progress_bar)
    finally:
        close()
    return Image(pixels, display=display, aovs=layers, stats=stats)


def write(image: np.ndarray, path: PathLike, *, aovs: Optional[Dict[str, np.ndarray]] = None,
          display: Optional[Dict[str, object]] = None) -> None:
    """Writes `image` (height, width, 3), or grey (height, width), to `path`, format by extension.

    .exr, .pfm, .hdr hold linear values; .png and .ppm are tone mapped with `display` (default:
    the Image's own, the scene's film settings). AOV layers (default: an Image's aovs) go inside
    an .exr, and beside other formats as <stem>.<layer>.<ext>, as `candela render --aov` writes.
    """
    if aovs is None:
        aovs = getattr(image, "aovs", {})
    if display is None:
        display = getattr(image, "display", None)
    _candela.write(os.fspath(path), np.asarray(image, dtype=np.float32), dict(aovs), display)


def read(path: PathLike) -> Image:
    """Reads an image file (.exr, .hdr, .pfm, .png) as linear RGB: an Image (height, width, 3).

    An 8-bit PNG is sRGB-decoded; a grey file becomes three equal channels.
    """
    return Image(_candela.read(os.fspath(path)))
