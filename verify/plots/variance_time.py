"""RMS error against time per shading point: who wins at equal time.

Usage: variance_time.py --out PNG --csv variance.csv --cost variance_cost.csv
One log-log panel per region, one curve per map for each sequence (line style), where the time
of N samples is set-up + N x per-sample cost from the same run (variance_cost.csv).
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLES = ("-", "--", ":", "-.")
# An RMS this small is the estimate's rounding (irradiances here are of order 1), not sampling
# error: a zero-variance map (projected where unoccluded). Its curve would set the axis range
# and squeeze the others, so it is named in a note instead of drawn.
ROUNDING_RMS = 1e-12


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--cost", required=True)
    a = ap.parse_args()
    cost = {}
    with open(a.cost, newline="") as f:
        for r in csv.DictReader(f):
            cost[r["map"]] = (float(r["setup_ns"]), float(r["sample_ns"]))
    curves, regions, maps, seqs = {}, [], [], []
    with open(a.csv, newline="") as f:
        for r in csv.DictReader(f):
            key = (r["region"], r["map"], r["sequence"])
            curves.setdefault(key, []).append((int(r["n"]), float(r["rmse"])))
            for lst, v in ((regions, r["region"]), (maps, r["map"]), (seqs, r["sequence"])):
                if v not in lst:
                    lst.append(v)
    if not curves:
        raise SystemExit("variance_time.py: no rows")
    cmap = plt.get_cmap("tab10")
    fig, axes = plt.subplots(1, len(regions), figsize=(5.2 * len(regions), 4.4), dpi=100,
                             squeeze=False)
    for i, region in enumerate(regions):
        ax = axes[0][i]
        floor = {}  # map -> largest RMS of its curves that sit at the rounding level
        for j, m in enumerate(maps):
            setup, per = cost.get(m, (0.0, 0.0))
            labelled = False
            for k, q in enumerate(seqs):
                pts = sorted(curves.get((region, m, q), []))
                if not pts:
                    continue
                if max(e for _, e in pts) < ROUNDING_RMS:
                    floor[m] = max(floor.get(m, 0.0), max(e for _, e in pts))
                    continue
                t = [(setup + n * per) * 1e-3 for n, _ in pts]
                ax.loglog(t, [e for _, e in pts], color=cmap(j % 10), ls=STYLES[k % len(STYLES)],
                          lw=1.1, label=None if labelled else m)
                labelled = True
        if floor:
            note = "; ".join("%s: zero variance, RMS <= %.0e (rounding), not drawn" % (m, e)
                             for m, e in floor.items())
            ax.text(0.99, 0.99, note, transform=ax.transAxes, ha="right", va="top", fontsize=7,
                    color="0.3")
        ax.set_title(region)
        ax.set_xlabel("time per shading point (microseconds): set-up + N samples")
        ax.set_ylabel("RMS error")
        ax.grid(True, which="major", color="0.92", lw=0.6)
        ax.legend(fontsize=7, loc="lower left")
    fig.suptitle("Equal time: RMS vs cost; line style: " +
                 ", ".join("%s %s" % (q, STYLES[k % len(STYLES)]) for k, q in enumerate(seqs)),
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out, format="png")


if __name__ == "__main__":
    main()
