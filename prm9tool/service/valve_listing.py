"""Finding and opening valves for the window's connection: the device factory's listing (USB,
emulated valves, the nodes on a CAN bus) and opening, imported only when used; the CAN bus the
GUI remembers as a dict, turned into the factory's options. No Qt."""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, TypeVar

if TYPE_CHECKING:
    from prm9tool.device.canlink.bus import CanOptions
    from prm9tool.device.factory import DeviceEntry
    from prm9tool.device.session import ValveSession

Listed = TypeVar("Listed")  # what the lister lists (DeviceEntry; the views see ValveListing)


def can_options(bus: Mapping[str, object]) -> CanOptions:
    """The device factory's ``CanOptions`` of ``bus`` (``interface``, ``channel``, ``bitrate``)."""
    from prm9tool.device import factory

    return factory.CanOptions.from_mapping(bus)


def default_lister(
    emulators: Sequence[str], can: Mapping[str, object] | None = None
) -> list[DeviceEntry]:
    """The valves connected over USB, the emulated ``emulators`` and, with ``can``, the nodes
    on that CAN bus."""
    from prm9tool.device import factory

    if can is None:
        return list(factory.list_devices(emulators))
    return list(factory.list_devices(emulators, can_options(can)))


def default_opener(entry: object) -> ValveSession:
    """A session to ``entry`` (a listed valve or a device id)."""
    from prm9tool.device import factory

    assert isinstance(entry, factory.DeviceEntry | str)
    return factory.open_session(entry)


def list_in_thread(
    lister: Callable[..., Sequence[Listed]],
    emulators: Sequence[str],
    can: Mapping[str, object] | None,
    deliver: Callable[[list[Listed] | Exception], None],
) -> None:
    """``lister(emulators[, can])`` in a thread of its own; ``deliver`` gets the entries or the
    exception listing raised (e.g. a broken USB stack: the caller says so)."""
    specs = list(emulators)
    bus = dict(can) if can is not None else None

    def run() -> None:
        try:
            found: list[Listed] | Exception = list(
                lister(specs) if bus is None else lister(specs, bus)
            )
        except Exception as exc:
            found = exc
        # RuntimeError: the connection was deleted meanwhile, nobody is waiting
        with contextlib.suppress(RuntimeError):
            deliver(found)

    threading.Thread(target=run, name="valve-list", daemon=True).start()
