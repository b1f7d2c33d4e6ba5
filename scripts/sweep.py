#!/usr/bin/python3
"""Parameter sweep of flexmbd_run (docs/sweeps.md): a base case (URDF + YAML) and a grid or zip of overrides
from a sweep file, one run each, locally in parallel or as a Slurm job array; writes summary.csv and a figure.

Exit status: 0 every run succeeded, 1 some run failed (a row with status failed), 2 bad input (the message
names the sweep file and the field), 3 Slurm did not take the array.
"""

import argparse
import os
import shutil
import sys

from flexmbd_sweep.case_plan import write_plan
from flexmbd_sweep.errors import SweepError
from flexmbd_sweep.local_backend import local_core_count, run_local
from flexmbd_sweep.slurm_backend import run_slurm
from flexmbd_sweep.summary import collect_rows, write_summary
from flexmbd_sweep.summary_figure import draw_figure
from flexmbd_sweep.sweep_spec import load_sweep_spec

EXIT_RUN_FAILED, EXIT_BAD_INPUT, EXIT_SLURM = 1, 2, 3


def default_runner():
    workspace = os.environ.get('FLEXMBD_WS') or os.path.join(os.path.expanduser('~'), 'flexmbd_ws')
    return os.path.join(workspace, 'devel', 'lib', 'flexmbd', 'flexmbd_run')


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('sweep_file')
    parser.add_argument('--out', help="output directory (default: the sweep file's output, or "
                                      "sweep_output/<sweep file name>); its cases/ are replaced")
    parser.add_argument('--jobs', type=int, default=local_core_count(),
                        help='runs at a time on this machine (default: the cores available, %(default)s)')
    parser.add_argument('--slurm', action='store_true', help='run the cases as a Slurm job array (sbatch --wait)')
    parser.add_argument('--sbatch-option', action='append', default=[], metavar='OPTION',
                        help='passed to sbatch, e.g. --sbatch-option=--partition=debug (repeatable)')
    parser.add_argument('--runner', default=default_runner(),
                        help='flexmbd_run to use (default: $FLEXMBD_WS/devel/lib/flexmbd/flexmbd_run)')
    return parser.parse_args()


def output_directory(args, spec):
    name = os.path.splitext(os.path.basename(args.sweep_file))[0]
    return os.path.abspath(args.out or spec.output or os.path.join('sweep_output', name))


def main():
    args = parse_arguments()
    if args.jobs < 1:
        print(f'error: sweep.py: --jobs {args.jobs}: expected at least 1', file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        spec = load_sweep_spec(args.sweep_file)
        out_dir = output_directory(args, spec)
        shutil.rmtree(os.path.join(out_dir, 'cases'), ignore_errors=True)
        plan = write_plan(spec, os.path.abspath(args.runner), out_dir)
    except SweepError as error:
        print(f'error: sweep.py: {error}', file=sys.stderr)
        return EXIT_BAD_INPUT
    count = len(plan['cases'])
    where = 'as a Slurm job array' if args.slurm else f'{min(args.jobs, count)} at a time'
    print(f'sweep: {count} cases of {args.sweep_file} in {out_dir}, {where}')
    if args.slurm:
        try:
            run_slurm(out_dir, count, args.sbatch_option)
        except SweepError as error:
            print(f'error: sweep.py: {error}', file=sys.stderr)
            return EXIT_SLURM
    else:
        run_local(out_dir, count, args.jobs)
    rows = collect_rows(plan)
    summary = os.path.join(out_dir, 'summary.csv')
    write_summary(plan, rows, summary)
    print(f'sweep: wrote {summary}')
    figure = os.path.join(out_dir, 'summary.png')
    draw_figure(spec.figure, plan['parameters'], rows, figure)
    print(f'sweep: wrote {figure}')
    failed = [row for row in rows if row['status'] != 'ok']
    for row in failed:
        print(f'sweep: case {row["case"]} failed: {row["message"]}', file=sys.stderr)
    print(f'sweep: {count - len(failed)} of {count} runs succeeded')
    return EXIT_RUN_FAILED if failed else 0


if __name__ == '__main__':
    sys.exit(main())
