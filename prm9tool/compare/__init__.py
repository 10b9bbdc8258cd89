"""Comparing parameter sets: a document, a valve, factory defaults, *.prm files, history records.

Plain Python over the catalogue (no Qt, no device): the compare view, ``--diff`` and the
history's record-to-record difference all build a :class:`~prm9tool.compare.model.Comparison`.
"""

from prm9tool.compare.model import Comparison, Row, Side

__all__ = ["Comparison", "Row", "Side"]
