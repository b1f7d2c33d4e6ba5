"""Runs a planned sweep's cases on this machine, `jobs` at a time."""

import os
from concurrent.futures import ThreadPoolExecutor

from .run_case import run_case


def local_core_count():
    return len(os.sched_getaffinity(0))


def run_local(out_dir, case_count, jobs):
    # Threads suffice: each case's work is a flexmbd_run process.
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        list(pool.map(lambda index: run_case(out_dir, index), range(case_count)))
