"""Comparing parameter sets from a script: :func:`diff` (the ``--diff`` command's engine). No Qt."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from prm9tool.api.params import ParameterSet, read_prm
from prm9tool.compare.model import NOT_ON_SOURCE_VALVE, Comparison, Side

if TYPE_CHECKING:
    from prm9tool.api.valve import Valve

__all__ = ["diff"]


def diff(
    a: ParameterSet | Valve | str | os.PathLike[str],
    b: ParameterSet | Valve | str | os.PathLike[str],
) -> Comparison:
    """Compare two parameter sets: each a :class:`ParameterSet`, a *.prm path or an open
    :class:`~prm9tool.api.valve.Valve` (its set downloaded).

    The :class:`~prm9tool.compare.model.Comparison` has ``equal``, ``changed`` and ``missing``
    rows and ``warnings()``; ``prm9tool.compare.export.as_json(result)`` is the JSON that
    ``--diff --json`` prints.
    """
    return Comparison((_side(a), _side(b)))


def _side(source: ParameterSet | Valve | str | os.PathLike[str]) -> Side:
    from prm9tool.api.valve import Valve

    if isinstance(source, Valve):
        params = source.download()
        return Side(f"valve {source.info.serial}", params.type_key, params.raw)
    if isinstance(source, ParameterSet):
        label = f"parameters of {source.type_key}"
        params = source
    else:
        label = os.fspath(source)
        params = read_prm(source)
    # a set read from a valve lacks what that valve did not have (docs/compare.md)
    return Side(label, params.type_key, params.raw, NOT_ON_SOURCE_VALVE())
