"""Collects the cases' result.json files into summary.csv: one row per case, failed runs included."""

import csv
import json
import os

from .run_case import RESULT_FILE

STATUS_COLUMNS = ('status', 'exit_code')


def _result(case):
    path = os.path.join(case['dir'], RESULT_FILE)
    try:
        with open(path, encoding='utf-8') as stream:
            return json.load(stream)
    except (OSError, ValueError):
        return {'status': 'failed', 'exit_code': '', 'metrics': {},
                'message': f'no result: the case did not run or did not finish ({path} is missing)'}


def collect_rows(plan):
    """One row per planned case: its parameters, status, runner statistics and metrics, and message."""
    rows = []
    for case in plan['cases']:
        result = _result(case)
        row = {'case': case['index'], **case['parameters']}
        row.update({key: result[key] for key in STATUS_COLUMNS})
        row.update(result['metrics'])
        row['message'] = result['message']
        rows.append(row)
    return rows


def summary_columns(plan):
    return (['case', *plan['parameters'], *STATUS_COLUMNS, *plan['runner_metrics'], *plan['csv_metrics'],
             'message'])


def write_summary(plan, rows, path):
    with open(path, 'w', newline='', encoding='utf-8') as stream:
        writer = csv.DictWriter(stream, fieldnames=summary_columns(plan), restval='')
        writer.writeheader()
        for row in rows:
            writer.writerow({key: '' if value is None else value for key, value in row.items()})
