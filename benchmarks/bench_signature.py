"""The field signature (issue 31 item 5): valve seconds it plays, wall time, the record's size.

An emulated E02 (stepped as fast as the CPU allows) is characterized with the default profile
(its birth certificate, as a ``characterization`` record's details with their curves), then
its signature is taken three times and compared; prints the end-of-line test's wall time, the
signature's, its motion (valve seconds) and the size of the record's curves (docs/PERFORMANCE.md
"The field signature")::

    PYTHONPATH=$PWD .venv/bin/python benchmarks/bench_signature.py [--quick]

``--quick`` (the smoke run): one signature instead of three.
"""

from __future__ import annotations

import argparse
import json
import time

from prm9tool.analysis.profile import DEFAULT
from prm9tool.characterize import drift
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize
from prm9tool.device.emulator import EmulatedValve
from prm9tool.service.history import characterization_details

E02 = "PRM9-06.3Z11/30-24E02S02"


def main() -> None:
    """Measure and print."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one signature (smoke run)")
    runs = 1 if parser.parse_args().quick else 3
    birth = characterize(EmulatorRig(EmulatedValve(E02, serial=7001)), DEFAULT)
    outcome, details = characterization_details(birth, curves=True)
    records = [{"id": 1, "operation": "characterization", "outcome": outcome, "details": details}]
    walls = []
    report = None
    for _ in range(runs):
        started = time.perf_counter()
        rig = EmulatorRig(EmulatedValve(E02, serial=7001))
        report = drift.signature(rig, lambda _serial: records)
        walls.append(time.perf_counter() - started)
    assert report is not None
    print(f"end-of-line test: {birth.wall_s:.2f} s wall")
    print(f"signature: {', '.join(f'{w:.2f}' for w in walls)} s wall, "
          f"{report.plan.motion_s:.1f} s of motion, verdict {report.verdict}")  # fmt: skip
    print(f"record: curves {len(json.dumps(details['curves']))} B, "
          f"details {len(json.dumps(details))} B")  # fmt: skip


if __name__ == "__main__":
    main()
