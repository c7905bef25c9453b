"""Image files: what write writes, read reads back, in every format the CLI writes."""
import numpy as np
import pytest

import candela


def ramp():
    y, x = np.mgrid[0:6, 0:8]
    return np.stack([x / 8, y / 6, (x + y) / 14], axis=2).astype(np.float32)


@pytest.mark.parametrize("ext", [".exr", ".pfm"])
def test_linear_float_formats_round_trip_exactly(tmp_path, ext):
    image = ramp() * 5
    candela.write(image, tmp_path / f"x{ext}")
    assert candela.read(tmp_path / f"x{ext}").tobytes() == image.tobytes()


def test_hdr_and_png_round_trip_to_their_precision(tmp_path):
    image = ramp()
    candela.write(image, tmp_path / "x.hdr")
    # RGBE: 8 bits of mantissa under the pixel's largest channel's exponent
    assert np.allclose(candela.read(tmp_path / "x.hdr"), image, rtol=0, atol=1 / 128)
    candela.write(image, tmp_path / "x.png")  # clamp tone map, sRGB: 8 bits back to linear
    assert np.allclose(candela.read(tmp_path / "x.png"), image, atol=0.01)
    candela.write(image, tmp_path / "x.ppm")
    assert (tmp_path / "x.ppm").read_bytes().startswith(b"P")


def test_grey_arrays_become_three_equal_channels(tmp_path):
    grey = ramp()[..., 0]
    candela.write(grey, tmp_path / "g.pfm")
    back = candela.read(tmp_path / "g.pfm")
    assert back.shape == (6, 8, 3) and np.array_equal(back[..., 1], grey)


def test_display_settings_tone_map_the_png(tmp_path):
    image = candela.Image(ramp() * 4, display={"tonemap": "reinhard"})
    candela.write(image, tmp_path / "r.png")
    clamped = tmp_path / "c.png"
    candela.write(image, clamped, display={"tonemap": "clamp"})
    assert (tmp_path / "r.png").read_bytes() == image._repr_png_()
    assert clamped.read_bytes() != image._repr_png_()
    assert image._repr_png_().startswith(b"\x89PNG\r\n\x1a\n")


def test_aov_layers_go_into_the_exr(tmp_path):
    image = candela.Image(ramp(), aovs={"depth": ramp()[..., :1] * 10, "albedo": ramp()})
    candela.write(image, tmp_path / "x.exr")
    assert np.array_equal(candela.read(tmp_path / "x.exr"), ramp())
    candela.write(image, tmp_path / "x.pfm")
    assert np.array_equal(candela.read(tmp_path / "x.depth.pfm")[..., 0], ramp()[..., 0] * 10)
