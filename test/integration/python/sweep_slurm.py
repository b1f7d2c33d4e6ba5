#!/usr/bin/python3
"""scripts/sweep.py --slurm against a real single-node Slurm started by the test (slurm_cluster.py): the same
sweep as a job array and with local jobs gives the same summary (sweep_slurm.test)."""

import os
import shutil
import tempfile
import unittest

import rostest

from slurm_cluster import SlurmCluster
from sweep_helpers import PENDULUM_ANGLES_DEG, pendulum_sweep, read_summary, run_sweep, write_sweep

# Wall times differ from run to run; every other column must be equal.
VARYING_COLUMNS = ('wall_time',)


class SweepSlurm(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.mkdtemp(prefix='sweep_slurm_')
        cls.cluster = SlurmCluster(tempfile.mkdtemp(prefix='slurm_cluster_'))
        cls.cluster.start()

    @classmethod
    def tearDownClass(cls):
        cls.cluster.stop()
        shutil.rmtree(cls.cluster.directory, ignore_errors=True)
        shutil.rmtree(cls.directory, ignore_errors=True)

    def test_job_array_gives_the_summary_of_local_jobs(self):
        sweep = write_sweep(self.directory, 'sweep.yaml', pendulum_sweep())
        slurm_out, local_out = (os.path.join(self.directory, name) for name in ('slurm_out', 'local_out'))
        done = run_sweep(sweep, slurm_out, '--slurm', env=self.cluster.env, timeout=180)
        self.assertEqual(done.returncode, 0, done.stdout + done.stderr + self.cluster.log_tail())
        self.assertIn('Slurm job array', done.stdout)
        for index in range(len(PENDULUM_ANGLES_DEG)):  # each case ran as its own array task
            self.assertTrue(os.path.exists(os.path.join(slurm_out, 'slurm', f'task-{index}.out')))
        done = run_sweep(sweep, local_out, '--jobs', '2')
        self.assertEqual(done.returncode, 0, done.stderr)

        slurm_rows, local_rows = read_summary(slurm_out), read_summary(local_out)
        self.assertEqual(len(slurm_rows), len(PENDULUM_ANGLES_DEG))
        self.assertEqual(list(slurm_rows[0]), list(local_rows[0]))
        for slurm_row, local_row in zip(slurm_rows, local_rows):
            self.assertEqual(slurm_row['status'], 'ok', slurm_row)
            for column in VARYING_COLUMNS:
                self.assertGreater(float(slurm_row.pop(column)), 0.0)
                self.assertGreater(float(local_row.pop(column)), 0.0)
            self.assertEqual(slurm_row, local_row)


if __name__ == '__main__':
    rostest.rosrun('flexmbd', 'sweep_slurm', SweepSlurm)
