"""Parameter sweeps of flexmbd_run: a base case, overrides, one run each, a summary (docs/sweeps.md)."""
