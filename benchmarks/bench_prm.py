"""*.prm files: load+validate and save of a full E04 -CA file against configparser.

The baseline, measured in the same run, is the standard library's configparser reading and
writing the same text (keys and values only: no types, ranges, rules, checksum or fsync).

    .venv/bin/python benchmarks/bench_prm.py [--repeat 7] [--number 200]
"""

from __future__ import annotations

import argparse
import configparser
import io
import statistics
import sys
import tempfile
import timeit
from collections.abc import Callable
from pathlib import Path

from prm9tool.catalogue.typekey import TypeKey
from prm9tool.files.prmfile import (
    PrmContents,
    check_bytes,
    load_document,
    read_file,
    save_document,
    write_file,
)

TYPE_KEY = "PRM9-06.3Z11/30-24E04S02-CA"


def per_call(func: Callable[[], object], repeat: int, number: int) -> float:
    """Median time of one call in seconds."""
    return statistics.median(timeit.repeat(func, repeat=repeat, number=number)) / number


def config_parse(text: str) -> configparser.ConfigParser:
    """The baseline reader: configparser with case-sensitive keys and inline # comments."""
    parser = configparser.ConfigParser(inline_comment_prefixes=("#",), interpolation=None)
    parser.optionxform = str  # type: ignore[assignment, method-assign]
    parser.read_string("[prm]\n" + text)
    return parser


def config_write(parser: configparser.ConfigParser, path: Path) -> None:
    """The baseline writer: configparser to a plain file (no temporary file, no fsync)."""
    with open(path, "w", encoding="utf-8") as stream:
        parser.write(stream)


Case = tuple[str, Callable[[], object], Callable[[], object]]


def cases(directory: Path) -> list[Case]:
    """(name, prm9tool operation, configparser baseline) on a full E04 -CA file."""
    contents = PrmContents.factory(TypeKey.parse(TYPE_KEY))
    contents.serial, contents.firmware = 1234567, "V0.35.16"
    text = contents.to_text()
    data = text.encode("utf-8")
    path, base_path = directory / "valve.prm", directory / "baseline.ini"
    path.write_bytes(data)
    parser = config_parse(text)
    doc = load_document(path)

    def baseline_load() -> object:
        return config_parse(path.read_text(encoding="utf-8"))

    def baseline_save() -> None:
        config_write(parser, base_path)

    return [
        ("parse+validate text (check_bytes)", lambda: check_bytes(data), lambda: config_parse(text)),
        ("load+validate file (read_file)", lambda: read_file(path), baseline_load),
        ("load into a document (load_document)", lambda: load_document(path), baseline_load),
        ("format text (to_text)", contents.to_text, lambda: parser.write(io.StringIO())),
        ("save: check+atomic+fsync+backup (write_file)", lambda: write_file(contents, path),
         baseline_save),
        ("save a document (save_document)", lambda: save_document(doc, path), baseline_save),
    ]  # fmt: skip


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark and print the figures and ratios."""
    options = argparse.ArgumentParser(description="*.prm load/save against configparser")
    options.add_argument("--repeat", type=int, default=7)
    options.add_argument("--number", type=int, default=200)
    args = options.parse_args(argv)
    size = len(PrmContents.factory(TypeKey.parse(TYPE_KEY)).values)
    print(f"*.prm benchmark: {TYPE_KEY} ({size} parameters) against configparser")
    print(f"python {sys.version.split()[0]}, median of {args.repeat} x {args.number} calls\n")
    print(f"{'operation':<46}{'prm9tool':>12}{'baseline':>12}{'ratio':>8}")
    with tempfile.TemporaryDirectory() as directory:
        for name, ours, baseline in cases(Path(directory)):
            mine = per_call(ours, args.repeat, args.number)
            theirs = per_call(baseline, args.repeat, args.number)
            print(f"{name:<46}{mine * 1e6:>9.1f} µs{theirs * 1e6:>9.1f} µs{mine / theirs:>7.1f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
