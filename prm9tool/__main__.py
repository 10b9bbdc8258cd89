"""``python -m prm9tool``."""

from __future__ import annotations

import sys

from prm9tool.cli.main import main

if __name__ == "__main__":
    sys.exit(main())
