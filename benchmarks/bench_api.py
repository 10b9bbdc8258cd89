"""The Python API's cost: importing it, opening an emulated valve, a single value, an upload.

Reference, measured in the same run: ``python -c "import numpy"`` (the floor of anything that
returns samples as arrays; the session module needs numpy). Each import figure is the median
of several fresh processes; the valve figures are medians of repeated calls in one process,
with emulator data in a temporary folder.

Run:  python benchmarks/bench_api.py [--runs N] [--quick]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

TYPE_KEY = "PRM9-06.3Z11/30-24E02S02-CA"
IMPORTS = {
    "python -c pass": "pass",
    "import numpy (reference)": "import numpy",
    "import prm9tool": "import prm9tool",
    "import prm9tool; prm9tool.connect": "import prm9tool; prm9tool.connect",
}


def process_s(code: str, runs: int) -> float:
    """Median wall-clock seconds of a fresh ``python -c code``."""
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-c", code], check=True)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def valve_figures(runs: int) -> dict[str, float]:
    """Median seconds of connect, a read, a checked write and an upload of the factory set."""
    import prm9tool

    figures: dict[str, list[float]] = {"connect": [], "read": [], "write": [], "upload": []}
    for serial in range(1, runs + 1):
        start = time.perf_counter()
        with prm9tool.connect(f"emulator:{TYPE_KEY}:{serial}", record_history=False) as valve:
            figures["connect"].append(time.perf_counter() - start)
            valve.wait_booted()
            start = time.perf_counter()
            valve["LIMTA"]
            figures["read"].append(time.perf_counter() - start)
            start = time.perf_counter()
            valve["LIMTA"] = 1800
            figures["write"].append(time.perf_counter() - start)
            params = prm9tool.ParameterSet.factory(TYPE_KEY)
            start = time.perf_counter()
            assert valve.upload(params, backup=False).stored
            figures["upload"].append(time.perf_counter() - start)
    return {name: statistics.median(values) for name, values in figures.items()}


def main() -> None:
    """Print the figures and their ratios to the reference."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--quick", action="store_true", help="a smoke run: one of each")
    args = parser.parse_args()
    runs = 1 if args.quick else args.runs
    with tempfile.TemporaryDirectory() as data:
        os.environ["PRM9TOOL_DATA_DIR"] = data
        imports = {name: process_s(code, runs) for name, code in IMPORTS.items()}
        reference = imports["import numpy (reference)"]
        for name, seconds in imports.items():
            print(f"{name:40s} {seconds * 1000:7.0f} ms  {seconds / reference:5.2f} x numpy")
        for name, seconds in valve_figures(runs).items():
            print(f"valve {name:34s} {seconds * 1000:7.1f} ms")


if __name__ == "__main__":
    main()
