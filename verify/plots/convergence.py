"""RMS error vs sample count for one region, laid out like Christensen 2018, Figs. 5-6.

Usage: convergence.py --out PNG --csv convergence.csv --fits convergence_fits.csv --region R
                      [--title T] [--method-column strategy]
One log-log panel per strategy (or per value of --method-column, e.g. the variance study's
"map"; two columns, in the CSV's order), one curve per sequence with
its fitted slope in the legend; faint lines show the reference slopes -0.5, -0.75, -1, -1.5.
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REFERENCE_SLOPES = (-0.5, -0.75, -1.0, -1.5)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--fits", required=True)
    ap.add_argument("--region", required=True)
    ap.add_argument("--title", default="")
    ap.add_argument("--method-column", default="strategy")
    a = ap.parse_args()

    curves = {}  # strategy -> sequence -> [(n, rmse)]
    sequences = []
    with open(a.csv, newline="") as f:
        for r in csv.DictReader(f):
            if r["region"] != a.region:
                continue
            curves.setdefault(r[a.method_column], {}).setdefault(r["sequence"], []).append(
                (int(r["n"]), float(r["rmse"])))
            if r["sequence"] not in sequences:
                sequences.append(r["sequence"])
    if not curves:
        raise SystemExit("convergence.py: no rows for region " + a.region)
    slopes = {}
    with open(a.fits, newline="") as f:
        for r in csv.DictReader(f):
            if r["region"] == a.region and r["slope"]:
                slopes[(r[a.method_column], r["sequence"])] = float(r["slope"])

    values = [e for per in curves.values() for pts in per.values() for _, e in pts if e > 0]
    ymin, ymax = min(values) / 1.5, max(values) * 1.5
    # A curve at rounding level (a zero-variance estimator) would squash every shared panel:
    # the axis spans at most 1e9 below the largest error, and such a panel says so instead.
    ymin = max(ymin, ymax * 1e-9)
    strategies = list(curves)
    cols = 2
    rows = math.ceil(len(strategies) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(6.2 * cols, 4.3 * rows), dpi=100,
                             squeeze=False, sharex=True, sharey=True)
    for ax in axes.flat:
        ax.set_axis_off()
    cmap = plt.get_cmap("tab10")
    colors = {s: cmap(i % 10) for i, s in enumerate(sequences)}
    for k, st in enumerate(strategies):
        ax = axes.flat[k]
        ax.set_axis_on()
        ns = sorted({n for pts in curves[st].values() for n, _ in pts})
        n0, n1 = ns[0], ns[-1]
        anchor = max(e for pts in curves[st].values() for n, e in pts if n == n0)
        for s in REFERENCE_SLOPES:
            ax.plot([n0, n1], [anchor, anchor * (n1 / n0) ** s], color="0.75", lw=0.8, ls="--",
                    zorder=1)
            end = anchor * (n1 / n0) ** s
            if end >= ymin:  # label only the lines that end inside the panel
                ax.text(n1, end, " %g" % s, color="0.55", fontsize=7, va="center")
        for seq in sequences:
            pts = sorted(curves[st].get(seq, []))
            if not pts:
                continue
            label = seq
            if (st, seq) in slopes:
                label += " (%.2f)" % slopes[(st, seq)]
            ax.loglog([n for n, _ in pts], [e for _, e in pts], marker="o", ms=2.5, lw=1.1,
                      color=colors[seq], label=label, zorder=2)
        top = max(e for pts in curves[st].values() for _, e in pts)
        if top < ymin:
            ax.text(0.5, 0.5, "RMS below %.0e: rounding\n(zero-variance estimator)" % top,
                    transform=ax.transAxes, ha="center", va="center", fontsize=9)
        ax.set_title(st, fontsize=11)
        ax.set_xscale("log", base=2)
        ax.set_ylim(ymin, ymax)
        ax.grid(True, which="major", color="0.92", lw=0.6)
        ax.legend(fontsize=7, loc="lower left", ncol=2, framealpha=0.8)
        ax.set_xlabel("samples N")
        ax.set_ylabel("RMS error")
    if a.title:
        fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.out, format="png")


if __name__ == "__main__":
    main()
