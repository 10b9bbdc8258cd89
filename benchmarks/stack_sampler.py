"""A sampling profiler for a process's every thread (cProfile sees one): ``sys._current_frames``
every millisecond; at exit the functions with the most samples, self and inclusive.

    python benchmarks/stack_sampler.py OUT.txt -m prm9tool --serve-emulator …

bench_plc_rig.py ``--profile`` runs the serving process under it (docs/PERFORMANCE.md).
"""

from __future__ import annotations

import atexit
import collections
import runpy
import signal
import sys
import threading
import time

INTERVAL_S = 0.001


def start(out: str) -> None:
    """Sample until the process exits; write the table to ``out``."""
    own: collections.Counter[str] = collections.Counter()
    inclusive: collections.Counter[str] = collections.Counter()
    samples = [0]
    me = threading.get_ident()

    def run() -> None:
        while True:
            time.sleep(INTERVAL_S)
            for ident, frame in sys._current_frames().items():
                if ident == me:
                    continue
                samples[0] += 1
                seen = set()
                top = True
                while frame is not None:
                    code = frame.f_code
                    key = f"{code.co_filename.rsplit('/', 2)[-1]}:{code.co_name}"
                    if top:
                        own[key] += 1
                        top = False
                    if key not in seen:
                        inclusive[key] += 1
                        seen.add(key)
                    frame = frame.f_back

    def dump() -> None:
        with open(out, "w", encoding="utf-8") as file:
            total = max(samples[0], 1)
            file.write(f"{samples[0]} thread samples\nself:\n")
            for key, n in own.most_common(40):
                file.write(f"{n / total:7.1%} {key}\n")
            file.write("inclusive:\n")
            for key, n in inclusive.most_common(60):
                file.write(f"{n / total:7.1%} {key}\n")

    atexit.register(dump)
    threading.Thread(target=run, daemon=True).start()


if __name__ == "__main__":
    start(sys.argv[1])
    signal.signal(signal.SIGTERM, signal.default_int_handler)
    if sys.argv[2] == "-m":
        sys.argv = [sys.argv[3], *sys.argv[4:]]
        runpy.run_module(sys.argv[0], run_name="__main__", alter_sys=True)
