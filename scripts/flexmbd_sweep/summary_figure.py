"""The sweep's figure: one panel per metric against one swept parameter, one line per value of the others."""

import math

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402 (after choosing the backend)


def _lines(rows, x, others):
    """{label of the other parameters' values: rows} for the successful runs, in sweep order."""
    lines = {}
    for row in rows:
        if row['status'] == 'ok':
            label = ', '.join(f'{name} = {row[name]}' for name in others)
            lines.setdefault(label, []).append(row)
    return lines


def draw_figure(figure, parameters, rows, path):
    """Panels for figure['y'] against figure['x']. A metric that is not finite (a decay not reached) is drawn
    as an open triangle at the top of its panel."""
    x, metrics = figure['x'], figure['y']
    others = [name for name in parameters if name != x]
    panels, axes = plt.subplots(len(metrics), 1, figsize=(7, 2.4 * len(metrics) + 0.6), sharex=True, squeeze=False)
    for axis, metric in zip(axes[:, 0], metrics):
        for label, line in _lines(rows, x, others).items():
            xs = [row[x] for row in line]
            ys = [float(row[metric]) if row[metric] not in (None, '') else math.nan for row in line]
            finite = [(a, b) for a, b in zip(xs, ys) if math.isfinite(b)]
            drawn = axis.plot(*zip(*finite), 'o-', label=label or None) if finite else axis.plot([], [])
            top = max((b for _, b in finite), default=1.0) * 1.08 or 1.0
            unreached = [a for a, b in zip(xs, ys) if math.isinf(b)]
            if unreached:
                axis.plot(unreached, [top] * len(unreached), '^', mfc='none', color=drawn[0].get_color(),
                          label='not reached in the run' if not others else None)
        axis.set_ylabel(metric)
        axis.grid(True, alpha=0.3)
        if axis.get_legend_handles_labels()[0]:
            axis.legend(fontsize='small')
    if figure.get('log_x'):
        axes[-1, 0].set_xscale('log')
    axes[-1, 0].set_xlabel(x)
    if figure.get('title'):
        panels.suptitle(figure['title'])
    panels.tight_layout()
    panels.savefig(path, dpi=110)
    plt.close(panels)
