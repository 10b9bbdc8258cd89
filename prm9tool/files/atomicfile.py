"""Atomic saving: moved to the leaf module :mod:`prm9tool.atomicfile` (issue 28), so that the
layers below the files (the remembered CANopen type keys of the catalogue) write as safely;
this name keeps working for the modules that import it from here."""

from prm9tool.atomicfile import (
    BACKUP_SUFFIX,
    atomic_write,
    remove_stale_temporaries,
    temporary_pattern,
)

__all__ = ["BACKUP_SUFFIX", "atomic_write", "remove_stale_temporaries", "temporary_pattern"]
