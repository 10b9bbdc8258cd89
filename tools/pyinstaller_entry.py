"""The single executable's entry point: the same ``main`` as ``prm9tool`` and ``python -m prm9tool``."""

import sys

from prm9tool.cli.main import main

if __name__ == "__main__":
    sys.exit(main())
