"""Spherical-ellipse point sets for `disklab points --map` (Guillen et al. 2017, Fig. 1 layout).

Usage: points_ellipse.py --out PNG --title T --panel CSV LABEL A_T B_T [--panel ...]
Each CSV has index,u,v,x,y,z,pdf,dx,dy,lx,ly: dx, dy the hit point on the disk in radii (disk
frame x_e, n x x_e), lx, ly the direction's x_e, y_e parts over a = sin(alpha). A_T, B_T are the
tangent-ellipse semi-axes tan(alpha), tan(beta), which give the ellipse's outline. One column
per panel: the disk seen from its lit side (top), the directions projected along z_e (bottom).
Points are coloured by their stratum of a 4 x 4 grid of the unit square; rows with pdf 0
(rejected candidates) are drawn as grey crosses.
"""
import argparse
import csv
import math
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def stratum(r):
    return min(3, int(4 * float(r["u"]))) * 4 + min(3, int(4 * float(r["v"])))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="")
    ap.add_argument("--panel", nargs=4, action="append", required=True,
                    metavar=("CSV", "LABEL", "A_T", "B_T"))
    a = ap.parse_args()

    n = len(a.panel)
    fig, axes = plt.subplots(2, n, figsize=(2.6 * n + 0.4, 5.6), dpi=120, squeeze=False)
    for col, (path, label, a_t, b_t) in enumerate(a.panel):
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        ok = [r for r in rows if float(r["pdf"]) > 0]
        rej = [r for r in rows if float(r["pdf"]) <= 0]
        colours = [stratum(r) for r in ok]
        top, bottom = axes[0][col], axes[1][col]

        top.add_patch(plt.Circle((0, 0), 1.0, fill=False, color="black", lw=0.8))
        top.scatter([float(r["dx"]) for r in ok], [float(r["dy"]) for r in ok], s=5,
                    c=colours, cmap="tab20", vmin=0, vmax=15, linewidths=0)
        if rej:
            top.scatter([float(r["dx"]) for r in rej], [float(r["dy"]) for r in rej], s=6,
                        marker="x", color="0.6", linewidths=0.5)
        top.set_xlim(-1.45, 1.45)
        top.set_ylim(-1.45, 1.45)
        top.set_title(f"{label}" + (f" ({len(rej)} rejected)" if rej else ""), fontsize=9)

        # Outline: the tangent ellipse (a_t cos t, b_t sin t, 1), normalized, scaled by 1/a.
        at, bt = float(a_t), float(b_t)
        sa = at / math.hypot(at, 1.0)
        xs, ys = [], []
        for i in range(361):
            t = 2 * math.pi * i / 360
            x, y = at * math.cos(t), bt * math.sin(t)
            norm = math.sqrt(x * x + y * y + 1.0)
            xs.append(x / norm / sa)
            ys.append(y / norm / sa)
        bottom.plot(xs, ys, color="black", lw=0.8)
        bottom.scatter([float(r["lx"]) for r in ok], [float(r["ly"]) for r in ok], s=5,
                       c=colours, cmap="tab20", vmin=0, vmax=15, linewidths=0)
        if rej:
            bottom.scatter([float(r["lx"]) for r in rej], [float(r["ly"]) for r in rej], s=6,
                           marker="x", color="0.6", linewidths=0.5)
        bottom.set_xlim(-1.2, 1.2)
        bottom.set_ylim(-1.2, 1.2)
        for ax in (top, bottom):
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
    axes[0][0].set_ylabel("disk (lit side)", fontsize=8)
    axes[1][0].set_ylabel("directions, ellipse frame / sin(alpha)", fontsize=8)
    fig.suptitle("\n".join(textwrap.wrap(a.title, width=int(45 * n + 10))), fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out)


if __name__ == "__main__":
    main()
