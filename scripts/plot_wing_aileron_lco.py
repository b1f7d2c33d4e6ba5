#!/usr/bin/python3
"""The wing with aileron's lowest limit-cycle airspeed against freeplay (issue 17 case 2, docs/validation.md):
U_LCO / U_F for each root angle of attack, from the brackets measured by flexmbd_run runs.

The CSV (config/wing_aileron/lco_onset.csv) has one row per (root angle of attack, freeplay): `aoa_deg`,
`freeplay_deg` (the stops at +-freeplay), `u_decays` (the highest airspeed whose motion decayed) and `u_sustains`
(the lowest airspeed whose cycle was sustained) [m/s], `u_flutter` (that angle's flutter speed without freeplay
[m/s]). Each point is the bracket's middle, its bar the bracket. --float-deg draws the flap's floating angle (the
free flap's static deflection at the angle of attack given by --float-aoa), beyond which a freeplay leaves the
flap off its stops.

Usage: plot_wing_aileron_lco.py CSV [--out PNG] [--float-deg X --float-aoa A]
       (PNG defaults to docs/figures/wing_aileron_ulco_vs_freeplay.png). Needs python3-matplotlib.
"""

import argparse
import os
import sys

from matplotlib.ticker import ScalarFormatter

from plot_csv import CsvError, plt, read_csv  # the runner CSVs' reader beside this file; selects the Agg backend

COLUMNS = ("aoa_deg", "freeplay_deg", "u_decays", "u_sustains", "u_flutter")
DEFAULT_OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "figures",
                           "wing_aileron_ulco_vs_freeplay.png")


def read_rows(path):
    """The CSV's rows as dicts of floats, grouped by angle of attack (in file order)."""
    header, columns = read_csv(path, first=(COLUMNS[0], "the root angle of attack [deg]"))
    missing = [name for name in COLUMNS if name not in header]
    if missing:
        raise CsvError(f"{path}: header: missing column(s) {', '.join(missing)}; expected {', '.join(COLUMNS)}")
    groups = {}
    for values in zip(*(columns[header.index(name)] for name in COLUMNS)):
        row = dict(zip(COLUMNS, values))
        groups.setdefault(row["aoa_deg"], []).append(row)
    return groups


def plot(groups, out, float_deg, float_aoa):
    figure, ax = plt.subplots(figsize=(7, 4.5))
    for aoa, rows in groups.items():
        rows.sort(key=lambda r: r["freeplay_deg"])
        gap = [r["freeplay_deg"] for r in rows]
        low = [r["u_decays"] / r["u_flutter"] for r in rows]
        high = [r["u_sustains"] / r["u_flutter"] for r in rows]
        middle = [(a + b) / 2 for a, b in zip(low, high)]
        ax.errorbar(gap, middle, yerr=[[m - a for m, a in zip(middle, low)], [b - m for m, b in zip(middle, high)]],
                    marker="o", linestyle="none", capsize=4, label=f"root angle of attack {aoa:g} deg")
    if float_deg is not None:
        ax.axvline(float_deg, color="grey", linestyle="--", linewidth=1.0,
                   label=f"free flap's floating angle at {float_aoa:g} deg")
    ax.set_xscale("log")
    ax.set_xticks(sorted({r["freeplay_deg"] for rows in groups.values() for r in rows}))
    ax.get_xaxis().set_major_formatter(ScalarFormatter())
    ax.set_xlabel("freeplay +- [deg]")
    ax.set_ylabel("U_LCO / U_F")
    ax.set_ylim(0.0, 1.1)
    ax.set_title("Wing with aileron: lowest limit-cycle airspeed over flutter speed")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower left")
    figure.tight_layout()
    figure.savefig(out, dpi=120)
    return out


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv")
    parser.add_argument("--out", default=DEFAULT_OUT)
    parser.add_argument("--float-deg", type=float)
    parser.add_argument("--float-aoa", type=float, default=5.0)
    args = parser.parse_args(argv)
    try:
        print(plot(read_rows(args.csv), args.out, args.float_deg, args.float_aoa))
    except (OSError, CsvError) as error:
        print(f"error: plot_wing_aileron_lco.py: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
