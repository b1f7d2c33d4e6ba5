"""Helpers of the figures that overlay several runs of one case read from their bags (plot_bag.read_columns):
named columns, bars of the intervals where a 0/1 flag column is set (sticking, contact: flag_intervals of
flexmbd_sweep/csv_metrics.py), and saving."""

import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend)

import plot_bag  # noqa: E402: the bag reader beside this file


def parse_args(argv, description, count, metavar, bags_help):
    """The command line of an overlay script: `count` bags in order, and --out-dir."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("bags", nargs=count, metavar=metavar, help=bags_help)
    parser.add_argument("--out-dir", "-o", default=".", help="folder for the PNG files (default: .)")
    return parser.parse_args(argv[1:])


def open_runs(args, prefix):
    """The runs read from the bags of the command line, and the stem <out-dir>/<prefix> of the PNG files (the
    folder made if missing)."""
    runs = [plot_bag.read_columns(bag) for bag in args.bags]
    os.makedirs(args.out_dir, exist_ok=True)
    return runs, os.path.join(args.out_dir, prefix)


def column(run, name, case):
    """The column `name` of a run (header, columns); `case` names the config folder in the error."""
    header, columns = run
    if name not in header:
        raise plot_bag.BagError("no column %s: not a bag of config/%s/" % (name, case))
    return columns[header.index(name)]


def draw_interval_bars(ax, intervals, row, color):
    """Bars along the bottom of the axes, one row per run (row 0 lowest)."""
    for start, end in intervals:
        ax.axvspan(start, end, ymin=0.02 + 0.05 * row, ymax=0.06 + 0.05 * row, color=color)


def finish(figure, ax, title, ylabel, path, legend_loc):
    """Titles, labels, grid and legend of a figure of one axes over time, then saves it."""
    ax.set_title(title)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(loc=legend_loc, fontsize="small")
    save(figure, path)


def save(figure, path, dpi=110):
    figure.tight_layout()
    figure.savefig(path, dpi=dpi)
    plt.close(figure)
    print(path)
