#!/usr/bin/python3
"""The blade droop-stop drop test's figures (issue 16, docs/validation.md): both release angles overlaid, from
their bags, with the droop stop's contact intervals as bars along the bottom of each plot (lower row: the first
bag).

  <out>/blade_drop_tip.png      tip deflection over blade length: the tip's distance below the line of the
                                root section (the hinge's angle), positive down, over L
  <out>/blade_drop_hinge.png    hinge rotation (flap angle, tip up positive) [deg]
  <out>/blade_drop_strain.png   bending strain (curvature k2) at x/L = 0.40 [1/m], positive when sagging

Usage: plot_blade_drop.py RELEASE_9.7.bag RELEASE_5.2.bag [--out-dir DIR]
Bags from flexmbd_run --bag or the node (~bag) of config/blade_drop/release_{9.7,5.2}deg.yaml, whose stations
are x/L = 0.40 (s0) and the tip (s1). Needs python3-rosbag and python3-matplotlib (no roscore).
"""

import math
import os
import sys

import plot_overlay  # helpers for figures of several runs overlaid; selects the Agg backend before pyplot loads
import matplotlib.pyplot as plt  # noqa: E402 (after the backend)

import plot_bag  # noqa: E402: the bag reader beside this file, columns named as in the runner's CSV
from flexmbd_sweep.csv_metrics import flag_intervals  # noqa: E402: sticking and contact intervals, as the sweeps'
import yaml  # noqa: E402

BLADE_YAML = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "config", "blade_drop",
                          "release_9.7deg.yaml")

LABELS = ("released at 9.7 deg", "released at 5.2 deg")
CONTACT = "stop.hinge.lower.in_contact"


def column(run, name):
    return plot_overlay.column(run, name, "blade_drop")


def blade_length():
    """The blade's length from its YAML (both release files share the blade) [m]."""
    with open(BLADE_YAML) as stream:
        return float(yaml.safe_load(stream)["beams"]["blade"]["length"])


def tip_deflection_over_length(run, length):
    """Tip below the line of the root section, over L. The station displacement u is from the straight blade at
    the release angle q0 (where the static analysis starts), so the tip is at L (cos q0, sin q0) + (ux, uz) in
    the x-z plane, and its distance below the root line at angle q is L sin(q - q0) + ux sin(q) - uz cos(q)."""
    angles = column(run, "joint.hinge.position")
    q0 = angles[0]
    return [(length * math.sin(q - q0) + ux * math.sin(q) - uz * math.cos(q)) / length
            for q, ux, uz in zip(angles, column(run, "beam.blade.s1.ux"), column(run, "beam.blade.s1.uz"))]


def plot_overlaid(runs, ylabel, values, title, path):
    """values(run) -> the curve of one run; both runs overlaid with their contact bars."""
    figure, ax = plt.subplots(figsize=(10, 4.5))
    for row, (run, label) in enumerate(zip(runs, LABELS)):
        time = column(run, "t")
        line, = ax.plot(time, values(run), label=label, linewidth=1.0)
        plot_overlay.draw_interval_bars(ax, flag_intervals(time, column(run, CONTACT)), row,
                                        line.get_color())
    ax.axhline(0.0, color="black", linewidth=0.5)
    plot_overlay.finish(figure, ax, title, ylabel, path, "upper right")


def main(argv):
    args = plot_overlay.parse_args(argv, "Plot the blade drop test, both release angles overlaid.", 2, "BAG",
                                   "bags of the 9.7 deg and the 5.2 deg release, in order")
    try:
        runs, stem = plot_overlay.open_runs(args, "blade_drop_")
        length = blade_length()
        plot_overlaid(runs, "tip deflection / L", lambda run: tip_deflection_over_length(run, length),
                      "Tip deflection over blade length (below the root section's line); bars: on the droop stop",
                      stem + "tip.png")
        plot_overlaid(runs, "hinge rotation [deg]",
                      lambda run: [math.degrees(q) for q in column(run, "joint.hinge.position")],
                      "Hinge rotation (flap angle; droop stop at 0 deg); bars: on the droop stop", stem + "hinge.png")
        plot_overlaid(runs, "bending strain k2 [1/m]", lambda run: column(run, "beam.blade.s0.k2"),
                      "Bending strain (curvature) at x/L = 0.40, positive sagging; bars: on the droop stop",
                      stem + "strain.png")
    except (plot_bag.BagError, OSError, KeyError, yaml.YAMLError) as exc:
        print("error: plot_blade_drop.py: %s" % exc, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
