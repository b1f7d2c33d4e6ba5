#!/usr/bin/python3
"""The wing with aileron's freeplay runs (issue 17 case 2, docs/validation.md): both airspeeds overlaid, from
their bags, with the intervals on a hinge stop as bars along the bottom of each plot (lower row: the first bag).

  <out>/wing_aileron_tip_displacement.png   wing tip's vertical displacement [m]
  <out>/wing_aileron_tip_rotation.png       wing tip's twist, nose up [deg]
  <out>/wing_aileron_flap.png               flap angle (the aileron hinge's rotation) [deg]
  <out>/wing_aileron_bending.png            flapwise bending moment at mid-span [N m]
  <out>/wing_aileron_torsion.png            torque at mid-span [N m]
  <out>/wing_aileron_contact.png            hinge stops' contact force, upper plus lower [N]

Usage: plot_wing_aileron.py BELOW.bag NEAR.bag [--out-dir DIR]
Bags from flexmbd_run --bag or the node (~bag) of config/wing_aileron/freeplay_below.yaml and
freeplay_near.yaml, whose wing stations are mid-span (s0) and the tip (s1). Needs python3-rosbag and
python3-matplotlib (no roscore).
"""

import math
import sys

import plot_overlay  # helpers for figures of several runs overlaid; selects the Agg backend before pyplot loads
import matplotlib.pyplot as plt  # noqa: E402 (after the backend)

import plot_bag  # noqa: E402: the bag reader beside this file, columns named as in the runner's CSV
from flexmbd_sweep.csv_metrics import flag_intervals  # noqa: E402: contact intervals, as the sweeps'

LABELS = ("0.946 U_F (published: 530 ft/s, decays)", "0.991 U_F (published: 555 ft/s, limit cycle)")
STOPS = ("stop.aileron_hinge.lower", "stop.aileron_hinge.upper")


def column(run, name):
    return plot_overlay.column(run, name, "wing_aileron")


def on_a_stop(run):
    """1 where the hinge rests on either stop."""
    return [max(lower, upper) for lower, upper in
            zip(column(run, STOPS[0] + ".in_contact"), column(run, STOPS[1] + ".in_contact"))]


def in_degrees(name):
    """run -> the column `name` in degrees."""
    return lambda run: [math.degrees(v) for v in column(run, name)]


def plot_overlaid(runs, ylabel, values, title, path):
    """values(run) -> the curve of one run; both runs overlaid with their contact bars."""
    figure, ax = plt.subplots(figsize=(10, 4.5))
    for row, (run, label) in enumerate(zip(runs, LABELS)):
        time = column(run, "t")
        line, = ax.plot(time, values(run), label=label, linewidth=1.0)
        plot_overlay.draw_interval_bars(ax, flag_intervals(time, on_a_stop(run)), row, line.get_color())
    plot_overlay.finish(figure, ax, title, ylabel, path, "upper right")


def main(argv):
    args = plot_overlay.parse_args(argv, "Plot the wing with aileron's freeplay runs, both speeds overlaid.", 2,
                                   "BAG", "bags of freeplay_below.yaml and freeplay_near.yaml, in order")
    bars = "; bars: on a hinge stop"
    try:
        runs, stem = plot_overlay.open_runs(args, "wing_aileron_")
        plot_overlaid(runs, "tip displacement [m]", lambda run: column(run, "beam.wing.s1.uz"),
                      "Wing tip displacement (up)" + bars, stem + "tip_displacement.png")
        # The wing turns nose up about -x (wing_aileron.urdf); the station's rotation is from the root's 5 deg.
        plot_overlaid(runs, "tip twist [deg]", lambda run: [-math.degrees(r) for r in column(run, "beam.wing.s1.rx")],
                      "Wing tip rotation (twist, nose up, from the rigid root's angle)" + bars,
                      stem + "tip_rotation.png")
        plot_overlaid(runs, "flap angle [deg]", in_degrees("joint.aileron_hinge.position"),
                      "Flap motion (aileron hinge; stops at +-0.5 deg)" + bars, stem + "flap.png")
        plot_overlaid(runs, "bending moment M2 [N m]", lambda run: column(run, "beam.wing.s0.M2"),
                      "Flapwise bending moment at mid-span" + bars, stem + "bending.png")
        plot_overlaid(runs, "torque T [N m]", lambda run: column(run, "beam.wing.s0.T"),
                      "Torsion moment at mid-span" + bars, stem + "torsion.png")
        plot_overlaid(runs, "contact force [N]",
                      lambda run: [lower + upper for lower, upper in
                                   zip(column(run, STOPS[0] + ".force"), column(run, STOPS[1] + ".force"))],
                      "Hinge stops' contact force (at 0.8 in radius)" + bars, stem + "contact.png")
    except (plot_bag.BagError, OSError, KeyError) as exc:
        print("error: plot_wing_aileron.py: %s" % exc, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
