"""The sweep's figure: panels of metrics against one swept parameter, one line per metric and per value of the
other parameters."""

import math
import os

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402 (after choosing the backend)


def panel_metrics(item):
    """A figure.y entry is one metric or a list of metrics that share a panel."""
    return item if isinstance(item, list) else [item]


def _lines(rows, x, others):
    """{label of the other parameters' values: rows} for the successful runs, in sweep order."""
    lines = {}
    for row in rows:
        if row['status'] == 'ok':
            label = ', '.join(f'{name} = {row[name]}' for name in others)
            lines.setdefault(label, []).append(row)
    return lines


def _draw_line(axis, line, x, metric, label, slot):
    """Finite values as a line; infinite ones (a decay not reached in the run) as open triangles along the top
    of the panel, one row per line (`slot`)."""
    xs = [row[x] for row in line]
    ys = [math.nan if row[metric] in (None, '') else float(row[metric]) for row in line]
    finite = [(a, b) for a, b in zip(xs, ys) if math.isfinite(b)]
    drawn = axis.plot(*zip(*finite), 'o-', label=label) if finite else axis.plot([], [], label=label)
    unreached = [a for a, b in zip(xs, ys) if math.isinf(b)]
    if unreached:
        axis.plot(unreached, [0.96 - 0.06 * slot] * len(unreached), '^', mfc='none', ms=8,
                  color=drawn[0].get_color(), transform=axis.get_xaxis_transform(), clip_on=False)
    return bool(unreached)


def _panel_label(metrics):
    """The metrics' common name in whole words (stick_time_B2, stick_time_B3 -> stick_time)."""
    if len(metrics) == 1:
        return metrics[0]
    prefix = os.path.commonprefix(metrics)
    return prefix[:prefix.rfind('_')] if '_' in prefix else 'value'


def draw_figure(figure, parameters, rows, path):
    x = figure['x']
    others = [name for name in parameters if name != x]
    lines = _lines(rows, x, others)
    items = figure['y']
    panels, axes = plt.subplots(len(items), 1, figsize=(9, 2.2 * len(items) + 0.8), sharex=True, squeeze=False)
    for axis, item in zip(axes[:, 0], items):
        metrics = panel_metrics(item)
        labels = [(metric, others_label) for metric in metrics for others_label in lines]
        unreached = False
        for slot, (metric, others_label) in enumerate(labels):
            label = ', '.join(filter(None, [metric, others_label]))
            unreached |= _draw_line(axis, lines[others_label], x, metric, label, slot)
        if unreached:  # room above the data for the rows of triangles
            bottom, top = axis.get_ylim()
            axis.set_ylim(bottom, top + 0.06 * (len(labels) + 1) / 0.8 * (top - bottom))
            axis.plot([], [], '^', mfc='none', color='gray', label='not reached in the run')
        axis.set_ylabel(_panel_label(metrics))
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize='x-small', loc='upper left', bbox_to_anchor=(1.01, 1.0))
    if figure.get('log_x'):
        axes[-1, 0].set_xscale('log')
    axes[-1, 0].set_xlabel(x)
    if figure.get('title'):
        panels.suptitle(figure['title'], fontsize='medium')
    panels.tight_layout()
    panels.savefig(path, dpi=110)
    plt.close(panels)
