"""What the sweep tests (sweep_local.py, sweep_slurm.py) share: where things are, writing a sweep file, running
scripts/sweep.py and reading its summary."""

import csv
import importlib
import os
import subprocess
import sys

import rospkg
import yaml
from roslib.packages import find_node

SOURCE_DIR = rospkg.RosPack().get_path('flexmbd')
RUNNER = find_node('flexmbd', 'flexmbd_run')[0]
SWEEP_SCRIPT = os.path.join(SOURCE_DIR, 'scripts', 'sweep.py')
TEST_DATA = os.path.join(SOURCE_DIR, 'test', 'data')

# A sweep of three short runs of the single pendulum released from rest (test/data/yaml/pendulum.yaml).
PENDULUM_ANGLES_DEG = [10.0, 20.0, 40.0]


def sweep_module(name):
    """A module of scripts/flexmbd_sweep, for the tests of its parts."""
    sys.path.insert(0, os.path.join(SOURCE_DIR, 'scripts'))
    return importlib.import_module(f'flexmbd_sweep.{name}')


def pendulum_sweep(**changes):
    """The sweep file's content as a dict; `changes` replace top-level entries."""
    sweep = {
        'base': {'urdf': os.path.join(TEST_DATA, 'urdf', 'pendulum.urdf'),
                 'config': os.path.join(TEST_DATA, 'yaml', 'pendulum.yaml')},
        'set': {'solver.t_end': 0.5},
        'grid': {'joints.B1.initial.position_deg': PENDULUM_ANGLES_DEG},
        'metrics': {'csv': {'peak_deg': {'kind': 'peak_abs', 'column': 'joint.B1.position',
                                         'scale': 57.29577951308232}}},
    }
    sweep.update(changes)
    return sweep


def write_sweep(directory, name, sweep):
    path = os.path.join(directory, name)
    with open(path, 'w', encoding='utf-8') as stream:
        yaml.safe_dump(sweep, stream)
    return path


def run_sweep(sweep_file, out_dir, *options, env=None, timeout=300):
    """Runs scripts/sweep.py as a user does; returns the completed process (text output)."""
    return subprocess.run([sys.executable, SWEEP_SCRIPT, sweep_file, '--out', out_dir, '--runner', RUNNER, *options],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, timeout=timeout)


def read_summary(out_dir):
    with open(os.path.join(out_dir, 'summary.csv'), newline='', encoding='utf-8') as stream:
        return list(csv.DictReader(stream))
