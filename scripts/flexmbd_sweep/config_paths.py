"""Dotted paths into a case's YAML tree (joints.B2.friction.preload), checked against the base case."""

from .errors import SweepError


def _kind(value):
    if isinstance(value, bool):
        return 'true or false'
    if isinstance(value, (int, float)):
        return 'a number'
    return {str: 'a string', list: 'a list', dict: 'a mapping'}.get(type(value), type(value).__name__)


def _parent(tree, path, where, base_name):
    """The mapping that holds the last key of `path`; every key before it must be in the tree already."""
    keys = path.split('.')
    if not all(keys):
        raise SweepError(f'{where}: {path!r} is not a dotted path (e.g. joints.B2.friction.preload)')
    node = tree
    for depth, key in enumerate(keys[:-1]):
        if not isinstance(node, dict) or key not in node:
            holder = '.'.join(keys[:depth]) or 'the top level'
            known = ', '.join(node) if isinstance(node, dict) else 'none: it is not a mapping'
            raise SweepError(f'{where}: unknown path {path!r}: {holder} of {base_name} has no key {key!r} '
                             f'(keys: {known})')
        node = node[key]
    if not isinstance(node, dict):
        raise SweepError(f'{where}: unknown path {path!r}: {".".join(keys[:-1])} of {base_name} is not a mapping')
    return node, keys[-1]


def set_path(tree, path, value, where, base_name):
    """Sets `path` to `value`. A key already there keeps its kind (a number stays a number); a new last key is
    left to the runner's check of the case (flexmbd_run --check)."""
    node, key = _parent(tree, path, where, base_name)
    if key in node and node[key] is not None and _kind(node[key]) != _kind(value):
        raise SweepError(f'{where}: {value!r} for {path} is not {_kind(node[key])} '
                         f'(the value in {base_name} is {node[key]!r})')
    node[key] = value


def scale_path(tree, path, factor, where, base_name):
    """Multiplies the number at `path` by `factor`."""
    node, key = _parent(tree, path, where, base_name)
    if key not in node or _kind(node[key]) != 'a number':
        raise SweepError(f'{where}: scale needs a number at {path} in {base_name} '
                         f'(found {node.get(key, "nothing")!r})')
    node[key] = node[key] * factor
