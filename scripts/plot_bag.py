#!/usr/bin/python3
"""Plots a bag written by flexmbd_node (~bag) or flexmbd_run (--bag): one PNG per group of quantities.

The bag's sample topics (docs/ros.md) are turned into the columns of the runner's CSV (joint.<name>.position,
energy.kinetic, solver.dt, ...) and plotted exactly as plot_csv.py plots a CSV, so both give the same figures:
  <stem>_joint_position.png, <stem>_joint_velocity.png, <stem>_joint_effort.png,
  <stem>_joint_reaction_force.png, <stem>_joint_reaction_moment.png, <stem>_energy.png,
  <stem>_solver_dt.png, <stem>_solver_iterations.png

Usage: plot_bag.py BAG [--out-dir DIR]   (DIR defaults to the bag's folder)
Prints the path of every PNG written. Needs python3-rosbag and python3-matplotlib (no roscore).
"""

import argparse
import os
import sys

import plot_csv  # the CSV plotter beside this file: same grouping, same figures

try:
    import rosbag
except ImportError:  # reported in main, with the package to install
    rosbag = None


class BagError(Exception):
    pass


SAMPLE_TYPES = {
    "joint_states": "sensor_msgs/JointState",
    "energy": "flexmbd/Energy",
    "reactions": "flexmbd/JointReactionArray",
    "solver": "flexmbd/SolverStep",
}
# published only by models with stops, frictional joints, beam stations, aero sections or strip stations
OPTIONAL_TYPES = {
    "contacts": "flexmbd/JointContactArray",
    "friction": "flexmbd/JointFrictionArray",
    "beam_loads": "flexmbd/BeamLoadsArray",  # models with output.beam_stations
    "aero_loads": "flexmbd/AeroLoadsArray",  # models with aero.sections, output.strip_stations or aero.rotors
}
# a beam station's CSV columns beam.<beam>.s<k>.<field>, in the CSV's order
STATION_FIELDS = ("N", "V2", "V3", "T", "M2", "M3", "e1", "g2", "g3", "k1", "k2", "k3")
# the CSV's energy columns, in its order; total = kinetic + potential
ENERGY_FIELDS = ("kinetic", "potential", "total", "external_work", "dissipated", "numerical_dissipation")


def find_sample_topics(bag):
    """Returns {kind: topic} for the sample topics, found by message type (any node name)."""
    found = {}
    for topic, info in bag.get_type_and_topic_info().topics.items():
        for kind, msg_type in list(SAMPLE_TYPES.items()) + list(OPTIONAL_TYPES.items()):
            if info.msg_type == msg_type:
                if kind in found:
                    raise BagError("two %s topics (%s, %s): expected one node's samples"
                                   % (msg_type, found[kind], topic))
                found[kind] = topic
    missing = [SAMPLE_TYPES[kind] for kind in SAMPLE_TYPES if kind not in found]
    if missing:
        raise BagError("no topic of type %s: not a flexmbd bag" % ", ".join(missing))
    return found


def read_columns(path):
    """Returns (header, columns) as plot_csv.read_csv does for the runner's CSV of the same run."""
    if rosbag is None:
        raise BagError("python3-rosbag is not installed (run scripts/install_deps.sh)")
    try:
        bag = rosbag.Bag(path)
    except (OSError, rosbag.ROSBagException) as exc:
        raise BagError("%s: cannot read the bag: %s" % (path, exc))
    with bag:
        topics = find_sample_topics(bag)
        messages = {kind: [m for _, m, _ in bag.read_messages(topics=[topic])] for kind, topic in topics.items()}
    counts = {kind: len(values) for kind, values in messages.items()}
    if len(set(counts.values())) != 1 or counts["joint_states"] == 0:
        raise BagError("%s: the sample topics hold different numbers of messages: %s" % (path, counts))

    columns = {"t": [m.header.stamp.to_sec() for m in messages["joint_states"]]}

    def add(name, value):
        columns.setdefault(name, []).append(value)

    for joint_state in messages["joint_states"]:
        for k, name in enumerate(joint_state.name):
            add("joint.%s.position" % name, joint_state.position[k])
            add("joint.%s.velocity" % name, joint_state.velocity[k])
            add("joint.%s.effort" % name, joint_state.effort[k])
    for reactions in messages["reactions"]:
        for r in reactions.joints:
            for axis in "xyz":
                add("joint.%s.reaction_force_%s" % (r.joint, axis), getattr(r.force, axis))
            for axis in "xyz":
                add("joint.%s.reaction_moment_%s" % (r.joint, axis), getattr(r.moment, axis))
    for contacts in messages.get("contacts", []):
        for c in contacts.contacts:
            for field in ("in_contact", "force", "torque", "approach"):
                add("stop.%s.%s.%s" % (c.joint, c.stop, field), float(getattr(c, field)))
    for friction in messages.get("friction", []):
        for f in friction.joints:
            for field in ("sticking", "torque", "normal_force", "slip_velocity", "work"):
                add("friction.%s.%s" % (f.joint, field), float(getattr(f, field)))
    for loads in messages.get("beam_loads", []):
        for station in loads.stations:
            prefix = "beam.%s.s%d." % (station.beam, station.station)
            for field in STATION_FIELDS:
                add(prefix + field, getattr(station, field))
            for axis in "xyz":
                add(prefix + "u" + axis, getattr(station.displacement, axis))
            for axis in "xyz":
                add(prefix + "r" + axis, getattr(station.rotation, axis))
    for loads in messages.get("aero_loads", []):
        for section in loads.sections:
            prefix = "aero.%s." % section.section
            for field in ("lift", "moment", "hinge_moment"):
                add(prefix + field, getattr(section, field))
            for k, mu in enumerate(section.inflow):
                add(prefix + "mu_%d" % (k + 1), mu)
        for station in loads.strip_stations:
            prefix = "strip.%s.s%d." % (station.strip, station.station)
            for field in ("lift", "moment", "hinge_moment"):
                add(prefix + field, getattr(station, field))
            for k, mu in enumerate(station.inflow):
                add(prefix + "mu_%d" % (k + 1), mu)
        for rotor in loads.rotors:
            add("aero.%s.inflow" % rotor.rotor, rotor.inflow)
            add("aero.%s.thrust" % rotor.rotor, rotor.thrust)
    for energy in messages["energy"]:
        for field in ENERGY_FIELDS:
            add("energy." + field, energy.kinetic + energy.potential if field == "total" else getattr(energy, field))
    for step in messages["solver"]:
        add("solver.dt", step.dt)
        add("solver.iterations", step.iterations)
    header = list(columns)
    return header, [columns[name] for name in header]


def main(argv):
    parser = argparse.ArgumentParser(description="Plot a flexmbd bag to PNG files.")
    parser.add_argument("bag", help="bag written by flexmbd_node (~bag) or flexmbd_run --bag")
    parser.add_argument("--out-dir", "-o", help="folder for the PNG files (default: the bag's folder)")
    args = parser.parse_args(argv[1:])
    try:
        header, columns = read_columns(args.bag)
    except BagError as exc:
        print("error: plot_bag.py: %s" % exc, file=sys.stderr)
        return 1
    out_dir = args.out_dir or os.path.dirname(os.path.abspath(args.bag))
    stem = os.path.splitext(os.path.basename(args.bag))[0]
    try:
        for path in plot_csv.plot_columns(header, columns, out_dir, stem):
            print(path)
    except plot_csv.CsvError as exc:
        print("error: plot_bag.py: %s" % exc, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
