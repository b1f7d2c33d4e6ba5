#!/usr/bin/env python3
"""Where a stiff strike's error comes from (issue 13; docs/theory.md, "The wing's strike: the history's error").

Two measurements through flexmbd_run, every step written (rate_hz 0) and read on the steps' cubics (q and qdot at
both ends of each step, as the runner's samples are):

  wing  config/wing_aileron/freeplay_below.yaml to 0.2 s at each error_tol against a run at 3e-7: the aileron's
        crest in its strike on the upper stop (0.158-0.172 s) relative to the converged crest, and the largest
        difference of the hinge angle over each stretch of the history (on a stop / in the gap, as the converged
        run has them).
  disk  the freeplay disk (test/data/urdf/freeplay_disk.urdf) between stiff linear stops (+-2 deg, 2e4 N m/rad)
        driven by a sine moment (2 N m, 3 Hz) for 2 s, against a run at 1e-8: the largest relative error of its
        strikes' crests; alone and beside --idle bodies that never move (one hinge each, nothing acts on them).
        Their entries in the local error norm (T12) are zero, so the difference is the RMS norm's dilution alone.

    bench/strike_history/strike_history.py [wing|disk ...] [--runner PATH] [--idle 50]

The runner defaults to $FLEXMBD_WS/devel/lib/flexmbd/flexmbd_run (default ~/flexmbd_ws). Standard library and
PyYAML (Debian's python3).
"""

import argparse
import bisect
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

import yaml

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WING = os.path.join(REPO, "config", "wing_aileron")
DISK_URDF = os.path.join(REPO, "test", "data", "urdf", "freeplay_disk.urdf")
DISK_YAML = {
    "joints": {"hinge": {"backlash": {"lower_deg": -2.0, "upper_deg": 2.0,
                                      "stop": {"type": "elastic", "law": "linear", "stiffness": 2.0e4}}}},
    "loads": [{"body": "disk", "moment": [0.0, 2.0, 0.0],
               "scale": {"law": "sine", "amplitude": 1.0, "frequency": 3.0}}],
    "solver": {"t_end": 2.0, "gravity": [0.0, 0.0, 0.0]},
}
DISK_INERTIAL = ('<inertial><origin xyz="0 0 0" rpy="0 0 0"/><mass value="1.0"/>'
                 '<inertia ixx="0.25" ixy="0" ixz="0" iyy="0.5" iyz="0" izz="0.25"/></inertial>')


class Steps:
    """A run's step ends of one joint variable, read between them on the cubic through q and qdot at both ends."""

    def __init__(self, rows, joint, accepted):
        self.t = [r["t"] for r in rows]
        self.q = [r["joint.%s.position" % joint] for r in rows]
        self.v = [r["joint.%s.velocity" % joint] for r in rows]
        self.rows, self.accepted = rows, accepted

    def at(self, time):
        i = max(1, min(bisect.bisect_left(self.t, time), len(self.t) - 1))
        h = self.t[i] - self.t[i - 1]
        if h <= 0:
            return self.q[i]
        s = (time - self.t[i - 1]) / h
        return ((2 * s**3 - 3 * s**2 + 1) * self.q[i - 1] + (s**3 - 2 * s**2 + s) * h * self.v[i - 1] +
                (3 * s**2 - 2 * s**3) * self.q[i] + (s**3 - s**2) * h * self.v[i])

    def extreme(self, a, b, sign=1.0, samples=4000):
        return max(sign * self.at(a + (b - a) * k / samples) for k in range(samples + 1)) * sign


def largest_difference(run, reference, a, b, samples=400):
    return max(abs(run.at(x) - reference.at(x)) for x in (a + (b - a) * k / samples for k in range(samples + 1)))


def run_case(runner, urdf, config, joint, solver, tmp, tag):
    config = dict(config, solver=dict(config.get("solver", {}), **solver))
    config["output"] = {"rate_hz": 0, "csv": os.path.join(tmp, tag + ".csv")}
    path = os.path.join(tmp, tag + ".yaml")
    with open(path, "w") as f:
        yaml.safe_dump(config, f)
    done = subprocess.run([runner, "--urdf", urdf, "--config", path], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("flexmbd_run failed (%s): %s" % (tag, done.stderr.strip() or done.stdout[-500:]))
    accepted = int(re.search(r"steps: (\d+) accepted", done.stdout).group(1))
    with open(config["output"]["csv"], newline="") as f:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return Steps(rows, joint, accepted)


def stretches(reference, columns, t_end):
    """[(start, end, 'stop' or 'gap')] of the converged run: on a stop while any of `columns` is in contact."""
    edges, inside = [0.0], [any(reference.rows[0][c] == 1.0 for c in columns)]
    for row in reference.rows[1:]:
        now = any(row[c] == 1.0 for c in columns)
        if now != inside[-1]:
            edges.append(row["t"])
            inside.append(now)
    edges.append(t_end)
    return [(a, b, "stop" if s else "gap") for a, b, s in zip(edges[:-1], edges[1:], inside)]


def wing(runner, tmp):
    with open(os.path.join(WING, "freeplay_below.yaml")) as f:
        config = yaml.safe_load(f)
    urdf, joint, t_end, strike = os.path.join(WING, "wing_aileron.urdf"), "aileron_hinge", 0.2, (0.158, 0.172)
    base = {"t_end": t_end}
    reference = run_case(runner, urdf, config, joint, dict(base, error_tol=3e-7), tmp, "wing_reference")
    crest = reference.extreme(*strike)
    columns = ["stop.aileron_hinge.upper.in_contact", "stop.aileron_hinge.lower.in_contact"]
    parts = [p for p in stretches(reference, columns, t_end) if p[0] < strike[0]]
    print("wing: reference %d steps, crest %.6f rad; history to %.3f s:" % (reference.accepted, crest, strike[0]))
    print("  " + ", ".join("%s %.4f-%.4f" % (kind, a, b) for a, b, kind in parts))
    print("| error_tol | steps to %.1f s | crest | over the strike | history | each stretch of the history |" % t_end)
    print("| --- | --- | --- | --- | --- | --- |")
    for tol in (1e-3, 2e-4, 1e-4, 5e-5, 3e-5, 1e-5, 1e-6):
        run = run_case(runner, urdf, config, joint, dict(base, error_tol=tol), tmp, "wing_%g" % tol)
        each = [largest_difference(run, reference, a, min(b, strike[0])) for a, b, _ in parts]
        print("| %g | %d | %+.2e | %.2e | %.2e | %s |" % (
            tol, run.accepted, run.extreme(*strike) / crest - 1, largest_difference(run, reference, *strike),
            max(each), " ".join("%.1e" % e for e in each)))


def idle_urdf(tmp, count):
    links = ['<link name="world"/>', '<link name="disk">%s</link>' % DISK_INERTIAL,
             '<joint name="hinge" type="continuous"><parent link="world"/><child link="disk"/>'
             '<origin xyz="0 0 0" rpy="0 0 0"/><axis xyz="0 1 0"/></joint>']
    for k in range(count):
        links.append('<link name="idle%d">%s</link>' % (k, DISK_INERTIAL))
        links.append('<joint name="idle_hinge%d" type="continuous"><parent link="world"/><child link="idle%d"/>'
                     '<origin xyz="0 0 0" rpy="0 0 0"/><axis xyz="0 1 0"/></joint>' % (k, k))
    path = os.path.join(tmp, "idle_%d.urdf" % count)
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<robot name="idle">\n%s\n</robot>\n' % "\n".join(links))
    return path


def crests(run):
    """The crest of each excursion beyond the gap, on the cubics between the step ends around it."""
    gap, found, i = math.radians(2.0), [], 0
    while i < len(run.q):
        if abs(run.q[i]) <= gap:
            i += 1
            continue
        j, sign = i, math.copysign(1.0, run.q[i])
        while j < len(run.q) and abs(run.q[j]) > gap:
            j += 1
        found.append(run.extreme(run.t[max(i - 1, 0)], run.t[min(j, len(run.t) - 1)], sign))
        i = j
    return found


def disk(runner, tmp, idle):
    print("| error_tol | disk alone: steps, crests' largest error | beside %d idle bodies |" % idle)
    print("| --- | --- | --- |")
    urdfs = [DISK_URDF, idle_urdf(tmp, idle)]
    references = [crests(run_case(runner, u, DISK_YAML, "hinge", {"error_tol": 1e-8}, tmp, "disk_ref_%d" % k))
                  for k, u in enumerate(urdfs)]
    for tol in (1e-3, 1e-4, 1e-5, 1e-6):
        cells = []
        for k, urdf in enumerate(urdfs):
            run = run_case(runner, urdf, DISK_YAML, "hinge", {"error_tol": tol}, tmp, "disk_%g_%d" % (tol, k))
            found = crests(run)
            if len(found) != len(references[k]):
                sys.exit("disk at %g: %d strikes against the reference's %d" % (tol, len(found), len(references[k])))
            error = max(abs(c / r - 1) for c, r in zip(found, references[k]))
            cells.append("%d, %.2e" % (run.accepted, error))
        print("| %g | %s |" % (tol, " | ".join(cells)))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("cases", nargs="*", default=["wing", "disk"])
    workspace = os.environ.get("FLEXMBD_WS", os.path.expanduser("~/flexmbd_ws"))
    parser.add_argument("--runner", default=os.path.join(workspace, "devel", "lib", "flexmbd", "flexmbd_run"))
    parser.add_argument("--idle", type=int, default=50)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="strike_history_") as tmp:
        for case in args.cases:
            {"wing": lambda: wing(args.runner, tmp), "disk": lambda: disk(args.runner, tmp, args.idle)}[case]()


if __name__ == "__main__":
    main()
