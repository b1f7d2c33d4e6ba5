#!/usr/bin/python3
"""The figures docs/validation.md quotes from a rotor engage run-up (config/rotor_engage/rotor_engage.yaml or
rotor_engage_no_wind.yaml), read from its bag: per blade the droop- and flap-stop contacts (count, first start,
last end), the largest tip excursions in the first 6 s and after, the pitch link's axial force between 2 and 10 s
against the last 2 s, and the rotor's thrust over a window (--thrust-window A B, default the last 2 s) against
the blade-element estimate at the mean Omega^2 of that window.

Thrust: the share of the machine's weight the rotor carries, i.e. the vertical reaction of the joints to the world
(rotor_drive under the shaft, collective under the slider) at the start (static, at rest) less their mean over
the window. The blade-element estimates for blades of chord c from r0 to R at pitch theta_0, lift slope a = 2 pi:
without inflow T = N rho a c Omega^2 theta_0 (R^3 - r0^3) / 6, and with the rotor's uniform inflow (aero.rotors)
the hover momentum balance 2 rho A nu^2 = T(nu) closed with the strips' own thrust (docs/theory.md (A13): a
quadratic in nu); docs/validation.md says what separates them from the run.

--until T reads the run only up to T s (e.g. before an instability).

Usage: rotor_engage_measures.py BAG [BAG ...] [--thrust-window A B] [--until T]   Needs python3-rosbag (no roscore).
"""

import argparse
import math

import sys

import plot_bag  # the bag reader beside this file, columns named as in the runner's CSV
from flexmbd_sweep.csv_metrics import flag_intervals  # contact intervals, as the sweeps'
from plot_rotor_engage import BLADES, PITCH_LINK_WINDOW, column, tip_bending, tip_height  # the figures' quantities

EARLY = 6.0  # s: the published largest tip deflections fall in the first 6 s
LAST = 2.0  # s at the end (full speed, 8.8 revolutions) for the full-speed loads and the thrust
GROUND_JOINTS = ("rotor_drive", "collective")
# The blade data of the YAML header: rho [kg/m^3], chord [m], root and tip radii [m], Omega_0 [rad/s], theta_0.
RHO, CHORD, ROOT, TIP, OMEGA0, THETA0 = 1.225, 0.47, 0.65, 7.77, 27.61, math.radians(3.0)


def hover_thrust_with_inflow(omega):
    """The strips' hover thrust [N] with the uniform inflow of docs/theory.md (A13): untwisted quasi-steady strips
    at theta_0, T(nu) = K [Omega^2 s c I2 - Omega nu (c^2 - s^2) I1 - nu^2 s c I0] = 2 rho A nu^2."""
    s, c = math.sin(THETA0), math.cos(THETA0)
    i0, i1, i2 = TIP - ROOT, (TIP ** 2 - ROOT ** 2) / 2, (TIP ** 3 - ROOT ** 3) / 3
    k = 2 * math.pi * RHO * (CHORD / 2) * BLADES * c
    area = math.pi * TIP ** 2
    a, b, free = 2 * RHO * area + k * s * c * i0, k * omega * (s * s - c * c) * i1, k * omega ** 2 * s * c * i2
    nu = (b + math.sqrt(b * b + 4 * a * free)) / (2 * a)
    return 2 * RHO * area * nu * nu


def mean_over(time, values, begin, end):
    chosen = [v for t, v in zip(time, values) if begin <= t <= end]
    return sum(chosen) / len(chosen)


def up_to(run, until):
    """The run's samples at t <= until."""
    header, columns = run
    kept = sum(1 for t in columns[header.index("t")] if t <= until)
    return header, [values[:kept] for values in columns]


def print_early_and_late(label, time, values):
    """Prints the range of `values` [m] up to EARLY s and after it."""
    early = [v for t, v in zip(time, values) if t <= EARLY]
    late = [v for t, v in zip(time, values) if t > EARLY]
    print("  %s: %.4f to %.4f m in the first %g s, %.4f to %.4f m after" %
          (label, min(early), max(early), EARLY, min(late) if late else float("nan"),
           max(late) if late else float("nan")))


def report(path, thrust_window, until):
    run = up_to(plot_bag.read_columns(path), until)
    time = column(run, "t")
    end = time[-1]
    print("%s: t = 0 to %g s, rotor speed at the end %.4g rad/s" % (path, end, column(run, "joint.rotor_drive.velocity")[-1]))
    for blade in range(BLADES):
        for stop in ("lower", "upper"):
            intervals = flag_intervals(time, column(run, "stop.flap_%d.%s.in_contact" % (blade, stop)))
            span = " from %.3f to %.3f s" % (intervals[0][0], intervals[-1][1]) if intervals else ""
            print("  blade %d %s stop: %d contact interval(s)%s" % (blade, "droop" if stop == "lower" else "flap",
                                                                    len(intervals), span))
        print_early_and_late("blade %d tip height" % blade, time, tip_height(run, blade))
        print_early_and_late("blade %d tip bending" % blade, time, tip_bending(run, blade))
        flap = column(run, "joint.flap_%d.position" % blade)
        print("  blade %d flap: %.3f to %.3f deg, %.3f deg at the end" %
              (blade, math.degrees(min(flap)), math.degrees(max(flap)), math.degrees(flap[-1])))
    for blade in range(BLADES):
        axial = column(run, "beam.pitch_link_%d.s0.N" % blade)
        window = [n for t, n in zip(time, axial) if PITCH_LINK_WINDOW[0] <= t <= PITCH_LINK_WINDOW[1]]
        last = [n for t, n in zip(time, axial) if t >= end - LAST]
        print("  pitch link %d axial force: %.0f to %.0f N in [%g, %g] s; %.0f to %.0f N in the last %g s" %
              (blade, min(window), max(window), PITCH_LINK_WINDOW[0], PITCH_LINK_WINDOW[1], min(last), max(last), LAST))
    vertical = [sum(values) for values in zip(*(column(run, "joint.%s.reaction_force_z" % j) for j in GROUND_JOINTS))]
    begin, stop = thrust_window or (end - LAST, end)
    thrust = vertical[0] - mean_over(time, vertical, begin, stop)
    omega_squared = mean_over(time, [w * w for w in column(run, "joint.rotor_drive.velocity")], begin, stop)
    without = BLADES * RHO * 2 * math.pi * CHORD * omega_squared * THETA0 * (TIP ** 3 - ROOT ** 3) / 6
    estimate = hover_thrust_with_inflow(math.sqrt(omega_squared))
    print("  weight carried at rest %.0f N; thrust over [%g, %g] s (Omega %.4g rad/s rms) %.0f N; blade-element "
          "estimate with uniform inflow %.0f N (ratio %.4f), without inflow %.0f N" %
          (vertical[0], begin, stop, math.sqrt(omega_squared), thrust, estimate, thrust / estimate, without))


def main(argv):
    parser = argparse.ArgumentParser(description="Figures of rotor engage run-ups, from their bags.")
    parser.add_argument("bags", nargs="+", metavar="BAG")
    parser.add_argument("--thrust-window", nargs=2, type=float, metavar=("A", "B"),
                        help="times [s] over which the thrust is averaged (default: the last 2 s)")
    parser.add_argument("--until", type=float, default=math.inf, help="read the runs up to this time [s]")
    args = parser.parse_args(argv[1:])
    try:
        for path in args.bags:
            report(path, args.thrust_window, args.until)
    except (plot_bag.BagError, OSError) as exc:
        print("error: rotor_engage_measures.py: %s" % exc, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
