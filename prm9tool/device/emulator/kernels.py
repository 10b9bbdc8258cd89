"""Which implementation of the control loop the emulated valves run (docs/emulator.md).

The compiled kernel (:mod:`.ckernel`, a C extension built by ``pip install``) when it could be
built, else the pure-Python reference (:mod:`.kernel`); the environment variable
``PRM9TOOL_EMULATOR_KERNEL=python|compiled`` forces one. The choice is made once per process,
at the first emulated valve (nothing is imported before: the GUI's start-up does not grow), and
said once in the log.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable
from typing import Protocol

from prm9tool.device.emulator.loopstate import LoopState
from prm9tool.errors import ValueRangeError

ENV = "PRM9TOOL_EMULATOR_KERNEL"
log = logging.getLogger(__name__)


class Loop(Protocol):
    """The control loop as the firmware drives it: ``send(n)`` runs n cycles, 0 flushes."""

    def send(self, n: int, /) -> None: ...

    def __next__(self) -> None: ...


LoopFactory = Callable[[LoopState], Loop]
_chosen: tuple[str, LoopFactory] | None = None


def compiled_unavailable() -> str | None:
    """Why the compiled kernel cannot be used here, or None if it can."""
    try:
        from prm9tool.device.emulator import ckernel  # noqa: F401
    except ImportError as exc:
        return f"{exc} (reinstall with a C compiler: pip install -e .)"
    return None


def choose(request: str | None = None) -> tuple[str, LoopFactory]:
    """("compiled" | "python", factory) for ``request`` (default: the environment variable).

    Raises :class:`ValueRangeError` for an unknown name or a forced compiled kernel that is
    not available.
    """
    wanted = (os.environ.get(ENV, "") if request is None else request).strip().lower()
    if wanted not in ("", "python", "compiled"):
        raise ValueRangeError(f"{ENV}={wanted!r}: use 'python' or 'compiled'")
    if wanted != "python":
        reason = compiled_unavailable()
        if reason is None:
            from prm9tool.device.emulator.ckernel import CompiledLoop

            return "compiled", CompiledLoop
        if wanted == "compiled":
            raise ValueRangeError(
                f"{ENV}=compiled, but the compiled kernel is unavailable: {reason}"
            )
        log.warning(
            "emulator: compiled control loop unavailable (%s); using the Python one", reason
        )
    from prm9tool.device.emulator.kernel import control_loop

    return "python", control_loop


def chosen() -> tuple[str, LoopFactory]:
    """The kernel of this process: (name, factory); chosen, and logged, on the first call."""
    global _chosen
    if _chosen is None:
        _chosen = choose()
        log.info("emulator: %s control loop", _chosen[0])
    return _chosen


def use(name: str | None) -> None:
    """Valves created from now on run kernel ``name`` (None: choose again on the next valve).

    For tests and benchmarks that compare the kernels in one process.
    """
    global _chosen
    _chosen = None if name is None else choose(name)
