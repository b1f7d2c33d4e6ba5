"""Case metrics computed from a run's CSV output (its columns: docs/config.md, "output", and csv_sink.hpp).

Each kind checks its entry of the sweep file (metrics.csv.<name>) and computes one number from the samples.
Times are sample-based: a sticking time is resolved to one output sample period (output.rate_hz).
"""

import csv
import math

import numpy as np


class _Kind:
    """A metric kind: the keys it takes (`column` or `columns`, plus numbers) and how it computes."""
    keys = ('kind', 'column')
    numbers = {}  # optional number key -> default
    min_samples = 2  # a history; a static analysis writes one sample

    def check(self, entry):
        entry.check_keys(self.keys + tuple(self.numbers))
        if 'column' in self.keys:
            entry.get('column', str, required=True)
        if 'columns' in self.keys:
            columns = entry.get('columns', list, required=True)
            if not columns or not all(isinstance(c, str) for c in columns):
                entry.fail('columns', 'expected a non-empty list of CSV column names')
        for key in self.numbers:
            value = entry.get(key, (int, float))
            if key != 'scale' and value is not None and value <= 0:
                entry.fail(key, f'{value!r} is not positive')

    def columns(self, entry):
        return [entry['column']] if 'column' in entry else list(entry['columns'])

    def option(self, entry, key):
        return entry.get(key, self.numbers[key])


class PeakAbs(_Kind):
    """Largest |x| over the run, times `scale` (e.g. 57.2958 for degrees); of a static analysis, its one sample."""
    numbers = {'scale': 1.0}
    min_samples = 1

    def compute(self, t, x, entry):
        return float(np.max(np.abs(x[0]))) * self.option(entry, 'scale')


class FinalAbsMax(_Kind):
    """Largest |x| over the last `window` seconds of the run, times `scale`: the amplitude left at the end."""
    numbers = {'window': 20.0, 'scale': 1.0}

    def compute(self, t, x, entry):
        final = t >= t[-1] - self.option(entry, 'window')
        return float(np.max(np.abs(x[0][final]))) * self.option(entry, 'scale')


class CycleAmplitude(_Kind):
    """Half the peak-to-peak range of x over the last `window` seconds, times `scale`: a limit cycle's amplitude
    about its own mean, as flexmbd_run's cycle report (output.cycle_from) gives it."""
    numbers = {'window': 20.0, 'scale': 1.0}

    def compute(self, t, x, entry):
        final = x[0][t >= t[-1] - self.option(entry, 'window')]
        return 0.5 * float(np.max(final) - np.min(final)) * self.option(entry, 'scale')


class DecayTime(_Kind):
    """The last sample time at which any |x_c| exceeds `fraction` of its own peak: from then on every column
    stays within that band. inf when that time lies within `hold` seconds of the run's end (the motion has not
    been seen to stay down: a slow swing may be passing through zero)."""
    keys = ('kind', 'columns')
    numbers = {'fraction': 0.1, 'hold': 20.0}

    def compute(self, t, x, entry):
        last_above = t[0]
        for values in x:
            magnitude = np.abs(values)
            above = np.nonzero(magnitude > self.option(entry, 'fraction') * np.max(magnitude))[0]
            if above.size:
                last_above = max(last_above, t[above[-1]])
        return math.inf if last_above > t[-1] - self.option(entry, 'hold') else float(last_above)


def flag_intervals(t, flags):
    """(start, end) of each run of samples whose 0/1 column (sticking, in contact) is set; a run lasts until the
    next sample (or the last one). The overlay figures (scripts/plot_overlay.py) draw the same intervals."""
    padded = np.concatenate(([0], (np.asarray(flags) > 0.5).astype(int), [0]))
    starts, ends = np.nonzero(np.diff(padded) == 1)[0], np.nonzero(np.diff(padded) == -1)[0]
    return [(t[a], t[min(b, len(t) - 1)]) for a, b in zip(starts, ends)]


class StickingTime(_Kind):
    """Total time in which a 0/1 column (friction.<joint>.sticking) is 1."""

    def compute(self, t, x, entry):
        return float(sum(end - start for start, end in flag_intervals(t, x[0])))


class StickingIntervals(_Kind):
    """Number of intervals in which a 0/1 column is 1, as the samples see them."""

    def compute(self, t, x, entry):
        return len(flag_intervals(t, x[0]))


class LongestSticking(_Kind):
    """Duration of the longest sticking interval of a 0/1 column."""

    def compute(self, t, x, entry):
        return max((end - start for start, end in flag_intervals(t, x[0])), default=0.0)


class LongestStickingStart(_Kind):
    """Start time of the longest sticking interval of a 0/1 column (nan if it never sticks)."""

    def compute(self, t, x, entry):
        intervals = flag_intervals(t, x[0])
        return float(max(intervals, key=lambda i: i[1] - i[0])[0]) if intervals else math.nan


METRIC_KINDS = {
    'peak_abs': PeakAbs(),
    'final_abs_max': FinalAbsMax(),
    'cycle_amplitude': CycleAmplitude(),
    'decay_time': DecayTime(),
    'sticking_time': StickingTime(),
    'sticking_intervals': StickingIntervals(),
    'longest_sticking': LongestSticking(),
    'longest_sticking_start': LongestStickingStart(),
}


def read_columns(csv_path, names):
    """t and the named columns of a runner CSV as float arrays; KeyError names a missing column."""
    with open(csv_path, newline='', encoding='utf-8') as stream:
        reader = csv.reader(stream)
        header = next(reader)
        index = {name: k for k, name in enumerate(header)}
        wanted = ['t'] + [n for n in names if n != 't']
        for name in wanted:
            if name not in index:
                raise KeyError(f'{csv_path} has no column {name!r}')
        rows = np.array([[float(row[index[n]]) for n in wanted] for row in reader]).reshape(-1, len(wanted))
    return {name: rows[:, k] for k, name in enumerate(wanted)}


def compute_csv_metrics(csv_path, metric_entries):
    """{metric name: value} for the sweep's metrics.csv entries, from one run's CSV."""
    names = [c for entry in metric_entries.values() for c in METRIC_KINDS[entry['kind']].columns(entry)]
    table = read_columns(csv_path, names)
    values = {}
    samples = len(table['t'])
    for name, entry in metric_entries.items():
        kind = METRIC_KINDS[entry['kind']]
        if samples < kind.min_samples:
            raise ValueError(f"{csv_path} has {samples} sample(s); metric {name!r} ({entry['kind']}) needs at least "
                             f"{kind.min_samples} (a static analysis writes one: use peak_abs)")
        values[name] = kind.compute(table['t'], [table[c] for c in kind.columns(entry)], entry)
    return values
