"""Expands a sweep into cases, writes each case's merged YAML and the plan every backend runs from."""

import difflib
import itertools
import json
import os
import subprocess

from .config_paths import scale_path, set_path
from .csv_metrics import METRIC_KINDS
from .errors import SweepError
from .yaml_io import dump_yaml, load_yaml

PLAN_FILE = 'plan.json'


def case_dir(out_dir, index):
    return os.path.join(out_dir, 'cases', f'{index:03d}')


def parameter_combinations(spec):
    """One {parameter: value} per case: the cartesian product of the grid, each combined with every position
    of the zipped parameters."""
    axes = [[(p, v) for v in p.values] for p in spec.grid]
    if spec.zipped:
        axes.append([tuple((p, p.values[k]) for p in spec.zipped) for k in range(len(spec.zipped[0].values))])
    combinations = []
    for choice in itertools.product(*axes):
        flat = []
        for item in choice:
            flat.extend(item if isinstance(item[0], tuple) else [item])
        combinations.append(flat)
    return combinations


def merged_config(spec, base, combination):
    """The base config with the sweep's `set` and one combination of parameter values applied."""
    config = json.loads(json.dumps(base))
    base_name = os.path.basename(spec.config)
    for path, value in spec.fixed.items():
        set_path(config, path, value, f'{spec.sweep_file}: set.{path}', base_name)
    for parameter, value in combination:
        for path in parameter.paths:
            where = f'{spec.sweep_file}: {parameter.field}'
            if parameter.scale:
                scale_path(config, path, value, where, base_name)
            else:
                set_path(config, path, value, where, base_name)
    return config


def check_case(runner, urdf, config_path, where, columns_path):
    """Has flexmbd_run load and build the case without running it, writing its CSV header to `columns_path`; its
    refusal becomes a SweepError. Returns the CSV's columns, or None when the case writes no such CSV (eigen)."""
    try:
        done = subprocess.run([runner, '--urdf', urdf, '--config', config_path, '--check', '--columns', columns_path],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, check=False)
    except OSError as error:
        raise SweepError(f'cannot run the runner {runner}: {error.strerror}') from None
    if done.returncode != 0:
        raise SweepError(f'{where}: the runner rejects this case: {done.stderr.strip()}')
    if not os.path.exists(columns_path):
        return None
    with open(columns_path, encoding='utf-8') as stream:
        return stream.readline().strip().split(',')


def check_metric_columns(spec, columns, where):
    """Every column the CSV metrics read must be one the case writes: a misspelt one fails here, before any case
    runs, with the closest column suggested."""
    for name, entry in spec.csv_metrics.items():
        for column in METRIC_KINDS[entry['kind']].columns(entry):
            if column in columns:
                continue
            closest = difflib.get_close_matches(column, columns, n=1)
            hint = f"; did you mean {closest[0]!r}?" if closest else ''
            raise SweepError(f'{spec.sweep_file}: metrics.csv.{name}: {column!r} is not a column of the CSV of '
                             f'{where}{hint}')


def write_plan(spec, runner, out_dir):
    """Writes cases/NNN/case.yaml for every case, checks each with the runner, and writes plan.json."""
    base = load_yaml(spec.config, 'base config') or {}
    if not isinstance(base, dict):
        raise SweepError(f'{spec.config}: the base config is not a mapping')
    cases = []
    for index, combination in enumerate(parameter_combinations(spec)):
        directory = case_dir(out_dir, index)
        os.makedirs(directory, exist_ok=True)
        config_path = os.path.join(directory, 'case.yaml')
        dump_yaml(merged_config(spec, base, combination), config_path)
        values = {parameter.name: value for parameter, value in combination}
        described = ', '.join(f'{p.field} = {v!r}' for p, v in combination)
        where = f'case {index} ({described})'
        columns = check_case(runner, spec.urdf, config_path, f'{spec.sweep_file}: {where}',
                             os.path.join(directory, 'columns.csv'))
        if columns is not None:
            check_metric_columns(spec, columns, where)
        cases.append({'index': index, 'dir': directory, 'config': config_path, 'parameters': values})
    plan = {'sweep_file': os.path.abspath(spec.sweep_file), 'runner': runner, 'urdf': spec.urdf,
            'runner_metrics': spec.runner_metrics, 'csv_metrics': spec.csv_metrics,
            'parameters': [p.name for p in spec.parameters], 'cases': cases}
    with open(os.path.join(out_dir, PLAN_FILE), 'w', encoding='utf-8') as stream:
        json.dump(plan, stream, indent=1)
    return plan


def read_plan(out_dir):
    with open(os.path.join(out_dir, PLAN_FILE), encoding='utf-8') as stream:
        return json.load(stream)
