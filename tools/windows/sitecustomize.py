"""PYTHONPATH for the embeddable CPython of the Windows stage (tools/windows/ci.sh; not shipped).

The embeddable's ``python313._pth`` makes Python ignore ``PYTHONPATH``; the tests start
processes of their own with it set (e.g. the tests folder for a driver script), so its entries
are put on ``sys.path`` here, as a normal Python would.
"""

import os
import sys

for entry in reversed(os.environ.get("PYTHONPATH", "").split(os.pathsep)):
    if entry and entry not in sys.path:
        sys.path.insert(1, entry)
