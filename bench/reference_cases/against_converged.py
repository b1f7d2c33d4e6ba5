#!/usr/bin/env python3
"""The reference cases of config/ at their shipped settings against converged runs (issue 13's aim: within 1e-3 of
converged at default settings; docs/theory.md, "Against the aim of the default tolerance").

One case per call (the machine is shared; each run is one flexmbd_run):

    bench/reference_cases/against_converged.py CASE [--error_tol X] [--joint_floor X] [--dt_max X] [--t_end T]
                                               [--reference_tol X] [--rate_hz X] [--runner PATH] [--cache DIR]
                                               [--drift [--joint NAME]]
                                               [--bands NAME [--window T0 T1] [--at T] [--edges F1,F2,...]]

Runs CASE as shipped (or with solver.error_tol X laid over it) and the converged run of the same files (error_tol
1e-7; 1e-6 for the rotor, the wing with aileron and the rigid antenna, whose runs at 1e-7 take too long on a shared
machine; steps 20 times finer where the case runs on fixed steps; the published antenna's fixed 1e-3 s steps, as in
bench/work_precision), cached under --cache (default /tmp/flexmbd_converged) by the content of the files and
settings: delete it after a change of the code that should move the converged motion. --t_end cuts both runs
short (the rotor's window); --reference_tol sets the converged run's error_tol instead (to check a reference against
one at a tolerance further down); --joint_floor sets solver.error_floor.joint of the run under test only (to see
whether a variable's error follows the floor rather than error_tol), --dt_max its solver.dt_max and dt (the first trial step);
--rate_hz sets output.rate_hz of both runs (the shipped 100 Hz folds a vibration above 50 Hz into low frequencies).
Prints, per joint variable,
the largest difference over the samples relative to the variable's largest converged value ("whole run") and the
difference of the largest values ("peak"), worst first, and how far a chord between the run's step ends strays
from the converged motion ("chord", h^2 |q''| / 8): what linear samples between step ends carried before they were
cubic (docs/theory.md, "Against the aim of the default tolerance"), now a measure of how well the steps resolve the
variable's motion. With --drift, for the worst joint by whole run, the
difference against time in ten windows and its least-squares fit to a phase drift: a run that lags the converged
one by c t differs by -c t v(t) (v the converged joint rate), so c is the relative period error and "explained" the
share of the difference's square sum that the drift accounts for. With --bands, that joint variable's difference over
the window (default the whole run) split into frequency bands (frequency_bands.py; edges in Hz, default 5, 12, 25,
150, 200): the largest of each band's part in eighths of the window, and each part at the instant --at (docs/theory.md,
"What the rotor's strikes leave behind").

Standard library and PyYAML (Debian's python3). The runner defaults to $FLEXMBD_WS/devel/lib/flexmbd/flexmbd_run.
"""

import argparse
import csv
import hashlib
import json
import os
import re
import resource
import subprocess
import sys
import tempfile

import yaml

import frequency_bands

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONFIG = os.path.join(REPO, "config")

# case -> (folder, urdf, yaml, solver keys of the converged run). Fixed-step cases: dt / 20 as their converged run.
CASES = {
    "pendulum_stop": ("pendulum_stop", "pendulum_stop.urdf", "pendulum_stop.yaml", {"dt": 5.0e-5}),
    "double_pendulum": ("double_pendulum", "double_pendulum.urdf", "double_pendulum.yaml", {"error_tol": 1e-7}),
    "blade_drop_9.7": ("blade_drop", "blade_drop.urdf", "release_9.7deg.yaml", {"error_tol": 1e-7}),
    "blade_drop_5.2": ("blade_drop", "blade_drop.urdf", "release_5.2deg.yaml", {"error_tol": 1e-7}),
    "wing_freeplay_lco": ("wing_aileron", "wing_aileron.urdf", "freeplay_lco.yaml", {"error_tol": 1e-6}),
    "wing_freeplay_below": ("wing_aileron", "wing_aileron.urdf", "freeplay_below.yaml", {"error_tol": 1e-6}),
    "rotor_engage": ("rotor_engage", "rotor_engage.urdf", "rotor_engage.yaml", {"error_tol": 1e-6}),
    "antenna_published_0": ("antenna_published", "antenna_published.urdf", "case0.yaml",
                            {"adaptive": False, "dt": 1e-3}),
    "antenna_published_1": ("antenna_published", "antenna_published.urdf", "case1.yaml",
                            {"adaptive": False, "dt": 1e-3, "error_tol": 1e-7}),
    "antenna_dampers": ("antenna", "antenna.urdf", "antenna_dampers.yaml", {"error_tol": 1e-6}),
    "antenna_friction": ("antenna", "antenna.urdf", "antenna_friction.yaml", {"error_tol": 1e-6}),
}


class Run:
    """A run's step counts, CPU seconds, and by sample time its joint positions and rates and the step size."""

    def __init__(self, steps, cpu, times, positions, rates, step_sizes):
        self.steps, self.cpu, self.times, self.positions, self.rates = steps, cpu, times, positions, rates
        self.step_sizes = step_sizes


def run_case(runner, urdf, yaml_path, solver, csv_path, output=None):
    """Runs the case with `solver` (and `output`) laid over the YAML's sections, the CSV to csv_path; returns the
    summary."""
    with open(yaml_path) as f:
        config = yaml.safe_load(f)
    config.setdefault("solver", {}).update(solver)
    config.setdefault("output", {}).update(output or {})
    config["output"]["bag"] = ""
    with tempfile.TemporaryDirectory(prefix="against_converged_") as tmp:
        config_path = os.path.join(tmp, "case.yaml")
        with open(config_path, "w") as f:
            yaml.safe_dump(config, f)
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
        done = subprocess.run([runner, "--urdf", urdf, "--config", config_path, "--csv", csv_path],
                              capture_output=True, text=True)
        cpu = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before
    if done.returncode != 0:
        raise RuntimeError("flexmbd_run failed (%s, %s): %s" % (yaml_path, solver, done.stderr.strip()))
    steps = re.search(r"steps: (\d+) accepted, (\d+) rejected", done.stdout)
    limit = re.search(r"local error limited the step most at ([^;\n]*)", done.stdout)
    return {"accepted": int(steps.group(1)), "rejected": int(steps.group(2)), "cpu": cpu,
            "limited_by": limit.group(1) if limit else "-"}


def read_run(csv_path, summary):
    times, positions, rates, step_sizes = [], {}, {}, []
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            times.append(float(row["t"]))
            step_sizes.append(float(row["solver.dt"]))
            for column, value in row.items():
                if column.startswith("joint.") and column.endswith(".position"):
                    positions.setdefault(column[6:-9], []).append(float(value))
                elif column.startswith("joint.") and column.endswith(".velocity"):
                    rates.setdefault(column[6:-9], []).append(float(value))
    return Run(summary["accepted"], summary.get("cpu", 0.0), times, positions, rates, step_sizes)


def converged_run(runner, case, cache, overrides, output=None):
    """The case's converged run (its solver keys, then `overrides`; `output` laid over its output section), from the
    cache when its files and settings have not changed."""
    folder, urdf, yaml_name, solver = CASES[case]
    solver = dict(solver, **overrides)
    digest = hashlib.sha1(json.dumps([solver, output] if output else solver, sort_keys=True).encode())
    for name in (urdf, yaml_name):
        with open(os.path.join(CONFIG, folder, name), "rb") as f:
            digest.update(f.read())
    stem = os.path.join(cache, "%s-%s" % (case, digest.hexdigest()[:12]))
    if not os.path.exists(stem + ".json"):
        os.makedirs(cache, exist_ok=True)
        summary = run_case(runner, os.path.join(CONFIG, folder, urdf), os.path.join(CONFIG, folder, yaml_name),
                           solver, stem + ".csv", output)
        with open(stem + ".json", "w") as f:
            json.dump(summary, f)
    with open(stem + ".json") as f:
        return read_run(stem + ".csv", json.load(f))


def differences(run, converged):
    """Per joint variable, relative to its largest converged value, on the common samples: the largest difference
    (whole run), the difference of the largest values (peak), and the largest departure of a chord between the run's
    step ends from the motion, h^2 |q''| / 8 (q'' from the converged rates)."""
    index = {round(t, 9): k for k, t in enumerate(converged.times)}
    common = [(k, index[round(t, 9)]) for k, t in enumerate(run.times) if round(t, 9) in index]
    result = {}
    for joint, values in converged.positions.items():
        largest = max(abs(v) for v in values)
        if largest == 0:
            continue
        whole = max(abs(run.positions[joint][k] - values[j]) for k, j in common)
        peak = abs(max(abs(v) for v in run.positions[joint]) - largest)
        rates, times = converged.rates[joint], converged.times
        def acceleration(j):
            return abs(rates[j + 1] - rates[j - 1]) / (times[j + 1] - times[j - 1])

        chord = max(run.step_sizes[k] ** 2 / 8 * acceleration(j) for k, j in common if 0 < j < len(times) - 1)
        result[joint] = (whole / largest, peak / largest, chord / largest, largest)
    return result


def phase_drift(run, converged, joint):
    """The difference against time in ten windows and its fit to -c t v(t): (windows, c, explained share)."""
    index = {round(t, 9): k for k, t in enumerate(converged.times)}
    pairs = [(t, run.positions[joint][k] - converged.positions[joint][index[round(t, 9)]],
              converged.rates[joint][index[round(t, 9)]]) for k, t in enumerate(run.times) if round(t, 9) in index]
    t0, t1 = pairs[0][0], pairs[-1][0]
    windows = []
    for w in range(10):
        lo, hi = t0 + (t1 - t0) * w / 10, t0 + (t1 - t0) * (w + 1) / 10
        inside = [abs(e) for t, e, _ in pairs if lo <= t <= hi]
        windows.append((lo, hi, max(inside) if inside else 0.0))
    basis = [-(t - t0) * v for t, _, v in pairs]
    square = sum(b * b for b in basis)
    c = sum(b * e for b, (_, e, _) in zip(basis, pairs)) / square if square > 0 else 0.0
    total = sum(e * e for _, e, _ in pairs)
    left = sum((e - c * b) ** 2 for b, (_, e, _) in zip(basis, pairs))
    return windows, c, 1.0 - left / total if total > 0 else 0.0


def bands(run, converged, joint, window, at, edges):
    """The joint's difference from the converged run over the window split into frequency bands (frequency_bands.py):
    per eighth of the window the largest of each band's part, and each part at the instant `at` (rad or m)."""
    index = {round(t, 9): k for k, t in enumerate(converged.times)}
    pairs = [(t, run.positions[joint][k] - converged.positions[joint][index[round(t, 9)]])
             for k, t in enumerate(run.times) if window[0] <= t <= window[1] and round(t, 9) in index]
    times = [t for t, _ in pairs]
    _, parts = frequency_bands.band_parts(times, [d for _, d in pairs], edges)
    names = ["%g-%g Hz" % (low, high) for low, high in zip(edges, edges[1:])] + [">%g Hz" % edges[-1]]
    print("%s: difference from the converged run by frequency band (largest in each stretch)" % joint)
    print("  %-17s %s" % ("stretch, s", " ".join("%10s" % name for name in names)))
    for w in range(8):
        lo, hi = window[0] + (window[1] - window[0]) * w / 8, window[0] + (window[1] - window[0]) * (w + 1) / 8
        inside = [k for k, t in enumerate(times) if lo <= t < hi]
        print("  %7.3f - %7.3f %s" % (lo, hi, " ".join("%10.2e" % max(abs(p[k]) for k in inside) for p in parts)))
    if at is not None:
        k = min(range(len(times)), key=lambda k: abs(times[k] - at))
        print("  at %.4f s: %+.3e, %s" % (times[k], pairs[k][1],
                                         ", ".join("%s %+.2e" % (n, p[k]) for n, p in zip(names, parts))))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("case", choices=sorted(CASES))
    parser.add_argument("--error_tol", type=float, help="solver.error_tol laid over the shipped settings")
    parser.add_argument("--joint_floor", type=float, help="solver.error_floor.joint of the run under test")
    parser.add_argument("--dt_max", type=float, help="solver.dt_max of the run under test")
    parser.add_argument("--t_end", type=float, help="solver.t_end of both runs")
    parser.add_argument("--reference_tol", type=float, help="the converged run's error_tol instead of its own")
    parser.add_argument("--runner", default=os.path.join(os.environ.get("FLEXMBD_WS", ""), "devel", "lib",
                                                         "flexmbd", "flexmbd_run"))
    parser.add_argument("--cache", default="/tmp/flexmbd_converged")
    parser.add_argument("--drift", action="store_true", help="the worst joint's difference against time, fitted")
    parser.add_argument("--joint", help="with --drift: this joint variable instead of the worst")
    parser.add_argument("--rate_hz", type=float, help="output.rate_hz of both runs (a fast vibration folds into "
                                                        "low frequencies at the shipped rate)")
    parser.add_argument("--bands", metavar="JOINT", help="this joint variable's difference split into frequency bands")
    parser.add_argument("--window", type=float, nargs=2, metavar=("T0", "T1"), help="with --bands: the stretch")
    parser.add_argument("--at", type=float, help="with --bands: each band's part at this instant")
    parser.add_argument("--edges", default="5,12,25,150,200", help="with --bands: the bands' edges, Hz")
    args = parser.parse_args()
    if not os.path.isfile(args.runner):
        sys.exit("no runner at %s (set FLEXMBD_WS or --runner)" % args.runner)

    folder, urdf, yaml_name, reference = CASES[args.case]
    window = {} if args.t_end is None else {"t_end": args.t_end}
    reference = dict(reference, **window)
    if args.reference_tol is not None:
        reference["error_tol"] = args.reference_tol
    output = {} if args.rate_hz is None else {"rate_hz": args.rate_hz}
    converged = converged_run(args.runner, args.case, args.cache, reference, output)
    solver = dict(window)
    if args.error_tol is not None:
        solver["error_tol"] = args.error_tol
    if args.joint_floor is not None:
        solver["error_floor"] = {"joint": args.joint_floor}
    if args.dt_max is not None:
        solver["dt_max"] = args.dt_max
        solver["dt"] = args.dt_max
    with tempfile.TemporaryDirectory(prefix="against_converged_") as tmp:
        csv_path = os.path.join(tmp, "run.csv")
        summary = run_case(args.runner, os.path.join(CONFIG, folder, urdf), os.path.join(CONFIG, folder, yaml_name),
                           solver, csv_path, output)
        run = read_run(csv_path, summary)
    print("%s %s: %d steps accepted (%d rejected), %.1f s CPU, local error limited the step most at %s; "
          "converged run %s: %d steps" % (args.case, solver or "as shipped", summary["accepted"], summary["rejected"],
                                          summary["cpu"], summary["limited_by"], reference, converged.steps))
    result = differences(run, converged)
    print("%-32s %10s %10s %14s %12s" % ("joint variable", "whole run", "peak", "chord", "largest"))
    for joint, (whole, peak, chord, largest) in sorted(result.items(), key=lambda item: -item[1][0]):
        print("%-32s %10.2e %10.2e %14.2e %12.4g" % (joint, whole, peak, chord, largest))
    if args.drift and result:
        worst = args.joint or max(result, key=lambda joint: result[joint][0])
        windows, c, explained = phase_drift(run, converged, worst)
        print("%s: difference against time (largest in each window, absolute)" % worst)
        for lo, hi, e in windows:
            print("  %8.3f - %8.3f s  %10.3e" % (lo, hi, e))
        print("  phase-drift fit -c t v(t): c = %.3e (relative period error), explained %.1f%%" % (c, 100 * explained))
    if args.bands:
        window = args.window or (run.times[0], run.times[-1])
        bands(run, converged, args.bands, window, args.at, [0.0] + [float(e) for e in args.edges.split(",")])


if __name__ == "__main__":
    main()
