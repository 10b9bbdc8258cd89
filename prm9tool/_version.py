"""The version of prm9tool, in one place (``pyproject.toml`` reads it: ``dynamic``).

A leaf module: the layers take ``__version__`` from here, never from the package's public
face ``prm9tool/__init__.py`` (the Python API's door, which reaches the device layer).
"""

__version__ = "0.1.0"
