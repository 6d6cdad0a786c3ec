#!/usr/bin/env python3
"""Aggregates K runs of one benchmark program (scripts/bench --processes K): for every target line
of the summary ([id] what  worst X.XXx (config), target <= Lx: ...) and every row of the median
ratio table, the min / median / max over the runs; a target's verdict is the median's. Prints
Markdown tables.

Usage: aggregate.py PROGRAM RUN_OUTPUT...
"""
import re
import statistics
import sys

TARGET = re.compile(r"^\s+\[([^\]]+)\] (.*?)\s+worst\s+([0-9.]+)x \(([^)]+)\), target <= ([0-9.e+]+)x:")
ROW = re.compile(r"^(\S+/\S+)\s+([0-9.]+)\s+([0-9.]+)")


def parse(path):
    targets, rows, in_table = {}, {}, False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("Median ratios"):
                in_table = True
                continue
            if in_table and not line.strip():
                in_table = False
            m = TARGET.match(line)
            if m:
                targets[m.group(1)] = (m.group(2), float(m.group(3)), m.group(4), float(m.group(5)))
                continue
            if in_table:
                r = ROW.match(line)
                if r:
                    rows[r.group(1)] = float(r.group(3))
    return targets, rows


def spread(values):
    return min(values), statistics.median(values), max(values)


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    program, paths = argv[1], argv[2:]
    runs = [parse(p) for p in paths]
    if not any(t or r for t, r in runs):
        # Only bench_maps prints targets and a median-ratio table today.
        print(f"aggregate: {program} prints no targets or ratio table: nothing to aggregate",
              file=sys.stderr)
        return 0
    k = len(runs)
    ids = [i for i in runs[0][0]]
    if ids:
        print(f"\n{program}: targets over {k} processes (worst configuration per process)\n")
        print("| target | limit | min | median | max | worst config (median run) | verdict |")
        print("| --- | --- | --- | --- | --- | --- | --- |")
        for i in ids:
            vals = [t[i][1] for t, _ in runs if i in t]
            what, _, _, limit = runs[0][0][i]
            lo, med, hi = spread(vals)
            at = sorted((t[i][1], t[i][2]) for t, _ in runs if i in t)[len(vals) // 2][1]
            verdict = "met" if med <= limit else "MISSED"
            print(f"| {what} | {limit:g}x | {lo:.2f} | {med:.2f} | {hi:.2f} | {at} | {verdict} |")
    names = sorted(set().union(*(r.keys() for _, r in runs)))
    if names:
        print(f"\n{program}: ratio to the baseline over {k} processes\n")
        print("| benchmark | min | median | max |")
        print("| --- | --- | --- | --- |")
        for n in names:
            lo, med, hi = spread([r[n] for _, r in runs if n in r])
            print(f"| {n} | {lo:.2f} | {med:.2f} | {hi:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
