"""First points of every square sequence side by side, like Christensen 2018, Fig. 2.

Usage: sequences.py --out PNG --csv FILE [--title T]
The CSV has sequence,index,u,v; one panel per sequence, in the order of first appearance.
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--title", default="")
    a = ap.parse_args()

    panels = {}
    with open(a.csv, newline="") as f:
        for r in csv.DictReader(f):
            xs, ys = panels.setdefault(r["sequence"], ([], []))
            xs.append(float(r["u"]))
            ys.append(float(r["v"]))
    if not panels:
        raise SystemExit("sequences.py: no rows in " + a.csv)
    cols = math.ceil(math.sqrt(len(panels)))
    rows = math.ceil(len(panels) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 3.4 * rows), dpi=110,
                             squeeze=False)
    for ax in axes.flat:
        ax.set_axis_off()
    for k, (name, (xs, ys)) in enumerate(panels.items()):
        ax = axes.flat[k]
        ax.set_axis_on()
        ax.plot([0, 1, 1, 0, 0], [0, 0, 1, 1, 0], color="black", lw=0.6)
        ax.scatter(xs, ys, s=2.5, color="black", linewidths=0)
        ax.set_xlim(-0.01, 1.01)
        ax.set_ylim(-0.01, 1.01)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title("(%s) %s" % (chr(ord("a") + k), name), fontsize=10)
    if a.title:
        fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.out, format="png")


if __name__ == "__main__":
    main()
