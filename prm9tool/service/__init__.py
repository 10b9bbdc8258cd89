"""The valve service: one implementation of each operation behind every front door.

The window (through ``online/``, the Qt adapter), the command line (``cli/``) and the Python
API (``api/``) open a valve's session and call the same functions here: one validation of a
user's value (:mod:`.values`), the upload sequence (:mod:`.upload`), the history as one
observer (:mod:`.history`), one owner of the valve's motion (:mod:`.motion`), EDS/DCF export
(:mod:`.export`) and the object that ties them to one open valve (:mod:`.valve`). No Qt
(import-linter contract). Re-exports nothing eagerly.
"""
