"""The compiled Qt resources (prm9tool/views/resources_rc.py) hold exactly what resources/ holds."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PySide6.QtCore import QDirIterator, QFile, QIODevice

from prm9tool.views import resources_rc  # noqa: F401  (registers the resources)

ROOT = Path(__file__).resolve().parent.parent / "resources"
COMMAND = (
    ".venv/bin/pyside6-rcc --format-version 1 --compress-algo zlib "
    "resources/prm9tool.qrc -o prm9tool/views/resources_rc.py"
)


def _listed() -> dict[str, Path]:
    """Resource path (``:/icons/app.svg``) -> source file, as prm9tool.qrc lists them."""
    listed = {}
    for group in ET.parse(ROOT / "prm9tool.qrc").getroot().iter("qresource"):
        for entry in group.iter("file"):
            name = entry.get("alias") or entry.text
            listed[f":{group.get('prefix')}/{name}"] = ROOT / entry.text
    return listed


def _compiled() -> set[str]:
    found = QDirIterator(":/", QDirIterator.IteratorFlag.Subdirectories)
    names = set()
    while found.hasNext():
        path = found.next()
        if QFile(path).size() and path.startswith((":/icons/", ":/help/")):
            names.add(path)
    return names


def test_every_file_of_resources_is_listed_in_the_qrc():
    on_disk = {p for p in ROOT.rglob("*") if p.is_file() and p.parent != ROOT}
    assert on_disk == set(_listed().values()), (
        f"list new files in resources/prm9tool.qrc, then: {COMMAND}"
    )


@pytest.mark.parametrize("resource", sorted(_listed()))
def test_the_compiled_resource_is_the_file_in_resources(resource):
    source = _listed()[resource]
    file = QFile(resource)
    assert file.open(QIODevice.OpenModeFlag.ReadOnly), f"{resource} is not compiled in: {COMMAND}"
    assert bytes(file.readAll().data()) == source.read_bytes(), f"{source} changed: {COMMAND}"


def test_nothing_else_is_compiled_in():
    assert _compiled() == set(_listed()), f"compiled resources differ from resources/: {COMMAND}"
