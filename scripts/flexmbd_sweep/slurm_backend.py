"""Runs a planned sweep's cases as one Slurm job array, one array task per case, and waits for it."""

import os
import subprocess
import sys

from .errors import SweepError

CASE_SCRIPT = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'sweep_case.py')


def write_batch_script(out_dir):
    """The array job: task K runs case K (scripts/sweep_case.py), which writes that case's result.json."""
    slurm_dir = os.path.join(out_dir, 'slurm')
    os.makedirs(slurm_dir, exist_ok=True)
    path = os.path.join(slurm_dir, 'array.sh')
    with open(path, 'w', encoding='utf-8') as stream:
        stream.write('#!/bin/bash\n'
                     '#SBATCH --job-name=flexmbd-sweep\n'
                     '#SBATCH --ntasks=1\n'
                     '#SBATCH --cpus-per-task=1\n'
                     f'#SBATCH --output={slurm_dir}/task-%a.out\n'
                     f'exec {sys.executable} {CASE_SCRIPT} {out_dir} "$SLURM_ARRAY_TASK_ID"\n')
    return path


def run_slurm(out_dir, case_count, sbatch_options):
    """Submits the array with `sbatch --wait` (returns when every task has ended). A task that fails leaves no
    result.json and becomes a failed row when the results are collected."""
    script = write_batch_script(out_dir)
    command = ['sbatch', '--wait', '--parsable', f'--array=0-{case_count - 1}', *sbatch_options, script]
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, check=False)
    except OSError as error:
        raise SweepError(f'cannot run sbatch: {error.strerror} (is slurm-client installed?)') from None
    job = done.stdout.strip().split(';')[0]
    if not job:
        raise SweepError(f'sbatch did not submit the array: {done.stderr.strip()}')
    print(f'sweep: Slurm job array {job} ended (sbatch status {done.returncode})')
