#!/usr/bin/env python3
"""Sweeps a material parameter and saves the renders side by side as a matplotlib figure.

The material spheres scene (scenes/material-spheres) with every gold sphere's GGX roughness set to
each value in turn, rendered small, tone mapped as the scene says (ACES), and plotted side by
side. From the repository root:

    PYTHONPATH=build/python python3 python/examples/roughness_sweep.py -o roughness_sweep.png

About 10 s on 2 cores at the defaults (--spp 32, --width 320).
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import candela  # noqa: E402

SCENE = pathlib.Path(__file__).resolve().parents[2] / "scenes" / "material-spheres" / "scene.json"


def display(image):
    """The image as the scene's PNG shows it (its tone map and sRGB curve), as 8-bit RGB."""
    import io
    return plt.imread(io.BytesIO(image._repr_png_()), format="png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="roughness_sweep.png")
    parser.add_argument("--spp", type=int, default=32)
    parser.add_argument("--width", type=int, default=320, help="of each render, in pixels")
    parser.add_argument("--dpi", type=int, default=100, help="of the figure")
    parser.add_argument("--roughness", type=float, nargs="+", default=[0.01, 0.05, 0.15, 0.4])
    args = parser.parse_args()

    scene = candela.load(SCENE)
    width = args.width
    height = width * 400 // 960  # the scene's aspect ratio
    images = []
    for alpha in args.roughness:
        d = scene.to_dict()
        for name in ("gold_smooth", "gold_glossy", "gold_rough"):
            d["materials"][name]["roughness"] = alpha
        image = candela.render(candela.Scene.from_dict(d, like=scene), spp=args.spp, resolution=(width, height))
        images.append(image)
        print(f"roughness {alpha}: {image.stats['render_seconds']:.2f} s, mean {float(np.mean(image)):.4f}")

    fig, axes = plt.subplots(1, len(images), figsize=(3.2 * len(images), 1.9), squeeze=False)
    for ax, alpha, image in zip(axes[0], args.roughness, images):
        ax.imshow(display(image))
        ax.set_title(f"gold roughness {alpha}", fontsize=9)
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(args.output, dpi=args.dpi)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
