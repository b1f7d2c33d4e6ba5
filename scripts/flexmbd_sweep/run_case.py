"""Runs one case of a planned sweep and writes its result.json: what every backend does per case, so that
local and Slurm runs are collected the same way."""

import json
import os
import subprocess

from .case_plan import read_plan
from .csv_metrics import compute_csv_metrics
from .runner_statistics import parse_runner_statistics

RESULT_FILE = 'result.json'


def _last_line(text):
    lines = [line for line in text.strip().splitlines() if line.strip()]
    return lines[-1] if lines else ''


def _outcome(case, plan):
    """(status, exit code, message, metrics) of running the case and reading its outputs."""
    directory = case['dir']
    csv_path = os.path.join(directory, 'run.csv')
    command = [plan['runner'], '--urdf', plan['urdf'], '--config', case['config']]
    if plan['csv_metrics']:
        command += ['--csv', csv_path]
    with open(os.path.join(directory, 'stdout.txt'), 'w', encoding='utf-8') as out, \
            open(os.path.join(directory, 'stderr.txt'), 'w+', encoding='utf-8') as err:
        exit_code = subprocess.run(command, stdout=out, stderr=err, check=False).returncode
        err.seek(0)
        message = _last_line(err.read())
    with open(os.path.join(directory, 'stdout.txt'), encoding='utf-8') as out:
        metrics = parse_runner_statistics(out.read(), plan['runner_metrics'])
    if exit_code != 0:
        return 'failed', exit_code, message or f'flexmbd_run exited with status {exit_code}', metrics
    if plan['csv_metrics']:
        try:
            metrics.update(compute_csv_metrics(csv_path, plan['csv_metrics']))
        except (KeyError, ValueError) as error:
            return 'failed', exit_code, f'metrics: {error.args[0]}', metrics
    return 'ok', exit_code, '', metrics


def run_case(out_dir, index):
    """Runs case `index` of the sweep planned in `out_dir`; returns its result, also written to result.json."""
    plan = read_plan(out_dir)
    case = plan['cases'][index]
    status, exit_code, message, metrics = _outcome(case, plan)
    result = {'index': index, 'status': status, 'exit_code': exit_code, 'message': message, 'metrics': metrics}
    with open(os.path.join(case['dir'], RESULT_FILE), 'w', encoding='utf-8') as stream:
        json.dump(result, stream, indent=1)
    return result
