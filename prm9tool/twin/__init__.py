"""A twin of each valve (issue 31): identify the emulator's plant constants from measured steps
(:mod:`.identify`) and keep them in a versioned TOML twin file (:mod:`.twinfile`).

No Qt. The package re-exports nothing eagerly (docs/ARCHITECTURE.md).
"""
