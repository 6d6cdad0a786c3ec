"""Reference image, or each map's image and false-colour error, laid out like Guillen et al.
2017, Fig. 7.

Usage: variance_images.py --out PNG --reference variance_reference.f64 --size S
                          [--images variance_image_<seq>.f64 --maps a,b,... --table
                           variance_images.csv --sequence SEQ]
The .f64 files are float64, little-endian, row-major, row 0 = largest y; the image file holds
one image per map in --maps order. Without --images only the reference is drawn. Otherwise the
top row shows the reference and each map's image on one colour scale, the bottom row
|estimate - reference| on one logarithmic scale, each map's MSE (from the table) underneath.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

EXTENT = (-2.0, 2.0, -2.0, 2.0)  # x, y of the ground square; row 0 is the top (largest y)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--reference", required=True)
    ap.add_argument("--size", type=int, required=True)
    ap.add_argument("--images")
    ap.add_argument("--maps", default="")
    ap.add_argument("--table")
    ap.add_argument("--sequence", default="")
    a = ap.parse_args()
    s = a.size
    ref = np.fromfile(a.reference, dtype="<f8")
    if ref.size != s * s:
        raise SystemExit("variance_images.py: %s holds %d values, not %d" % (a.reference, ref.size, s * s))
    ref = ref.reshape(s, s)
    vmax = float(ref.max())
    if not a.images:
        fig, ax = plt.subplots(figsize=(5.2, 4.6), dpi=100)
        im = ax.imshow(ref, extent=EXTENT, cmap="inferno", vmin=0.0, vmax=vmax)
        fig.colorbar(im, ax=ax, label="irradiance E")
        ax.set_title("reference irradiance on the ground")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        fig.tight_layout()
        fig.savefig(a.out, format="png")
        return
    maps = [m for m in a.maps.split(",") if m]
    imgs = np.fromfile(a.images, dtype="<f8")
    if imgs.size != len(maps) * s * s:
        raise SystemExit("variance_images.py: %s does not hold %d images" % (a.images, len(maps)))
    imgs = imgs.reshape(len(maps), s, s)
    mse = {}
    with open(a.table, newline="") as f:
        for r in csv.DictReader(f):
            # The table also holds the shadowed pixels' rows: the label is the image's MSE.
            if r["sequence"] == a.sequence and r.get("region", "image") == "image":
                mse[r["map"]] = float(r["mse"])
    errs = np.abs(imgs - ref[None, :, :])
    positive = errs[errs > 0]
    lo = float(np.percentile(positive, 1)) if positive.size else 1e-12
    hi = float(errs.max()) if positive.size else 1.0
    cols = len(maps) + 1
    fig, axes = plt.subplots(2, cols, figsize=(2.3 * cols, 5.0), dpi=100, squeeze=False)
    axes[0][0].imshow(ref, extent=EXTENT, cmap="inferno", vmin=0.0, vmax=vmax)
    axes[0][0].set_title("reference", fontsize=9)
    axes[1][0].set_axis_off()
    axes[1][0].text(0.5, 0.5, "|estimate - reference|\nlog colour scale\n%.0e .. %.0e" % (lo, hi),
                    ha="center", va="center", fontsize=8, transform=axes[1][0].transAxes)
    for k, m in enumerate(maps):
        axes[0][k + 1].imshow(imgs[k], extent=EXTENT, cmap="inferno", vmin=0.0, vmax=vmax)
        axes[0][k + 1].set_title(m, fontsize=9)
        axes[1][k + 1].imshow(np.maximum(errs[k], lo), extent=EXTENT, cmap="viridis",
                              norm=LogNorm(vmin=lo, vmax=hi))
        axes[1][k + 1].set_xlabel("MSE %.3g" % mse.get(m, float("nan")), fontsize=9)
    for row in axes:
        for ax in row:
            ax.set_xticks([])
            ax.set_yticks([])
    fig.suptitle("16 samples per pixel, %s (first randomization); MSE over all randomizations"
                 % a.sequence, fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out, format="png")


if __name__ == "__main__":
    main()
