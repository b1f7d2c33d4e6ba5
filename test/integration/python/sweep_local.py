#!/usr/bin/python3
"""scripts/sweep.py on this machine (sweep_local.test): a small sweep, its summary and figure, the errors it
reports for bad sweep files, and a failed run as a failed row."""

import math
import os
import shutil
import tempfile
import unittest

import numpy as np
import rostest

from sweep_helpers import PENDULUM_ANGLES_DEG, pendulum_sweep, read_summary, run_sweep, sweep_module, write_sweep

compute_csv_metrics = sweep_module('csv_metrics').compute_csv_metrics

# Released from rest, the pendulum's largest |angle| is its initial one (the t = 0 sample); the scheme does not
# add energy, so later samples stay below it up to Newton's tolerance, far under this bound.
PEAK_TOLERANCE_DEG = 1e-6


class SweepLocal(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix='sweep_local_')
        self.addCleanup(shutil.rmtree, self.directory, ignore_errors=True)
        self.out_dir = os.path.join(self.directory, 'out')

    def sweep_file(self, **changes):
        return write_sweep(self.directory, 'sweep.yaml', pendulum_sweep(**changes))

    def assert_bad_input(self, done, *fragments):
        self.assertEqual(done.returncode, 2, done.stderr)
        for fragment in fragments:
            self.assertIn(fragment, done.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.out_dir, 'summary.csv')))

    def test_grid_gives_one_row_per_value_with_statistics_and_metrics(self):
        done = run_sweep(self.sweep_file(), self.out_dir, '--jobs', '2')
        self.assertEqual(done.returncode, 0, done.stderr)
        rows = read_summary(self.out_dir)
        self.assertEqual([float(r['joints.B1.initial.position_deg']) for r in rows], PENDULUM_ANGLES_DEG)
        for row, angle in zip(rows, PENDULUM_ANGLES_DEG):
            self.assertEqual(row['status'], 'ok', row)
            self.assertAlmostEqual(float(row['peak_deg']), angle, delta=PEAK_TOLERANCE_DEG)
            self.assertGreater(int(row['steps']), 0)
            self.assertGreaterEqual(int(row['rejected']), 0)
            self.assertGreaterEqual(int(row['newton_iterations']), int(row['steps']))
            self.assertGreater(float(row['wall_time']), 0.0)
        self.assertGreater(os.path.getsize(os.path.join(self.out_dir, 'summary.png')), 0)

    def test_zip_scales_base_values_together(self):
        zipped = {'initial_scale': {'paths': ['joints.B1.initial.position_deg'], 'scale': [0.5, 2.0]}}
        done = run_sweep(self.sweep_file(grid={}, zip=zipped), self.out_dir, '--jobs', '1')
        self.assertEqual(done.returncode, 0, done.stderr)
        peaks = [float(r['peak_deg']) for r in read_summary(self.out_dir)]
        for peak, expected in zip(peaks, [15.0, 60.0]):  # pendulum.yaml starts at 30 deg
            self.assertAlmostEqual(peak, expected, delta=PEAK_TOLERANCE_DEG)

    def test_unknown_path_names_the_sweep_file_and_the_field(self):
        sweep = self.sweep_file(grid={'joints.B9.initial.position_deg': [1.0]})
        self.assert_bad_input(run_sweep(sweep, self.out_dir), sweep, 'grid.joints.B9.initial.position_deg',
                              "no key 'B9'")

    def test_value_of_the_wrong_kind_names_the_field(self):
        sweep = self.sweep_file(grid={'joints.B1.initial.position_deg': [10.0, 'steep']})
        self.assert_bad_input(run_sweep(sweep, self.out_dir), sweep, 'grid.joints.B1.initial.position_deg',
                              "'steep'", 'is not a number')

    def test_value_the_runner_refuses_names_the_case_and_the_runners_reason(self):
        sweep = self.sweep_file(grid={'solver.t_end': [0.5, -1.0]})
        self.assert_bad_input(run_sweep(sweep, self.out_dir), sweep, 'case 1 (grid.solver.t_end = -1.0)',
                              'solver.t_end')

    def test_misspelt_metric_column_is_refused_before_any_case_runs_with_the_closest_column(self):
        # Once found only after every case ran: each row failed, with the runner's exit code 0.
        metrics = {'csv': {'peak_deg': {'kind': 'peak_abs', 'column': 'joint.B1.positon'}}}
        sweep = self.sweep_file(metrics=metrics)
        self.assert_bad_input(run_sweep(sweep, self.out_dir), sweep, "metrics.csv.peak_deg: 'joint.B1.positon' is "
                              "not a column", "did you mean 'joint.B1.position'?")
        self.assertFalse(os.path.exists(os.path.join(self.out_dir, 'cases', '000', 'run.csv')))

    def test_path_set_by_grid_and_zip_is_refused_naming_the_path(self):
        # Once run with the zip's values and summarised with the grid's (explore23 sweep/grid_zip_same.yaml).
        zipped = {'start': {'paths': ['joints.B1.initial.position_deg'], 'values': [1.0, 2.0]}}
        sweep = self.sweep_file(zip=zipped)
        self.assert_bad_input(run_sweep(sweep, self.out_dir), sweep,
                              "zip.start: path 'joints.B1.initial.position_deg' is also set by "
                              "grid.joints.B1.initial.position_deg")

    def test_missing_base_file_names_the_field(self):
        sweep = self.sweep_file(base={'urdf': '/nonexistent/pendulum.urdf', 'config': 'pendulum.yaml'})
        self.assert_bad_input(run_sweep(sweep, self.out_dir), sweep, 'base.urdf', 'no such file')

    def test_failed_run_is_a_failed_row_and_a_non_zero_exit(self):
        # test/data/yaml/error_tol_underflow.yaml: this error_tol makes the run fail at dt_min (exit 3).
        sweep = self.sweep_file(grid={'solver.error_tol': [1.0e-4, 4.9e-324]})
        done = run_sweep(sweep, self.out_dir)
        self.assertEqual(done.returncode, 1, done.stderr)
        rows = read_summary(self.out_dir)
        self.assertEqual([r['status'] for r in rows], ['ok', 'failed'])
        self.assertEqual(rows[1]['exit_code'], '3')
        self.assertIn('run failed', rows[1]['message'])
        self.assertEqual(rows[1]['peak_deg'], '')
        self.assertIn('case 1 failed', done.stderr)

    def metrics_of(self, columns, metrics):
        """The metrics of a CSV made of `columns` (t first)."""
        path = os.path.join(self.directory, 'run.csv')
        np.savetxt(path, np.column_stack(list(columns.values())), delimiter=',', header=','.join(columns),
                   comments='')
        return compute_csv_metrics(path, metrics)

    def test_static_analysis_has_a_peak_but_no_history(self):
        one_sample = {'t': np.array([0.0]), 'x': np.array([-0.0526])}
        peak = {'tip': {'kind': 'peak_abs', 'column': 'x', 'scale': 1000.0}}
        self.assertAlmostEqual(self.metrics_of(one_sample, peak)['tip'], 52.6, places=9)
        with self.assertRaisesRegex(ValueError, r"1 sample\(s\); metric 'decay' \(decay_time\) needs at least 2"):
            self.metrics_of(one_sample, {'decay': {'kind': 'decay_time', 'columns': ['x']}})

    def test_decay_time_is_the_last_sample_above_the_fraction_of_the_peak(self):
        t = np.round(np.arange(0.0, 100.005, 0.01), 6)
        decays = {'t': t, 'a': np.where(t < 50.0, -2.0, 0.1), 'b': np.where(t < 30.0, 1.0, 0.0)}
        still_moving = {'t': t, 'a': np.where(t < 90.0, 1.0, 0.0)}
        metric = {'decay': {'kind': 'decay_time', 'columns': ['a', 'b'], 'fraction': 0.1, 'hold': 20.0}}
        self.assertAlmostEqual(self.metrics_of(decays, metric)['decay'], 49.99, places=9)
        metric['decay']['columns'] = ['a']
        self.assertEqual(self.metrics_of(still_moving, metric)['decay'], math.inf)

    def test_cycle_amplitude_is_half_the_final_peak_to_peak(self):
        # An offset sine whose amplitude halves at 5 s; sampled at 0.01 s it reaches its peaks (t = k + 1/4, 3/4)
        t = np.round(np.arange(0.0, 10.005, 0.01), 6)
        x = 0.3 + np.where(t < 5.0, 4.0, 2.0) * np.sin(2 * np.pi * t)
        metric = {'amplitude': {'kind': 'cycle_amplitude', 'column': 'x', 'window': 4.0, 'scale': 10.0}}
        self.assertAlmostEqual(self.metrics_of({'t': t, 'x': x}, metric)['amplitude'], 20.0, places=9)

    def test_sticking_metrics_count_the_sticking_samples(self):
        t = np.round(np.arange(0.0, 10.005, 0.01), 6)
        sticking = ((t >= 1.0) & (t < 3.0) | (t >= 5.0) & (t < 6.0) | (t >= 9.5)).astype(float)
        metrics = {name: {'kind': name, 'column': 's'}
                   for name in ('sticking_time', 'sticking_intervals', 'longest_sticking', 'longest_sticking_start')}
        values = self.metrics_of({'t': t, 's': sticking}, metrics)
        self.assertAlmostEqual(values['sticking_time'], 3.5, places=9)  # the last interval ends with the run
        self.assertEqual(values['sticking_intervals'], 3)
        self.assertAlmostEqual(values['longest_sticking'], 2.0, places=9)
        self.assertAlmostEqual(values['longest_sticking_start'], 1.0, places=9)


if __name__ == '__main__':
    rostest.rosrun('flexmbd', 'sweep_local', SweepLocal)
