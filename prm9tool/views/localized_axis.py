"""A pyqtgraph axis whose tick labels use the decimal separator of the program language."""

from __future__ import annotations

import pyqtgraph as pg

from prm9tool.i18n import current_language
from prm9tool.messages import localized_number


class LocalizedAxis(pg.AxisItem):
    """pyqtgraph's own tick spacing and digits; ``0,5`` instead of ``0.5`` in German and Czech
    (the one rule of ``prm9tool.messages.localized_number``)."""

    def tickStrings(self, values: list[float], scale: float, spacing: float) -> list[str]:
        """The tick texts pyqtgraph would write, in the program language."""
        language = current_language()
        return [
            localized_number(text, language) for text in super().tickStrings(values, scale, spacing)
        ]
