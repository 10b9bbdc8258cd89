"""*.prm files: load+validate and save of a full E04 -CA file against configparser.

The baseline, measured in the same run, is the standard library's configparser reading and
writing the same text (keys and values only: no types, ranges, rules, checksum or fsync).

    .venv/bin/python benchmarks/bench_prm.py [--repeat 7] [--number 200] [--quick]

Then a file at the 1 MiB limit full of unknown names (issue 15 item 16): ``check_bytes`` with
the bounded spelling suggestions, with a suggestion for every unknown name (as before), and
configparser on the same text; and the worst case of a number (issue 25 item 20): a run of
nines ending in a letter, from 24 kB to the 1 MiB limit, against the old number rule.
``--quick`` is a smoke run (seconds): the small cases only.
"""

from __future__ import annotations

import argparse
import configparser
import io
import re
import statistics
import sys
import tempfile
import timeit
from collections.abc import Callable
from pathlib import Path

from prm9tool.catalogue import CATALOGUE
from prm9tool.catalogue.typekey import TypeKey
from prm9tool.errors import ValueRangeError
from prm9tool.files import prmcheck
from prm9tool.files.prmdocument import load_document, save_document
from prm9tool.files.prmfile import (
    MAX_FILE_SIZE,
    PrmContents,
    check_bytes,
    read_file,
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


def unknown_names_file() -> tuple[str, int]:
    """A valid file filled up to the size limit with unknown names, and how many."""
    text = PrmContents.factory(TypeKey.parse(TYPE_KEY)).to_text()
    lines = [line for line in text.split("\n") if line and not line.startswith("checksum")]
    size, count = len(text), 0
    while size < MAX_FILE_SIZE - 100:
        lines.append(f"LIMTAX{count:05d} = 1")
        size, count = size + len(lines[-1]) + 1, count + 1
    return "\n".join([*lines, "checksum = crc32:00000000", ""]), count


def bench_unknown_names() -> None:
    """``--check`` of a 1 MiB file of unknown names: bounded suggestions against unbounded."""
    text, count = unknown_names_file()
    data = text.encode("utf-8")
    bounded = per_call(lambda: check_bytes(data), 3, 1)
    limit = prmcheck.MAX_SUGGESTIONS
    prmcheck.MAX_SUGGESTIONS = count  # a suggestion for every unknown name
    try:
        unbounded = per_call(lambda: check_bytes(data), 1, 1)
    finally:
        prmcheck.MAX_SUGGESTIONS = limit
    baseline = per_call(lambda: config_parse(text), 3, 1)
    print(f"\n{len(data)} bytes, {count} unknown names (check_bytes)")
    print(
        f"  suggestions for the first {limit}: {bounded:7.2f} s = {bounded / baseline:5.1f}x configparser"
    )
    print(
        f"  a suggestion for every name: {unbounded:7.2f} s = {unbounded / baseline:5.1f}x configparser"
    )
    print(f"  configparser (keys and values only): {baseline:7.2f} s")


# the number rule before issue 25 item 20: correct, but quadratic on a failing long token
OLD_NUMBER = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")


def long_number_file(size: int) -> bytes:
    """A full file whose LIMTA is a run of nines ending in a letter, ``size`` bytes in all."""
    text = PrmContents.factory(TypeKey.parse(TYPE_KEY)).to_text()
    digits = size - len(text)
    return re.sub(r"(?m)^LIMTA = .*$", lambda _m: f"LIMTA = {'9' * digits}x", text).encode()


def bench_long_numbers(quick: bool) -> None:
    """The worst case of issue 25 item 20: check time against file size (linear now), and the
    number rule alone on a run of digits ending in a letter, old (quadratic) against new."""
    sizes = (24_000, 96_000) if quick else (24_000, 96_000, 384_000, MAX_FILE_SIZE - 1)
    print("\nA full file whose LIMTA is a run of nines ending in 'x' (check_bytes)")
    for size in sizes:
        data = long_number_file(size)
        now = per_call(lambda data=data: check_bytes(data), 1 if quick else 3, 1)
        print(f"  {size:>8} bytes: {now * 1000:8.1f} ms = {now / size * 1e9:6.1f} ns/byte")
    print("The number rule alone on n nines and an 'x': old regex (before), parse_display (now)")
    for digits in (500, 1000) if quick else (1000, 2000, 4000):
        token = "9" * digits + "x"
        old = per_call(lambda token=token: OLD_NUMBER.fullmatch(token), 1, 1)
        new = per_call(lambda token=token: _refused(token), 3, 10)
        print(f"  {digits:>6} digits: old {old * 1000:9.1f} ms, new {new * 1e6:7.1f} µs")


def _refused(token: str) -> bool:
    """The new rule, through the public parser (it refuses the token)."""
    try:
        CATALOGUE["LIMTA"].parse_display(token)
    except ValueRangeError:
        return True
    return False


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark and print the figures and ratios."""
    options = argparse.ArgumentParser(description="*.prm load/save against configparser")
    options.add_argument("--repeat", type=int, default=7)
    options.add_argument("--number", type=int, default=200)
    options.add_argument("--quick", action="store_true", help="a smoke run: seconds, not figures")
    args = options.parse_args(argv)
    if args.quick:
        args.repeat, args.number = 1, 3
    size = len(PrmContents.factory(TypeKey.parse(TYPE_KEY)).values)
    print(f"*.prm benchmark: {TYPE_KEY} ({size} parameters) against configparser")
    print(f"python {sys.version.split()[0]}, median of {args.repeat} x {args.number} calls\n")
    print(f"{'operation':<46}{'prm9tool':>12}{'baseline':>12}{'ratio':>8}")
    with tempfile.TemporaryDirectory() as directory:
        for name, ours, baseline in cases(Path(directory)):
            mine = per_call(ours, args.repeat, args.number)
            theirs = per_call(baseline, args.repeat, args.number)
            print(f"{name:<46}{mine * 1e6:>9.1f} µs{theirs * 1e6:>9.1f} µs{mine / theirs:>7.1f}x")
    if not args.quick:
        bench_unknown_names()
    bench_long_numbers(args.quick)
    return 0


if __name__ == "__main__":
    sys.exit(main())
