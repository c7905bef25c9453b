"""Renders: the CLI's bits, AOV layers' shapes and dtypes, statistics, keywords, progress."""
import numpy as np
import pytest

import candela
from conftest import CORNELL, CORNELL_PBRT, run_cli, tiny_document

SIZE = (24, 16)


@pytest.mark.parametrize("scene_file, extra", [(CORNELL, []), (CORNELL, ["--spectral"]), (CORNELL_PBRT, [])])
def test_the_same_bits_as_the_cli(tmp_path, scene_file, extra):
    out = tmp_path / "cli.pfm"
    run_cli("render", scene_file, "--spp", 3, "--seed", 7, "--resolution", "24x16", "--threads", 2, *extra,
            "-o", out)
    image = candela.render(candela.load(scene_file), spp=3, seed=7, resolution=SIZE, threads=2,
                           spectral=True if extra else None)
    cli = candela.read(out)
    assert image.dtype == np.float32 and image.shape == (16, 24, 3)
    assert image.tobytes() == cli.tobytes()
    assert image.mean() > 0  # a black image would match a black one


def test_the_cli_writes_the_pythons_png_and_exr(tmp_path):
    run_cli("render", CORNELL, "--spp", 2, "--resolution", "24x16", "-o", tmp_path / "cli.png",
            "-o", tmp_path / "cli.exr")
    image = candela.render(candela.load(CORNELL), spp=2, resolution=SIZE)
    assert image._repr_png_() == (tmp_path / "cli.png").read_bytes()
    candela.write(image, tmp_path / "py.exr")
    assert (tmp_path / "py.exr").read_bytes() == (tmp_path / "cli.exr").read_bytes()


def test_aov_layers_shapes_and_dtypes(cornell):
    image = candela.render(cornell, spp=2, resolution=SIZE, aovs=["albedo", "normal", "depth", "position",
                                                                   "variance", "spp"])
    channels = {"albedo": 3, "normal": 3, "depth": 1, "position": 3, "variance": 3, "spp": 1}
    assert set(image.aovs) == set(channels)
    for name, c in channels.items():
        layer = image.aovs[name]
        assert layer.dtype == np.float32 and layer.shape == (16, 24, c), name
    assert np.all(image.aovs["spp"] == 2)
    assert np.all(image.aovs["albedo"] >= 0) and np.all(image.aovs["albedo"] <= 1)
    assert candela.render(cornell, spp=1, resolution=SIZE).aovs == {}


def test_aov_bits_match_the_cli(tmp_path, cornell):
    run_cli("render", CORNELL, "--spp", 2, "--resolution", "24x16", "--aov", "albedo,normal,depth", "-o",
            tmp_path / "x.pfm")
    image = candela.render(cornell, spp=2, resolution=SIZE, aovs=["albedo", "normal", "depth"])
    for name in ("albedo", "normal"):
        assert image.aovs[name].tobytes() == candela.read(tmp_path / f"x.{name}.pfm").tobytes(), name
    depth = candela.read(tmp_path / "x.depth.pfm")
    assert image.aovs["depth"][..., 0].tobytes() == np.ascontiguousarray(depth[..., 0]).tobytes()


def test_statistics():
    image = candela.render(candela.Scene.from_dict(tiny_document()), spp=3, threads=1)
    s = image.stats
    assert (s["width"], s["height"], s["spp"], s["spp_done"], s["end"]) == (8, 6, 3, 3, "complete")
    assert s["samples"] == 8 * 6 * 3 and s["threads"] == 1
    assert s["rays"]["camera"] == 8 * 6 * 3 and s["rays"]["total"] >= s["rays"]["camera"]
    assert s["integrator"] == "path"


def test_keywords_override_the_scene():
    scene = candela.Scene.from_dict(tiny_document())
    assert candela.render(scene).shape == (6, 8, 3)
    assert candela.render(scene, resolution=(5, 3)).shape == (3, 5, 3)
    a, b = candela.render(scene, seed=1), candela.render(scene, seed=2)
    assert not np.array_equal(a, b)
    assert np.array_equal(candela.render(scene, seed=1, threads=1), a)  # threads change no bits
    assert candela.render(scene, integrator="bsdf").stats["integrator"] == "bsdf"


def test_time_limit_stops_between_passes():
    scene = candela.Scene.from_dict(tiny_document())
    image = candela.render(scene, spp=1 << 24, resolution=(64, 64), time_limit=0.3, threads=2)
    assert image.stats["end"] == "time_limit"
    assert 0 < image.stats["spp_done"] < 1 << 24


def test_target_error_stops_when_met():
    scene = candela.Scene.from_dict(tiny_document())
    image = candela.render(scene, spp=4096, target_error=0.05, threads=2)
    assert image.stats["converged"] and image.stats["relmse_estimate"] <= 0.05
    assert image.stats["spp_done"] < 4096


def test_progress_callback_sees_fractions_up_to_one():
    seen = []
    candela.render(candela.Scene.from_dict(tiny_document()), spp=64, progress=seen.append)
    assert seen and seen[-1] == 1.0 and seen == sorted(seen) and all(0 <= f <= 1 for f in seen)


def test_progress_true_shows_a_bar_and_changes_no_bits():
    scene = candela.Scene.from_dict(tiny_document())  # a tqdm bar if tqdm is installed, else the library's
    assert np.array_equal(candela.render(scene, spp=16, progress=True), candela.render(scene, spp=16))


def test_an_error_in_the_progress_callback_stops_the_render():
    def fail(fraction):
        raise RuntimeError("from the callback")
    scene = candela.Scene.from_dict(tiny_document())
    with pytest.raises(RuntimeError, match="from the callback"):
        candela.render(scene, spp=1 << 24, resolution=(64, 64), progress=fail)


def test_pythons_floating_point_mode_is_kept():
    """The render threads flush denormals to zero; the caller's thread, which renders too, not after."""
    import sys
    candela.render(candela.Scene.from_dict(tiny_document()), spp=4, threads=1)
    assert sys.float_info.min / 2 > 0  # a denormal, not flushed to zero
    assert np.float32(1e-38) / np.float32(10) > 0
