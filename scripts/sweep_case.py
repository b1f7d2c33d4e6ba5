#!/usr/bin/python3
"""One case of a planned sweep (a Slurm array task runs this): sweep_case.py OUT_DIR INDEX.
Writes OUT_DIR/cases/INDEX/result.json; exits 0 once it is written, whether the run succeeded or not."""

import sys

from flexmbd_sweep.run_case import run_case

if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run_case(sys.argv[1], int(sys.argv[2]))
