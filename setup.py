"""Build of the compiled control loop (everything else is declared in pyproject.toml).

The extension is optional: without a C compiler ``pip install`` still succeeds and the emulator
runs on the pure-Python reference loop (docs/emulator.md "Compiled kernel"). The flags keep
IEEE double arithmetic exactly as CPython evaluates it: no fast-math, no fused multiply-add.
"""

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

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
            ["prm9tool/device/emulator/_ckernel.c"],
            optional=True,  # no compiler: installs anyway, the Python loop runs
        )
    ],
    cmdclass={"build_ext": ExactFloatBuildExt},
)
