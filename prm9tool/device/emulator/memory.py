"""The emulated valve's parameter memory between RAM and its non-volatile image: what NMT reset
communication, a reload after a failed upload and the store command (CiA 301 0x1010) do with
the working values. A mixin of
:class:`~prm9tool.device.emulator.firmware.Firmware`, which loads the RAM at power-up. No Qt.
"""

from __future__ import annotations

from prm9tool.catalogue.variant import Variant
from prm9tool.device.emulator.nvimage import NvImage, is_nonvolatile
from prm9tool.device.emulator.objdict import ObjectDictionary
from prm9tool.device.records import NmtState


class ParameterMemory:
    """Working values (the object dictionary's RAM) ↔ the NV image (a mixin)."""

    od: ObjectDictionary
    nv: NvImage
    variant: Variant
    node_id: int
    nmt_state: NmtState
    setpoint_dirty: bool
    config_dirty: bool

    def reset_communication(self) -> None:
        """NMT reset communication: communication objects back to their power-on values."""
        od = self.od
        for param in od.entries.values():
            if 0x1000 <= param.index <= 0x1FFF and param.group != "od_structure":
                value = self.nv.values.get(param.mnemonic)
                if value is None or not is_nonvolatile(param):
                    value = param.default_for(self.variant, self.node_id)
                if param.key not in od.getters:
                    od.values[param.key] = value
        self.nmt_state = NmtState.PRE_OPERATIONAL

    def reload(self) -> None:
        """Working values of the stored parameters ← the NV image, without a power cycle.

        Only the parameters the store command keeps change; the state machine, the boot
        timeline and the latched interface settings stay as they are, and the loop picks the
        values up in its next cycle.
        """
        od = self.od
        for param in od.entries.values():
            if is_nonvolatile(param) and param.key not in od.getters:
                value = self.nv.values.get(param.mnemonic)
                if value is None:
                    value = param.default_for(self.variant, self.node_id)
                od.values[param.key] = value
        self.setpoint_dirty = self.config_dirty = True

    def nonvolatile_values(self) -> dict[str, int | str]:
        """The RAM values the store command writes (node-relative defaults left out)."""
        image = {}
        for param in self.od.entries.values():
            if not is_nonvolatile(param):
                continue
            value = self.od.values[param.key]
            if param.node_relative and value == param.default_for(self.variant, self.node_id):
                continue
            image[param.mnemonic] = value
        return image
