"""The sweep file (docs/sweeps.md): checked and turned into plain data; every error names the file and field."""

import os
from dataclasses import dataclass, field

from .csv_metrics import METRIC_KINDS
from .errors import SweepError
from .runner_statistics import RUNNER_METRICS
from .summary_figure import panel_metrics
from .yaml_io import load_yaml

TOP_LEVEL_KEYS = ('base', 'set', 'grid', 'zip', 'metrics', 'figure', 'output')


@dataclass
class Parameter:
    """One swept quantity: a summary column `name`, the dotted config paths it sets, and per case either the
    value written to every path or (scale) the factor applied to each path's base value."""
    name: str
    field: str  # where it is in the sweep file, e.g. zip.preload_factor
    paths: list
    values: list
    scale: bool = False


@dataclass
class SweepSpec:
    sweep_file: str
    urdf: str
    config: str
    fixed: dict  # dotted path -> value, set in every case
    grid: list  # Parameters whose values combine as a cartesian product
    zipped: list  # Parameters whose values go together, one case per position
    runner_metrics: list
    csv_metrics: dict  # metric name -> its mapping (kind, column(s), ...)
    figure: dict = field(default_factory=dict)
    output: str = ''

    @property
    def parameters(self):
        return self.grid + self.zipped


class _Fields:
    """Reads fields of one mapping of the sweep file, naming `sweep_file` and the field's path in errors."""

    def __init__(self, sweep_file, mapping, where):
        self.sweep_file, self.mapping, self.where = sweep_file, mapping, where

    def fail(self, key, message):
        raise SweepError(f'{self.sweep_file}: {self.where}{key}: {message}')

    def check_keys(self, allowed):
        for key in self.mapping:
            if key not in allowed:
                self.fail(key, f'unknown key (expected one of: {", ".join(allowed)})')

    def get(self, key, kind, required=False, default=None):
        if key not in self.mapping:
            if required:
                self.fail(key, 'missing')
            return default
        value = self.mapping[key]
        if not isinstance(value, kind) or isinstance(value, bool) and kind is not bool:
            self.fail(key, f'{value!r} is not {_KIND_NAMES.get(kind, kind)}')
        return value

    def child(self, key, required=False):
        return _Fields(self.sweep_file, self.get(key, dict, required, {}), f'{self.where}{key}.')


_KIND_NAMES = {dict: 'a mapping', list: 'a list', str: 'a string', (int, float): 'a number', bool: 'true or false'}


def _existing_file(fields, key, base_dir):
    path = os.path.join(base_dir, fields.get(key, str, required=True))
    if not os.path.isfile(path):
        fields.fail(key, f'no such file: {path}')
    return os.path.abspath(path)


def _parameter(fields, name):
    """A parameter given as a list of values (its name is the path), or as {path(s), values or scale}."""
    spec = fields.mapping[name]
    if isinstance(spec, list):
        return Parameter(name, fields.where + name, [name], _value_list(fields, name, spec))
    entry = fields.child(name)
    entry.check_keys(('path', 'paths', 'values', 'scale'))
    if ('path' in spec) == ('paths' in spec):
        fields.fail(name, 'give either path or paths')
    paths = [entry.get('path', str)] if 'path' in spec else entry.get('paths', list)
    if not paths or not all(isinstance(p, str) and p for p in paths):
        entry.fail('paths', 'expected a non-empty list of dotted paths')
    if ('values' in spec) == ('scale' in spec):
        fields.fail(name, 'give either values or scale')
    key = 'scale' if 'scale' in spec else 'values'
    values = _value_list(entry, key, entry.get(key, list))
    if key == 'scale':
        for k, factor in enumerate(values):
            if not isinstance(factor, (int, float)) or isinstance(factor, bool):
                entry.fail(f'{key}[{k}]', f'{factor!r} is not a number')
    return Parameter(name, fields.where + name, paths, values, scale=key == 'scale')


def _value_list(fields, key, values):
    if not values:
        fields.fail(key, 'expected a non-empty list of values')
    for k, value in enumerate(values):
        if value is None or isinstance(value, dict):
            fields.fail(f'{key}[{k}]', f'{value!r} is not a value (a number, string, true/false or a list)')
    return values


def _parameters(fields):
    return [_parameter(fields, name) for name in fields.mapping]


def _metrics(fields):
    metrics = fields.child('metrics')
    metrics.check_keys(('runner', 'csv'))
    runner = metrics.get('runner', list, default=list(RUNNER_METRICS))
    for k, name in enumerate(runner):
        if name not in RUNNER_METRICS:
            metrics.fail(f'runner[{k}]', f'{name!r} is not a runner statistic ({", ".join(RUNNER_METRICS)})')
    csv = metrics.child('csv')
    for name in csv.mapping:
        entry = csv.child(name)
        kind = entry.get('kind', str, required=True)
        if kind not in METRIC_KINDS:
            entry.fail('kind', f'{kind!r} is not a metric kind ({", ".join(METRIC_KINDS)})')
        METRIC_KINDS[kind].check(entry)
    return runner, csv.mapping


def _figure(fields, parameters, metric_names):
    figure = fields.child('figure')
    figure.check_keys(('x', 'y', 'log_x', 'title'))
    if not figure.mapping:  # every metric against the first parameter
        return {'x': parameters[0].name, 'y': list(metric_names)}
    names = [p.name for p in parameters]
    x = figure.get('x', str, required=True)
    if x not in names:
        figure.fail('x', f'{x!r} is not a swept parameter ({", ".join(names)})')
    y = figure.get('y', list, required=True)
    for k, item in enumerate(y):
        for name in panel_metrics(item):
            if name not in metric_names:
                figure.fail(f'y[{k}]', f'{name!r} is not a metric of this sweep ({", ".join(metric_names)})')
    figure.get('log_x', bool)
    figure.get('title', str)
    return figure.mapping


def _check_paths_set_once(sweep_file, parameters):
    """Two parameters setting one path would write both values into the case and label the row with one of them,
    while the run takes the other."""
    setters = {}
    for parameter in parameters:
        for path in parameter.paths:
            if path in setters:
                raise SweepError(f'{sweep_file}: {parameter.field}: path {path!r} is also set by {setters[path]}; '
                                 'expected each config path in one parameter')
            setters[path] = parameter.field


def load_sweep_spec(sweep_file):
    document = load_yaml(sweep_file, 'sweep file')
    if not isinstance(document, dict):
        raise SweepError(f'{sweep_file}: expected a mapping with keys {", ".join(TOP_LEVEL_KEYS)}')
    root = _Fields(sweep_file, document, '')
    root.check_keys(TOP_LEVEL_KEYS)
    base = root.child('base', required=True)
    base.check_keys(('urdf', 'config'))
    base_dir = os.path.dirname(os.path.abspath(sweep_file))
    grid, zipped = _parameters(root.child('grid')), _parameters(root.child('zip'))
    if not grid and not zipped:
        root.fail('grid', 'nothing to sweep: give grid or zip (or both)')
    names = [p.name for p in grid + zipped]
    for name in names:
        if names.count(name) > 1:
            root.fail('zip', f'parameter {name!r} is also in grid')
    _check_paths_set_once(sweep_file, grid + zipped)
    lengths = {len(p.values) for p in zipped}
    if len(lengths) > 1:
        root.fail('zip', f'every parameter needs as many values (have {", ".join(map(str, sorted(lengths)))})')
    fixed = root.child('set').mapping
    runner_metrics, csv_metrics = _metrics(root)
    return SweepSpec(
        sweep_file=sweep_file,
        urdf=_existing_file(base, 'urdf', base_dir),
        config=_existing_file(base, 'config', base_dir),
        fixed=fixed, grid=grid, zipped=zipped,
        runner_metrics=runner_metrics, csv_metrics=csv_metrics,
        figure=_figure(root, grid + zipped, runner_metrics + list(csv_metrics)),
        output=root.get('output', str, default=''))
