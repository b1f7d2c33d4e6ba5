#!/usr/bin/python3
"""The published antenna's figures (issue 16, docs/validation.md): its three cases overlaid, from their bags.

  <out>/antenna_published_rotations.png   relative rotations phi_1..phi_4 of B1..B4 [deg]
  <out>/antenna_published_friction.png    friction torques at B2 and B3 (cases 1, 2), sticking intervals as bars
  <out>/antenna_published_moments.png     bending moment at each panel's mid-span station
  <out>/antenna_published_work.png        cumulative work of the drive and energy dissipated

Usage: plot_antenna_published.py CASE0.bag CASE1.bag CASE2.bag [--out-dir DIR]
Bags from flexmbd_run --bag or the node (~bag) of config/antenna_published/case{0,1,2}.yaml; the panels' stations
are the YAMLs' output.beam_stations (mid-span). Needs python3-rosbag and python3-matplotlib (no roscore).
"""

import math
import sys

import plot_overlay  # helpers for figures of several runs overlaid; selects the Agg backend before pyplot loads
import matplotlib.pyplot as plt  # noqa: E402 (after the backend)

import plot_bag  # noqa: E402: the bag reader beside this file, columns named as in the runner's CSV
from flexmbd_sweep.csv_metrics import flag_intervals  # noqa: E402: sticking and contact intervals, as the sweeps'

JOINTS = ("B1", "B2", "B3", "B4")
FRICTION_JOINTS = ("B2", "B3")
PANELS = ("panel_1", "panel_2", "panel_3", "panel_4")
# The deployment turns about y, the axis 2 of the panels' sections: in-plane bending is M2.
IN_PLANE_MOMENT = "M2"
CASE_LABELS = ("case 0 (dampers)", "case 1 (friction)", "case 2 (preloads doubled)")


def column(run, name):
    return plot_overlay.column(run, name, "antenna_published")


def plot_stacked(runs, rows, title, path):
    """One axes per (y label, column name, scale) row, the three cases overlaid on each."""
    figure, axes = plt.subplots(len(rows), 1, figsize=(10, 9), sharex=True)
    for ax, (ylabel, name, scale) in zip(axes, rows):
        for run, label in zip(runs, CASE_LABELS):
            ax.plot(column(run, "t"), [scale * v for v in column(run, name)], label=label, linewidth=0.9)
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
    axes[0].set_title(title)
    axes[0].legend(loc="upper right", fontsize="small")
    axes[-1].set_xlabel("time [s]")
    plot_overlay.save(figure, path)


def plot_rotations(runs, path):
    rows = [("phi_%s [deg]" % joint[1:], "joint.%s.position" % joint, math.degrees(1.0)) for joint in JOINTS]
    plot_stacked(runs, rows, "Relative rotations at the revolute joints", path)


def plot_friction(runs, path):
    figure, axes = plt.subplots(len(FRICTION_JOINTS), 1, figsize=(10, 7), sharex=True)
    friction_runs = list(zip(runs[1:], CASE_LABELS[1:]))
    for ax, joint in zip(axes, FRICTION_JOINTS):
        for k, (run, label) in enumerate(friction_runs):
            time = column(run, "t")
            line, = ax.plot(time, column(run, "friction.%s.torque" % joint), label=label, linewidth=0.8)
            # one row of bars per case along the bottom of the axes
            sticking = flag_intervals(time, column(run, "friction.%s.sticking" % joint))
            plot_overlay.draw_interval_bars(ax, sticking, k, line.get_color())
        ax.set_ylabel("%s friction torque [N m]" % joint)
        ax.grid(True, alpha=0.3)
    axes[0].set_title("Friction torques; bars: sticking intervals (lower row case 1, upper row case 2)")
    axes[0].legend(loc="upper right", fontsize="small")
    axes[-1].set_xlabel("time [s]")
    plot_overlay.save(figure, path)


def plot_moments(runs, path):
    rows = [("%s [N m]" % panel, "beam.%s.s0.%s" % (panel, IN_PLANE_MOMENT), 1.0) for panel in PANELS]
    plot_stacked(runs, rows, "Bending moment at the panels' mid-span (in the deployment plane)", path)


def plot_work(runs, path):
    figure, ax = plt.subplots(figsize=(10, 5))
    for run, label in zip(runs, CASE_LABELS):
        time = column(run, "t")
        line, = ax.plot(time, column(run, "energy.external_work"), label=label + ": work of the drive",
                        linewidth=1.0)
        ax.plot(time, column(run, "energy.dissipated"), linestyle="--", color=line.get_color(),
                label=label + ": dissipated by dampers or friction", linewidth=1.0)
    plot_overlay.finish(figure, ax, "Cumulative work of the drive and of the joint forces", "energy [J]", path, "best")


def main(argv):
    args = plot_overlay.parse_args(argv, "Plot the published antenna's three cases overlaid.", 3, "CASE_BAG",
                                   "bags of case 0, case 1 and case 2, in order")
    try:
        runs, stem = plot_overlay.open_runs(args, "antenna_published_")
        plot_rotations(runs, stem + "rotations.png")
        plot_friction(runs, stem + "friction.png")
        plot_moments(runs, stem + "moments.png")
        plot_work(runs, stem + "work.png")
    except (plot_bag.BagError, OSError) as exc:
        print("error: plot_antenna_published.py: %s" % exc, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
