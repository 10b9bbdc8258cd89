"""Stand-in for hidapi's ``hid`` module in subprocess tests (put this folder on PYTHONPATH).

``PRM9TOOL_FAKE_HID`` lists the valves, ``;``-separated: ``TYPEKEY,SERIAL[,option=N]...``
with the options of :class:`support.usb_fakes.FakeCable` (``unplug_after_out``,
``corrupt_reads_after_out``). Each valve appears as ``/dev/hidraw<n>``.
"""

from __future__ import annotations

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

from support.usb_fakes import FakeHid

from prm9tool.device.emulator import EmulatedValve

_FAKE = FakeHid()
for _number, _spec in enumerate(filter(None, os.environ.get("PRM9TOOL_FAKE_HID", "").split(";"))):
    _type_key, _serial, *_options = _spec.split(",")
    _valve = _FAKE.add(EmulatedValve(_type_key, int(_serial)), f"/dev/hidraw{_number}".encode())
    for _option in _options:
        _name, _value = _option.split("=")
        setattr(_valve.cable, _name, int(_value))

enumerate = _FAKE.enumerate
device = _FAKE.device
