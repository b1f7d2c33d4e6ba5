#!/usr/bin/python3
"""Plots a flexmbd CSV output file: one PNG per group of columns.

The CSV's first row is a header and its first column is `t` (time, s). Columns are grouped by name:
  joint.<name>.position  -> <stem>_joint_position.png   (position [rad or m])
  joint.<name>.velocity  -> <stem>_joint_velocity.png   (velocity [rad/s or m/s])
  joint.<name>.effort    -> <stem>_joint_effort.png     (effort [N m or N])
  joint.<name>.reaction_force_<x|y|z> -> <stem>_joint_reaction_force.png (force [N])
  joint.<name>.reaction_moment_<x|y|z> -> <stem>_joint_reaction_moment.png (moment [N m])
  joint.<name>.<other>   -> <stem>_joint_<other>.png
  stop.<joint>.<stop>.<q> -> <stem>_stop_<q>.png      (in_contact, force [N], torque, approach [m])
  friction.<joint>.<q>   -> <stem>_friction_<q>.png     (sticking, torque, normal_force [N], slip_velocity, work)
  aero.<section>.<load>  -> <stem>_aero_<load>.png      (lift [N], moment, hinge_moment [N m])
  aero.<section>.mu_<k>  -> <stem>_aero_inflow.png      (Peters' inflow states [m/s])
  strip.<strip>.s<k>.<load> -> <stem>_strip_<load>.png  (per unit span: lift [N/m], moment, hinge_moment [N m/m])
  strip.<strip>.s<k>.mu_<i> -> <stem>_strip_inflow.png  (Peters' inflow states at the strip stations [m/s])
  energy.<kind>          -> <stem>_energy.png           (energy [J])
  solver.dt              -> <stem>_solver_dt.png        (step size [s], log scale)
  solver.iterations      -> <stem>_solver_iterations.png (Newton iterations per step)
  solver.<other>         -> <stem>_solver_<other>.png
  <prefix>.<rest>        -> <stem>_<prefix>.png (any other column, grouped by its first component)

Usage: plot_csv.py CSV [--out-dir DIR]   (DIR defaults to the CSV's folder)
Prints the path of every PNG written.
"""

import argparse
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)


class CsvError(Exception):
    pass


# group key -> (title, y label, log scale)
KNOWN_GROUPS = {
    "joint_position": ("Joint positions", "position [rad or m]", False),
    "joint_velocity": ("Joint velocities", "velocity [rad/s or m/s]", False),
    "joint_effort": ("Joint efforts", "effort [N m or N]", False),
    "joint_reaction_force": ("Joint reaction forces (on the child, world frame)", "force [N]", False),
    "joint_reaction_moment": ("Joint reaction moments (on the child)", "moment [N m]", False),
    "stop_in_contact": ("Stops in contact", "in contact (1) or open (0)", False),
    "stop_force": ("Stop contact forces", "force [N]", False),
    "stop_torque": ("Stop forces on the joint variables", "torque [N m or N]", False),
    "stop_approach": ("Stop approaches (elastic stops)", "approach [m]", False),
    "friction_sticking": ("Joints sticking", "sticking (1) or sliding (0)", False),
    "friction_torque": ("Friction forces on the joint variables", "torque [N m or N]", False),
    "friction_normal_force": ("Friction normal forces", "force [N]", False),
    "friction_slip_velocity": ("Slip velocities at the races", "velocity [m/s]", False),
    "friction_work": ("Energy dissipated by friction", "energy [J]", False),
    "aero_lift": ("Aero section lift (up)", "lift [N]", False),
    "aero_moment": ("Aero section moment about the elastic axis (nose up)", "moment [N m]", False),
    "aero_hinge_moment": ("Aero section hinge moment (trailing edge down)", "moment [N m]", False),
    "aero_inflow": ("Aero section inflow states", "mu [m/s]", False),
    "strip_lift": ("Strip lift per unit span (along the chord normal)", "lift [N/m]", False),
    "strip_moment": ("Strip moment per unit span about the elastic axis (nose up)", "moment [N m/m]", False),
    "strip_hinge_moment": ("Strip hinge moment per unit span (trailing edge down)", "moment [N m/m]", False),
    "strip_inflow": ("Strip inflow states", "mu [m/s]", False),
    "energy": ("Energy", "energy [J]", False),
    "solver_dt": ("Solver step size", "step size [s]", True),
    "solver_iterations": ("Newton iterations per step", "iterations", False),
}


def read_csv(path, first=("t", "time, s")):
    """Returns (header, columns) where columns[i] is the list of floats of header[i]; the first column must be
    named first[0] (first[1] says what it is), or anything if first is None."""
    if not os.path.exists(path):
        raise CsvError("%s: no such file" % path)
    if not os.path.isfile(path):
        raise CsvError("%s: not a regular file" % path)
    try:
        with open(path, newline="") as handle:
            rows = list(csv.reader(handle))
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise CsvError("%s: cannot read: %s" % (path, exc))
    # (line number, fields) of the non-blank lines
    rows = [(number, row) for number, row in enumerate(rows, start=1)
            if row and any(cell.strip() for cell in row)]
    if not rows:
        raise CsvError("%s: empty file (expected a header row)" % path)
    header = [name.strip() for name in rows[0][1]]
    if first and header[0] != first[0]:
        raise CsvError("%s: header: first column is %r, expected '%s' (%s)" % (path, header[0], first[0], first[1]))
    if len(header) < 2:
        raise CsvError("%s: header: only a '%s' column, nothing to plot" % (path, header[0]))
    empty = [i + 1 for i, name in enumerate(header) if not name]
    if empty:
        raise CsvError("%s: header: empty column name in column(s) %s" % (path, empty))
    duplicates = sorted({name for name in header if header.count(name) > 1})
    if duplicates:
        raise CsvError("%s: header: duplicate column name(s) %s" % (path, ", ".join(duplicates)))
    if len(rows) < 2:
        raise CsvError("%s: header only, no data rows" % path)
    columns = [[] for _ in header]
    for line_number, row in rows[1:]:
        if len(row) != len(header):
            raise CsvError("%s: line %d: %d fields, the header has %d"
                           % (path, line_number, len(row), len(header)))
        for index, cell in enumerate(row):
            try:
                columns[index].append(float(cell))
            except ValueError:
                raise CsvError("%s: line %d: column '%s': %r is not a number"
                               % (path, line_number, header[index], cell))
    return header, columns


def group_key(name):
    """Returns (group key, legend label) for a column name."""
    parts = name.split(".")
    if parts[0] == "joint" and len(parts) >= 3:
        joint, quantity = ".".join(parts[1:-1]), parts[-1]
        component = re.fullmatch(r"(.+)_([xyz])", quantity)
        if component:  # joint.<name>.reaction_force_x -> one plot for all components
            return "joint_" + component.group(1), "%s %s" % (joint, component.group(2))
        return "joint_" + quantity, joint
    if parts[0] in ("stop", "friction") and len(parts) >= 3:  # one plot per quantity, a line per stop or joint
        return parts[0] + "_" + parts[-1], ".".join(parts[1:-1])
    if parts[0] == "beam" and len(parts) >= 4:  # beam.<beam>.s<k>.<quantity>: one plot per quantity
        return "beam_" + parts[-1], ".".join(parts[1:-1])
    if parts[0] in ("aero", "strip") and len(parts) >= 3:  # one plot per load, one for all inflow states
        if re.fullmatch(r"mu_\d+", parts[-1]):
            return parts[0] + "_inflow", ".".join(parts[1:])
        return parts[0] + "_" + parts[-1], ".".join(parts[1:-1])
    if parts[0] == "energy" and len(parts) >= 2:
        return "energy", ".".join(parts[1:])
    if parts[0] == "solver" and len(parts) >= 2:
        return "solver_" + "_".join(parts[1:]), ".".join(parts[1:])
    if len(parts) >= 2:
        return parts[0], ".".join(parts[1:])
    return name, name


def safe_file_part(text):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text)


def plot_group(time, series, key, out_path):
    title, ylabel, log_scale = KNOWN_GROUPS.get(key, (key.replace("_", " "), key.replace("_", " "), False))
    figure, axes = plt.subplots(figsize=(10, 5.5))
    for label, values in series:
        axes.plot(time, values, label=label, linewidth=1.0)
    if log_scale and all(v > 0 for _, values in series for v in values if math.isfinite(v)):
        axes.set_yscale("log")
    axes.set_title(title)
    axes.set_xlabel("time [s]")
    axes.set_ylabel(ylabel)
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best", fontsize="small", ncol=max(1, len(series) // 12))
    figure.tight_layout()
    figure.savefig(out_path, dpi=120)
    plt.close(figure)


def plot_columns(header, columns, out_dir, stem):
    """Plots columns named as in the CSV (header[0] is 't') to <out_dir>/<stem>_<group>.png; returns the paths.

    Shared with plot_bag.py, which turns a bag into the same columns. Raises CsvError if a file cannot be
    written."""
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as exc:
        raise CsvError("cannot create output folder %s: %s" % (out_dir, exc))
    groups = {}
    for name, values in zip(header[1:], columns[1:]):
        key, label = group_key(name)
        groups.setdefault(key, []).append((label, values))
    paths = []
    for key, series in groups.items():
        out_path = os.path.join(out_dir, "%s_%s.png" % (stem, safe_file_part(key)))
        try:
            plot_group(columns[0], series, key, out_path)
        except OSError as exc:
            raise CsvError("cannot write %s: %s" % (out_path, exc))
        paths.append(out_path)
    return paths


def main(argv):
    parser = argparse.ArgumentParser(description="Plot a flexmbd CSV output file to PNG files.")
    parser.add_argument("csv", help="CSV file written by flexmbd_run --csv")
    parser.add_argument("--out-dir", "-o", help="folder for the PNG files (default: the CSV's folder)")
    args = parser.parse_args(argv[1:])

    out_dir = args.out_dir or os.path.dirname(os.path.abspath(args.csv))
    stem = os.path.splitext(os.path.basename(args.csv))[0]
    try:
        header, columns = read_csv(args.csv)
        for path in plot_columns(header, columns, out_dir, stem):
            print(path)
    except CsvError as exc:
        print("error: plot_csv.py: %s" % exc, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
