"""The one error the sweep driver reports for bad input: its message names the file and the field."""


class SweepError(Exception):
    """Bad sweep input (file, field, value); the driver prints it on one line and exits 2."""
