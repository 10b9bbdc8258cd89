"""Update the translation sources from the program's texts, then compile them.

    .venv/bin/python tools/update_translations.py            # lupdate + lrelease
    .venv/bin/python tools/update_translations.py --no-release

Runs the procedure of translations/README.md: pyside6-lupdate for German and Czech and, plural
forms only, for English; then keeps the committed style of the .ts files (tags indented one level
inside <TS>, apostrophes unescaped) so the diff shows only the messages that changed; then
pyside6-lrelease into prm9tool/translations/*.qm. New messages stay "unfinished" until they are
translated (pyside6-linguist); tests/test_gui_i18n.py fails meanwhile.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGETS = {"de": ["-target-language", "de_DE"], "cs": ["-target-language", "cs_CZ"],
           "en": ["-pluralonly", "-target-language", "en_US"]}  # fmt: skip
_TAG = re.compile(r"\s*<(?!\?xml|!DOCTYPE|TS[ >]|/TS>)")


def _tool(name: str) -> str:
    return str(Path(sys.executable).parent / name)


def restyle(path: Path) -> None:
    """Indent lupdate's output as the committed files are (text lines stay as they are)."""
    lines = path.read_text(encoding="utf-8").split("\n")
    lines = ["    " + line if _TAG.match(line) else line for line in lines]
    path.write_text("\n".join(lines).replace("&apos;", "'"), encoding="utf-8")


def main() -> int:
    """Update every .ts file (and compile it unless --no-release)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-release", action="store_true", help="do not compile the .qm files")
    args = parser.parse_args()
    listed = subprocess.run(["git", "ls-files", "prm9tool/*.py"], cwd=ROOT, check=True,
                            capture_output=True, text=True).stdout.split()  # fmt: skip
    # the compiled resources have no texts, and lupdate crashes on some of their byte strings
    listed = [name for name in listed if not name.endswith("resources_rc.py")]
    for language, options in TARGETS.items():
        ts = ROOT / "translations" / f"prm9tool_{language}.ts"
        subprocess.run([_tool("pyside6-lupdate"), *listed, "-no-obsolete", "-locations", "none",
                        *options, "-ts", str(ts)], cwd=ROOT, check=True)  # fmt: skip
        restyle(ts)
        if not args.no_release:
            qm = ROOT / "prm9tool" / "translations" / f"prm9tool_{language}.qm"
            # compiled beside it, then put in its place: a running prm9tool maps the .qm it
            # loaded into memory and died (SIGSEGV, SIGBUS) when lrelease rewrote it in place
            fresh = qm.with_suffix(".qm.new")
            subprocess.run([_tool("pyside6-lrelease"), str(ts), "-qm", str(fresh)], check=True)
            fresh.replace(qm)
    return 0


if __name__ == "__main__":
    sys.exit(main())
