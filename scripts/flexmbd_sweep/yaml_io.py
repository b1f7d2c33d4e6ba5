"""Reading and writing YAML as flexmbd's loader (yaml-cpp) reads it."""

import json
import re

import yaml

from .errors import SweepError


class _Loader(yaml.SafeLoader):
    """PyYAML follows YAML 1.1, where 2.9e8 and 1e-3 are strings; yaml-cpp and our configs read them as numbers."""


_Loader.add_implicit_resolver(
    'tag:yaml.org,2002:float',
    re.compile(r'^[-+]?(?:[0-9][0-9_]*(?:\.[0-9_]*)?[eE][-+]?[0-9]+|\.[0-9_]+[eE][-+]?[0-9]+)$'),
    list('-+0123456789.'))


def load_yaml(path, what):
    """The YAML document in `path` as plain dicts and lists; anchors and aliases are expanded into copies, so
    that overriding one aliased value changes only that place."""
    try:
        with open(path, encoding='utf-8') as stream:
            document = yaml.load(stream, Loader=_Loader)
    except OSError as error:
        raise SweepError(f'{path}: cannot read the {what}: {error.strerror}') from None
    except yaml.YAMLError as error:
        raise SweepError(f'{path}: the {what} is not valid YAML: {" ".join(str(error).split())}') from None
    return json.loads(json.dumps(document))


def dump_yaml(document, path):
    with open(path, 'w', encoding='utf-8') as stream:
        yaml.safe_dump(document, stream, default_flow_style=None, sort_keys=False)
