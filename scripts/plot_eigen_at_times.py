#!/usr/bin/python3
"""Plots the mode tables a dynamic run printed at solver.eigen.at_times: frequency against time, one line per
mode index (modes ordered by frequency at each time, so lines that cross swap indices).

Usage: flexmbd_run --urdf U --config C > run.txt; plot_eigen_at_times.py run.txt [--out PNG] [--modes N]
(PNG defaults to run_eigen_at_times.png beside the text). Prints the path of the PNG written.
"""

import argparse
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HEADING = re.compile(r"eigen-analysis at t = (\S+) s")
ROW = re.compile(r"^\s*(\d+)\s+(\S+)")


def read_tables(path):
    """[(t, [frequency_Hz of mode 1, 2, ...])] in the order printed."""
    tables = []
    with open(path) as text:
        for line in text:
            heading = HEADING.search(line)
            if heading:
                tables.append((float(heading.group(1)), []))
                continue
            row = ROW.match(line)
            if tables and row and not line.startswith("flexmbd_run"):
                tables[-1][1].append(float(row.group(2)))
    return tables


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", help="the runner's standard output")
    parser.add_argument("--out", help="PNG to write")
    parser.add_argument("--modes", type=int, default=0, help="modes to plot (0: all printed)")
    args = parser.parse_args()
    tables = read_tables(args.output)
    if not tables:
        sys.exit("plot_eigen_at_times.py: no 'eigen-analysis at t = ...' table in " + args.output)
    count = max(len(frequencies) for _, frequencies in tables)
    if args.modes > 0:
        count = min(count, args.modes)
    figure, axes = plt.subplots(figsize=(7, 4.5))
    for mode in range(count):
        points = [(t, f[mode]) for t, f in tables if mode < len(f)]
        axes.plot([p[0] for p in points], [p[1] for p in points], marker=".", label="mode %d" % (mode + 1))
    axes.set_xlabel("time [s]")
    axes.set_ylabel("frequency [Hz]")
    axes.set_title("Modes about the state of the run")
    axes.grid(True)
    axes.legend()
    out = args.out or os.path.splitext(args.output)[0] + "_eigen_at_times.png"
    figure.tight_layout()
    figure.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
