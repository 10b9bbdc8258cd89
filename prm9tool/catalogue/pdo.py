"""The valve's fixed PDO mapping (manual table 7-13): a valve fact, read by the EDS writer and
the emulated CANopen slave alike. No Qt."""

from __future__ import annotations

from prm9tool.catalogue.schema import Parameter


def mapping_for_control_mode(param: Parameter, control_mode: int) -> int:
    """A PDO mapping entry's value in ``control_mode`` (table 7-13: entry 2 follows 0x6043)."""
    if control_mode == 4 and param.default_e04 is not None:
        return param.default_e04
    assert isinstance(param.default, int)
    return param.default
