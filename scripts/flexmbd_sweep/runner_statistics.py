"""The run statistics flexmbd_run prints (src/tools/flexmbd_run.cpp, StepStatistics::Summary)."""

import re

# Summary column -> (pattern in the runner's output, its group, type). A failed run prints the step line but
# not the wall time.
_PATTERNS = {
    'steps': (r'steps: (\d+) accepted, (\d+) rejected', 1, int),
    'rejected': (r'steps: (\d+) accepted, (\d+) rejected', 2, int),
    'newton_iterations': (r'; (\d+) Newton iterations', 1, int),
    'wall_time': (r'samples written in (\S+) s wall time', 1, float),
}
RUNNER_METRICS = tuple(_PATTERNS)


def parse_runner_statistics(stdout, names):
    """{name: value} for the requested statistics found in the runner's standard output (None if absent)."""
    values = {}
    for name in names:
        pattern, group, kind = _PATTERNS[name]
        match = re.search(pattern, stdout)
        values[name] = kind(match.group(group)) if match else None
    return values
