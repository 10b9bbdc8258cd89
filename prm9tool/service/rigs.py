"""The rig a test that moves the valve runs on, for an open session, and the end-of-line test
on it: what :class:`~prm9tool.service.valve.ValveService`'s characterize, autotune and
signature and the API's ``characterize`` share. No Qt.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from prm9tool.analysis.profile import Profile
    from prm9tool.characterize.rig import Rig
    from prm9tool.characterize.run import Characterization
    from prm9tool.device.session import ValveSession

__all__ = ["characterize_session", "profile_of", "session_rig"]


def characterize_session(
    session: ValveSession,
    profile: Profile | str | os.PathLike[str] | None,
    progress: Callable[[str], None] | None,
) -> Characterization:
    """The end-of-line test on an open session (the rig its link gives)."""
    from prm9tool.characterize.run import characterize as run

    chosen = profile_of(profile)
    with session_rig(session) as rig:
        return run(rig, chosen, progress)


@contextmanager
def session_rig(session: ValveSession) -> Iterator[Rig]:
    """The rig the tests that move the valve run on: the link's (a USB stream, CANopen SDO
    samples) or, for an emulated valve, the valve itself stepped as fast as the CPU allows
    (as ``--characterize --emulator`` does)."""
    from prm9tool.characterize.canrig import rig_for_session
    from prm9tool.characterize.rig import EmulatorRig

    if session.emulator is None:
        yield rig_for_session(session)
        return
    from prm9tool.device.emulated_valves import emulated_valve, stepped_here

    with stepped_here(emulated_valve(session.info.type_key, session.info.serial)) as valve:
        yield EmulatorRig(valve)


def profile_of(profile: Profile | str | os.PathLike[str] | None) -> Profile:
    """The acceptance profile: the default (None), the one given, or the file's."""
    from prm9tool.analysis.profile import DEFAULT, load_profile
    from prm9tool.analysis.profile import Profile as ProfileType

    if profile is None:
        return DEFAULT
    if isinstance(profile, ProfileType):
        return profile
    return load_profile(os.fspath(profile))
