"""Relative error of each solid-angle formula vs distance (disklab accuracy).

Usage: accuracy.py --out PNG --csv ROWS.csv [--target 1e-14]
ROWS.csv has id,category,two_sided,distance,formula,value,reference,rel_error (lines starting
with '#' are comments); rows with an empty rel_error (reference 0) are skipped. Log-log, one
marker set per formula; errors below the plot floor are drawn on it.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 1e-19  # errors are computed in long double; exact results (0) are drawn here
STYLE = {
    "production": ("production (R_J, cancellation-free)", "o", "tab:blue"),
    "radial_eq19_printed": ("eq. (19) as printed", "s", "tab:red"),
    "parallel_eq11_printed": ("eq. (11) as printed", "^", "tab:orange"),
    "on_axis_closed_form": ("on-axis closed form", "D", "tab:green"),
    "quadrature_double": ("boundary quadrature (double)", "x", "tab:gray"),
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--target", type=float, default=1e-14)
    a = ap.parse_args()

    series = {}
    with open(a.csv, newline="") as f:
        lines = (line for line in f if not line.startswith("#"))
        for r in csv.DictReader(lines):
            if r["rel_error"] == "":
                continue
            xs, ys = series.setdefault(r["formula"], ([], []))
            xs.append(float(r["distance"]))
            ys.append(max(float(r["rel_error"]), FLOOR))
    if not series:
        raise SystemExit("accuracy.py: no rows with a relative error in " + a.csv)

    fig, ax = plt.subplots(figsize=(8, 5.2), dpi=110)
    for name, (xs, ys) in series.items():
        label, marker, color = STYLE.get(name, (name, ".", None))
        ax.scatter(xs, ys, marker=marker, s=22, label=label, color=color,
                   facecolors="none" if marker in "osD^" else None, linewidths=1.0)
    ax.axhline(1.1e-16, color="black", lw=0.8, ls=":", label="1e-16 (double rounding, eps/2)")
    ax.axhline(a.target, color="tab:blue", lw=0.8, ls="--",
               label="production target %.0e" % a.target)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(FLOOR / 3, 10)
    ax.set_xlabel("distance |o - c| / r (radii)")
    ax.set_ylabel("relative error vs 50-digit reference")
    ax.set_title("Disk solid angle: error of each formula vs distance")
    ax.grid(True, which="major", lw=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(a.out, format="png")


if __name__ == "__main__":
    main()
