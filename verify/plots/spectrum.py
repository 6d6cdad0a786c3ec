"""Radial power spectra (averaged periodograms) of square sequences, as in Ahmed et al. 2017.

Usage: spectrum.py --out PNG --csv FILE [--title T]
The CSV has sequence,count,seeds,frequency,frequency_over_sqrt_n,power; one curve per sequence,
frequency in units of sqrt(N) (the blue-noise peak of N well-spread points sits near 1), power
normalized so that uniform random points have 1 at every frequency.
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
    ap.add_argument("--title", default="")
    a = ap.parse_args()

    curves = {}
    with open(a.csv, newline="") as f:
        for r in csv.DictReader(f):
            xs, ys = curves.setdefault(r["sequence"], ([], []))
            xs.append(float(r["frequency_over_sqrt_n"]))
            ys.append(float(r["power"]))
    if not curves:
        raise SystemExit("spectrum.py: no rows in " + a.csv)
    fig, ax = plt.subplots(figsize=(7.5, 4.2), dpi=110)
    ax.axhline(1.0, color="0.6", lw=0.8, ls="--", label="uniform random (expected)")
    for name, (xs, ys) in curves.items():
        ax.plot(xs, ys, lw=1.3, label=name)
    ax.set_xlabel("radial frequency / sqrt(N)")
    ax.set_ylabel("power (averaged periodogram)")
    ax.set_xlim(0, max(max(xs) for xs, _ in curves.values()))
    ax.set_ylim(0, None)
    ax.legend(fontsize=9)
    if a.title:
        ax.set_title(a.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out, format="png")


if __name__ == "__main__":
    main()
