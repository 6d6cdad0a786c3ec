"""Point-set pictures for `disklab points` (Christensen 2018, Figs. 2 and 3).

Usage: points.py --out PNG --csv FILE --mode disk|square --title T [--lines FILE]
       [--square-outline]
The CSV has index,u,v[,x,y,weight]; --lines holds polylines "line,x,y" (strata images).
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--mode", choices=["disk", "square"], required=True)
    ap.add_argument("--title", default="")
    ap.add_argument("--lines")
    ap.add_argument("--square-outline", action="store_true")
    a = ap.parse_args()

    with open(a.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(5, 5), dpi=120)
    if a.mode == "square":
        xs = [float(r["u"]) for r in rows]
        ys = [float(r["v"]) for r in rows]
        ax.plot([0, 1, 1, 0, 0], [0, 0, 1, 1, 0], color="black", lw=0.8)
        ax.scatter(xs, ys, s=6, c=range(len(xs)), cmap="viridis", linewidths=0)
        ax.set_xlim(-0.02, 1.02)
        ax.set_ylim(-0.02, 1.02)
    else:
        if a.lines:
            polylines = {}
            with open(a.lines, newline="") as f:
                for r in csv.DictReader(f):
                    polylines.setdefault(r["line"], ([], []))
                    polylines[r["line"]][0].append(float(r["x"]))
                    polylines[r["line"]][1].append(float(r["y"]))
            for xs, ys in polylines.values():
                ax.plot(xs, ys, color="0.8", lw=0.5, zorder=1)
        circle = plt.Circle((0, 0), 1.0, fill=False, color="black", lw=0.8, zorder=2)
        ax.add_patch(circle)
        if a.square_outline:
            ax.plot([-1, 1, 1, -1, -1], [-1, -1, 1, 1, -1], color="0.5", lw=0.6, zorder=2)
        inside = [r for r in rows if float(r["weight"]) > 0]
        zeros = [r for r in rows if float(r["weight"]) <= 0]
        ax.scatter([float(r["x"]) for r in inside], [float(r["y"]) for r in inside], s=8,
                   c=[int(r["index"]) for r in inside], cmap="viridis", linewidths=0, zorder=3,
                   vmin=0, vmax=max(len(rows) - 1, 1))
        if zeros:
            ax.scatter([float(r["x"]) for r in zeros], [float(r["y"]) for r in zeros], s=10,
                       facecolors="none", edgecolors="red", linewidths=0.6, zorder=3,
                       label="weight 0 (padding)")
            ax.legend(loc="upper right", fontsize=7)
        lim = 1.08
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    ax.set_title(a.title, fontsize=9)
    ax.set_xticks([])
    ax.set_yticks([])
    fig.tight_layout()
    fig.savefig(a.out)


if __name__ == "__main__":
    main()
