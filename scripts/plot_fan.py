#!/usr/bin/python3
"""Plots a fan-plot table of flexmbd_run (an eigen-analysis sweep written to output.csv or --csv): natural
frequency and damping ratio of each mode against the swept parameter, in two panels sharing the x axis.

The CSV's header is the parameter (`airspeed` [m/s] or `velocity_scale`), then f1_Hz..fN_Hz, then zeta1..zetaN.
--modes 3,4,6 draws only those modes (e.g. the structural ones, leaving out the real roots and the fast damped pair
of aerodynamic states, whose frequencies grow with the airspeed). --mark X draws a vertical line at X (repeatable), e.g. the flutter speed the runner prints
(`flexmbd_run: flutter: mode 2 at U = 23.954 m/s (6.02 Hz)`); --runner-output FILE marks every speed such a line
of a saved runner output names. --per-rev OMEGA (a rotor's fan plot over velocity_scale, OMEGA the hub's initial
rate in rad/s) draws the frequencies as multiples of OMEGA, 2 pi f / OMEGA, with the rays of 1, 2, ... per rev;
--name K=TEXT names mode K in the legend (repeatable).

Usage: plot_fan.py CSV [--out PNG] [--modes K,K,...] [--mark X ...] [--runner-output FILE] [--per-rev OMEGA]
                   [--name K=TEXT ...]   (PNG defaults to CSV with .png)
Prints the path of the PNG written.
"""

import argparse
import math
import os
import re
import sys

from plot_csv import CsvError, plt, read_csv

UNITS = {"airspeed": "airspeed [m/s]", "velocity_scale": "velocity factor"}
# flexmbd_run's line for a change of stability (src/tools/flexmbd_run.cpp, RunAirspeedSweep)
CROSSING = re.compile(r"flexmbd_run: (flutter|divergence|stable again): mode (\d+) at U = (\S+) m/s")


def crossings_in(path):
    """(kind, mode, speed) of every change of stability a saved runner output reports."""
    try:
        with open(path) as handle:
            return [(m.group(1), int(m.group(2)), float(m.group(3))) for m in CROSSING.finditer(handle.read())]
    except OSError as exc:
        raise CsvError("cannot read runner output %s: %s" % (path, exc))


def plot_fan(header, columns, wanted, marks, out_path, per_rev=None, names=None):
    modes = sorted(int(name[1:-3]) for name in header if re.fullmatch(r"f\d+_Hz", name))
    if not modes or any("zeta%d" % k not in header for k in modes):
        raise CsvError("header %s: expected f<k>_Hz and zeta<k> columns for each mode" % ",".join(header))
    missing = [k for k in wanted if k not in modes]
    if missing:
        raise CsvError("--modes: no mode %s in the table (it has modes 1 to %d)"
                       % (",".join(map(str, missing)), modes[-1]))
    modes = wanted or modes
    x = columns[0]
    names = names or {}
    scale = 2 * math.pi / per_rev if per_rev else 1.0
    figure, (upper, lower) = plt.subplots(2, 1, sharex=True, figsize=(8, 7))
    for k in modes:
        label = names.get(k, "mode %d" % k)
        upper.plot(x, [scale * f for f in columns[header.index("f%d_Hz" % k)]], marker="o", markersize=3, label=label)
        lower.plot(x, columns[header.index("zeta%d" % k)], marker="o", markersize=3, label=label)
    if per_rev:
        top = max(scale * f for k in modes for f in columns[header.index("f%d_Hz" % k)])
        for n in range(1, int(math.ceil(top / max(x))) + 1):
            upper.plot([0, max(x)], [0, n * max(x)], color="gray", linewidth=0.6, linestyle=":")
        upper.set_ylim(0, 1.05 * top)
    lower.axhline(0.0, color="black", linewidth=0.8)
    for label, value in marks:
        for axes in (upper, lower):
            axes.axvline(value, color="red", linestyle="--", linewidth=1.0)
        lower.annotate(label, (value, 1.0), xycoords=("data", "axes fraction"), xytext=(4, -14),
                       textcoords="offset points", color="red", fontsize="small")
    upper.set_ylabel("frequency / Omega_0 (rays: 1, 2, ... per rev)" if per_rev else "natural frequency [Hz]")
    lower.set_ylabel("damping ratio")
    xlabel = "rotor speed / Omega_0" if per_rev else UNITS.get(header[0], header[0])
    lower.set_xlabel(xlabel)
    for axes in (upper, lower):
        axes.grid(True, alpha=0.3)
        axes.legend(loc="best", fontsize="small")
    upper.set_title("Frequencies and damping ratios against %s" % xlabel)
    figure.tight_layout()
    try:
        figure.savefig(out_path, dpi=120)
    except OSError as exc:
        raise CsvError("cannot write %s: %s" % (out_path, exc))
    plt.close(figure)


def main(argv):
    parser = argparse.ArgumentParser(description="Plot a flexmbd_run fan-plot table (CSV) to a PNG file.")
    parser.add_argument("csv", help="fan-plot table written by flexmbd_run (output.csv or --csv)")
    parser.add_argument("--out", "-o", help="PNG path (default: the CSV's path with .png)")
    parser.add_argument("--modes", default="", help="comma-separated mode numbers to draw (default: all)")
    parser.add_argument("--mark", type=float, action="append", default=[], help="draw a vertical line here")
    parser.add_argument("--runner-output", help="mark the changes of stability this saved runner output reports")
    parser.add_argument("--per-rev", type=float, help="draw 2 pi f / PER_REV: a rotor's hub rate [rad/s]")
    parser.add_argument("--name", action="append", default=[], help="K=TEXT: the legend's name of mode K")
    args = parser.parse_args(argv[1:])
    out_path = args.out or os.path.splitext(args.csv)[0] + ".png"
    try:
        try:
            wanted = [int(k) for k in args.modes.split(",") if k.strip()]
        except ValueError:
            raise CsvError("--modes %r: expected mode numbers separated by commas, e.g. 3,4,6" % args.modes)
        header, columns = read_csv(args.csv, first=None)
        marks = [("%g" % value, value) for value in args.mark]
        if args.runner_output:
            marks += [("%s, mode %d: %g" % (kind, mode, speed), speed)
                      for kind, mode, speed in crossings_in(args.runner_output)]
        try:
            names = {int(k): text for k, text in (entry.split("=", 1) for entry in args.name)}
        except ValueError:
            raise CsvError("--name %s: expected K=TEXT, e.g. 2=flap" % ",".join(args.name))
        plot_fan(header, columns, wanted, marks, out_path, args.per_rev, names)
    except CsvError as exc:
        print("error: plot_fan.py: %s" % exc, file=sys.stderr)
        return 1
    print(out_path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
