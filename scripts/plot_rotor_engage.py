#!/usr/bin/python3
"""The rotor engage run-up's figures (issue 18, docs/validation.md), from the bags of the gust run and the
still-air run (config/rotor_engage/rotor_engage.yaml and rotor_engage_no_wind.yaml):

  <out>/rotor_engage_tip.png          blade tip height above the flap hinges' plane [m] (out of plane, up
                                      positive) over the run-up, each blade, one panel per run
  <out>/rotor_engage_tip_bending.png  the tip's bending alone: its height above the line of the blade's root
                                      section through the flap hinge, (R - e) sin(flap) below the tip height
  <out>/rotor_engage_flap.png         flap hinge rotations [deg], each blade, one panel per run; bars along the
                                      bottom: droop-stop contact (solid), flap-stop contact (hatched), one row per
                                      blade
  <out>/rotor_engage_pitch_link.png   axial force at the pitch link's mid-point (blade 0) [N], 2 to 10 s, both
                                      runs overlaid

Usage: plot_rotor_engage.py GUST.bag NO_WIND.bag [--out-dir DIR]
Bags from flexmbd_run --bag or the node (~bag); the cases' stations are the blade tips (s0 of blade_k) and the
pitch links' mid-points (s0 of pitch_link_k). Needs python3-rosbag and python3-matplotlib (no roscore).
"""

import math
import sys

import plot_overlay  # helpers for figures of several runs overlaid; selects the Agg backend before pyplot loads
import matplotlib.pyplot as plt  # noqa: E402 (after the backend)

import plot_bag  # noqa: E402: the bag reader beside this file, columns named as in the runner's CSV
from flexmbd_sweep.csv_metrics import flag_intervals  # noqa: E402: contact intervals, as the sweeps'

LABELS = ("gust", "no wind")
BLADES = 3
# The tip's height above the hinges' plane at the start: the blade (7.47 m from the hinge to the tip, straight
# in the assembled pose) at the droop stop's -0.54 deg; the tip station's uz is measured from there.
HINGE_TO_TIP = 7.47
TIP_START_HEIGHT = -HINGE_TO_TIP * math.sin(math.radians(0.54))
PITCH_LINK_WINDOW = (2.0, 10.0)


def column(run, name):
    return plot_overlay.column(run, name, "rotor_engage")


def tip_height(run, blade):
    return [TIP_START_HEIGHT + uz for uz in column(run, "beam.blade_%d.s0.uz" % blade)]


def tip_bending(run, blade):
    flap = column(run, "joint.flap_%d.position" % blade)
    return [h - HINGE_TO_TIP * math.sin(q) for h, q in zip(tip_height(run, blade), flap)]


def flap_deg(run, blade):
    return [math.degrees(q) for q in column(run, "joint.flap_%d.position" % blade)]


def plot_per_blade(runs, values, ylabel, title, path, with_stops):
    """One panel per run, a curve per blade; with_stops adds the droop (solid) and flap (hatched) contact bars."""
    figure, axes = plt.subplots(len(runs), 1, figsize=(10, 4.0 * len(runs)), sharex=True)
    for ax, run, label in zip(axes, runs, LABELS):
        time = column(run, "t")
        for blade in range(BLADES):
            line, = ax.plot(time, values(run, blade), label="blade %d" % blade, linewidth=0.8)
            if with_stops:
                draw_contacts(ax, time, run, blade, line.get_color())
        ax.set_title("%s: %s" % (label, title))
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right", fontsize="small")
    axes[-1].set_xlabel("time [s]")
    plot_overlay.save(figure, path)


def draw_contacts(ax, time, run, blade, color):
    for stop, hatch in (("lower", None), ("upper", "////")):
        for start, end in flag_intervals(time, column(run, "stop.flap_%d.%s.in_contact" % (blade, stop))):
            ax.axvspan(start, end, ymin=0.02 + 0.05 * blade, ymax=0.06 + 0.05 * blade, color=color,
                       fill=hatch is None, hatch=hatch)


def plot_pitch_link(runs, path):
    figure, ax = plt.subplots(figsize=(10, 4.5))
    begin, end = PITCH_LINK_WINDOW
    for run, label in zip(runs, LABELS):
        pairs = [(t, n) for t, n in zip(column(run, "t"), column(run, "beam.pitch_link_0.s0.N")) if begin <= t <= end]
        ax.plot([t for t, _ in pairs], [n for _, n in pairs], label=label, linewidth=0.8)
    ax.axhline(0.0, color="black", linewidth=0.5)
    plot_overlay.finish(figure, ax, "Axial force at the mid-point of blade 0's pitch link (tension positive)",
                        "axial force [N]", path, "upper right")


def main(argv):
    args = plot_overlay.parse_args(argv, "Plot the rotor engage run-up, gust and still air.", 2, "BAG",
                                   "bags of the gust and the still-air run-up, in order")
    try:
        runs, stem = plot_overlay.open_runs(args, "rotor_engage_")
        plot_per_blade(runs, tip_height, "tip height [m]",
                       "blade tip above the flap hinges' plane (out of plane, up positive)", stem + "tip.png", False)
        plot_per_blade(runs, tip_bending, "tip bending [m]",
                       "blade tip above its root section's line (bending alone, up positive)",
                       stem + "tip_bending.png", False)
        plot_per_blade(runs, flap_deg, "flap [deg]",
                       "flap hinge rotations; bars: droop stop (solid), flap stop (hatched), a row per blade",
                       stem + "flap.png", True)
        plot_pitch_link(runs, stem + "pitch_link.png")
    except (plot_bag.BagError, OSError) as exc:
        print("error: plot_rotor_engage.py: %s" % exc, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
