"""Reference counting: a thousand renders of a tiny scene do not grow the process.

Two measures: the resident memory (what a user sees) and the bytes malloc has handed out and not
had back (glibc's mallinfo2, over every arena: free of the page and fragmentation noise of the
resident size, so that a leak of a few hundred bytes per render shows).
"""
import ctypes
import gc
import resource
import sys

import candela
from conftest import tiny_document

# 32x32 pixels: the image and its albedo layer are 12 KiB each, so that leaking either (or the
# film, or the scene) over 1000 renders is at least 12 MiB, six times the resident bound.
RESIDENT_BOUND_KIB = 2048
# 64 bytes a render: far below any object a render makes (a thread's record in TBB, an
# exception's, a dict's); measured: 0.2 KiB over 1000 renders after the first 100 (6 KiB over
# the first 1000 after those).
MALLOC_BOUND_BYTES = 64 * 1000


class _MallInfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in
                "arena ordblks smblks hblks hblkhd usmblks fsmblks uordblks fordblks keepcost".split()]


_libc = ctypes.CDLL(None)
_libc.mallinfo2.restype = _MallInfo2


def malloc_bytes():
    info = _libc.mallinfo2()
    return info.uordblks + info.hblkhd  # in use from the arenas, and in blocks of their own


def resident_kib():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * resource.getpagesize() // 1024


def tiny_scene_dict():
    d = tiny_document()
    d["camera"]["resolution"] = [32, 32]
    d["sampler"]["spp"] = 1
    return d


def renders(n, kept=None):
    d = tiny_scene_dict()
    for i in range(n):
        scene = candela.Scene.from_dict(d)
        image = candela.render(scene, threads=1, aovs=["albedo"], seed=i)
        if i % 100 == 0:
            image._repr_png_()
        if kept is not None:
            kept.append(image)
        del scene, image
    gc.collect()


def growth(n, kept=None):
    """(resident KiB, malloc'd bytes) that n renders leave behind."""
    gc.collect()
    resident, used = resident_kib(), malloc_bytes()
    renders(n, kept)
    return resident_kib() - resident, malloc_bytes() - used


def test_a_thousand_renders_do_not_leak():
    renders(200)  # allocators, caches and the thread pool reach their steady size
    resident, used = growth(1000)
    assert resident < RESIDENT_BOUND_KIB, f"resident memory grew by {resident} KiB over 1000 renders"
    assert used < MALLOC_BOUND_BYTES, f"malloc'd memory grew by {used} bytes over 1000 renders"


def test_the_measures_see_a_leak_of_the_images():
    """The control: holding every image, as a leak of them would, exceeds both bounds."""
    kept = []
    resident, used = growth(1000, kept)
    assert resident > RESIDENT_BOUND_KIB and used > MALLOC_BOUND_BYTES


def test_render_keeps_no_reference_to_its_scene():
    scene = candela.Scene.from_dict(tiny_scene_dict())
    count = sys.getrefcount(scene)
    candela.render(scene, threads=1)
    assert sys.getrefcount(scene) == count
