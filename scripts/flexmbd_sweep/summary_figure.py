"""The sweep's figure: panels of metrics against one swept parameter, one line per metric and per value of the
other parameters."""

import math

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


def _draw_line(axis, line, x, metric, label):
    """Finite values as a line; infinite ones (a decay not reached in the run) as open triangles at the top."""
    xs = [row[x] for row in line]
    ys = [math.nan if row[metric] in (None, '') else float(row[metric]) for row in line]
    finite = [(a, b) for a, b in zip(xs, ys) if math.isfinite(b)]
    drawn = axis.plot(*zip(*finite), 'o-', label=label) if finite else axis.plot([], [], label=label)
    unreached = [a for a, b in zip(xs, ys) if math.isinf(b)]
    if unreached:
        top = max((b for _, b in finite), default=1.0) * 1.08 or 1.0
        axis.plot(unreached, [top] * len(unreached), '^', mfc='none', ms=9, color=drawn[0].get_color(),
                  label=f'{label}: not reached in the run')


def draw_figure(figure, parameters, rows, path):
    x = figure['x']
    others = [name for name in parameters if name != x]
    lines = _lines(rows, x, others)
    items = figure['y']
    panels, axes = plt.subplots(len(items), 1, figsize=(7, 2.2 * len(items) + 0.8), sharex=True, squeeze=False)
    for axis, item in zip(axes[:, 0], items):
        metrics = panel_metrics(item)
        for metric in metrics:
            for others_label, line in lines.items():
                _draw_line(axis, line, x, metric, ', '.join(filter(None, [metric, others_label])))
        axis.set_ylabel(metrics[0] if len(metrics) == 1 else 'value')
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize='x-small')
    if figure.get('log_x'):
        axes[-1, 0].set_xscale('log')
    axes[-1, 0].set_xlabel(x)
    if figure.get('title'):
        panels.suptitle(figure['title'], fontsize='medium')
    panels.tight_layout()
    panels.savefig(path, dpi=110)
    plt.close(panels)
