"""Build of the compiled control loop (everything else is declared in pyproject.toml).

The extension is optional: without a C compiler ``pip install`` still succeeds and the emulator
runs on the pure-Python reference loop (docs/emulator.md "Compiled kernel"). The flags keep
IEEE double arithmetic exactly as CPython evaluates it: no fast-math, no fused multiply-add.
"""

import hashlib
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = "prm9tool/device/emulator/_ckernel.c"
# The module carries the hash of its source: ckernel.py refuses a build older than the source
# in a working tree (an edited _ckernel.c that was not rebuilt).
SOURCE_HASH = hashlib.sha256((Path(__file__).parent / SOURCE).read_bytes()).hexdigest()[:16]

FLAGS = {
    "unix": ["-O2", "-ffp-contract=off", "-fno-fast-math", "-std=c99"],
    "mingw32": ["-O2", "-ffp-contract=off", "-fno-fast-math", "-std=c99"],
    "msvc": ["/O2", "/fp:precise"],  # /fp:precise never contracts to FMA unless /fp:contract
}


class ExactFloatBuildExt(build_ext):
    """Compiler flags for exact double arithmetic, per compiler family."""

    def build_extensions(self) -> None:
        flags = FLAGS.get(self.compiler.compiler_type, [])
        for ext in self.extensions:
            ext.extra_compile_args = flags
        super().build_extensions()


setup(
    ext_modules=[
        Extension(
            "prm9tool.device.emulator._ckernel",
            [SOURCE],
            define_macros=[("SOURCE_HASH", f'"{SOURCE_HASH}"')],
            optional=True,  # no compiler: installs anyway, the Python loop runs
        )
    ],
    cmdclass={"build_ext": ExactFloatBuildExt},
)
