"""Issue 34 item 19: the German test report was in English ("Result: FAIL", "step 5 %:
overshoot", "not reached", PASS/FAIL) with decimal points, and the German "Ergebnis" column
of the autotune's table was cut off. Every generated text of the report, its plots' labels
and the tables are in the program language and its locale, in all three languages."""

from __future__ import annotations

import dataclasses
import re

import pytest
from pypdf import PdfReader

from prm9tool import i18n
from prm9tool.analysis.model import Targets
from prm9tool.analysis.profile import parse_profile
from prm9tool.characterize.acceptance import propose
from prm9tool.characterize.rig import EmulatorRig
from prm9tool.characterize.run import characterize
from prm9tool.device.emulator import EmulatedValve
from prm9tool.model.document import ParameterDocument
from prm9tool.views.tuning.plot import _number
from prm9tool.views.tuning.report import date_text, link_text, write_pdf
from prm9tool.views.tuning.window import TuningWindow

E02 = "PRM9-06.3Z11/30-24E02S02"
E04 = "PRM9-06.3Z11/30-24E04S02"
SHORT = {"process": {"test": {"step_amplitudes_pct": [90], "step_duration_s": 0.15}}}
EXPECTED = {  # language: words of the report that were English
    "de": ("Geprüfter Regelkreis", "Prozessregler (E04)", "Kennwerte", "Standard (eingebaut)",
           "Emulator (schneller als Echtzeit gerechnet)", "nicht erreicht: die Antwort endete",
           "NICHT BESTANDEN", "12.2026"),
    "cs": ("Zkoušená regulační smyčka", "procesní regulátor (E04)", "Hodnoty",
           "výchozí (vestavěný)", "emulátor (počítaný", "nedosaženo: odezva skončila",
           "NEVYHOVUJE", "12.2026"),
    "en": ("Loop tested", "process controller (E04)", "Figures", "default (built in)",
           "emulator (stepped faster than real time)", "not reached: the response ended",
           "FAIL", "12/"),
}  # fmt: skip


@pytest.fixture(scope="module")
def e04_report():
    return characterize(EmulatorRig(EmulatedValve(E04)), parse_profile(SHORT, "default"))


@pytest.fixture
def language(request, qapp):
    i18n.set_language(request.param)
    yield request.param
    i18n.set_language("en")


@pytest.mark.parametrize("language", ["de", "cs", "en"], indirect=True)
def test_the_report_is_in_the_program_language_with_its_decimal_separator(
    language, e04_report, tmp_path
):
    pdf = tmp_path / f"{language}.pdf"
    write_pdf(e04_report, pdf)
    text = " ".join(page.extract_text() for page in PdfReader(str(pdf)).pages)
    text = " ".join(text.split())
    for words in EXPECTED[language]:
        assert words in text, (words, text[:600])
    if language != "en":
        for english in ("Loop tested", "Figures", "not reached", "stepped faster", "PASS"):
            assert english not in text
        assert re.search(r" 5\d,\d % ", text)  # where the 90 % step ended, decimal comma
        assert _number(0.5) == "0,5" and _number(-2.5) == "−2,5"  # the plots' ticks


def test_the_link_and_the_date_are_written_as_the_language_writes_them(qapp):
    can = "CANopen node 10 (virtual can0), TPDO1 at the tool's SYNC, one sample per 1.7 ms"
    i18n.set_language("de")
    try:
        assert link_text(can) == (
            "CANopen-Knoten 10 (virtual can0), TPDO1 zum SYNC des Programms, ein Abtastwert je "
            "1,7 ms"
        )
        assert date_text("2026-12-02T00:13:05+00:00") == "02.12.2026 00:13 UTC"
        assert link_text("USB") == "USB"
    finally:
        i18n.set_language("en")


def test_the_autotune_table_shows_every_column_in_german(qtbot):
    i18n.set_language("de")
    try:
        w = TuningWindow(ParameterDocument(E02))
        qtbot.addWidget(w)
        w.show()
        profile = parse_profile({"test": {"step_amplitudes_pct": [25], "static_period_s": 4}})
        rig = EmulatorRig(EmulatedValve(E02))
        w.autotune.show_result(
            propose(rig, "model", "position", Targets(10, 0.04), 50, 60, profile)
        )
        qtbot.waitExposed(w)
        table = w.autotune.table
        assert table.horizontalHeaderItem(4).text() == "Ergebnis"
        assert table.horizontalScrollBar().maximum() == 0  # "Ergebnis" was cut off
        assert table.item(0, 4).text() in ("BESTANDEN", "NICHT BESTANDEN")
    finally:
        i18n.set_language("en")


def test_the_frequency_response_page_writes_numbers_as_german_does(qtbot, monkeypatch):
    """ "Sinus-Sweep 0.2 … 20 Hz" and "−3 dB: 3.8 Hz" had decimal points in German; on the
    process loop the sweep's range is the loop's (0.2 … 20 Hz), not the spool's 1 … 200 Hz."""
    from prm9tool.characterize.procedures import bode_test

    i18n.set_language("de")
    try:
        w = TuningWindow(ParameterDocument(E04))  # control mode 4: the process loop
        qtbot.addWidget(w)
        said: list[str] = []
        monkeypatch.setattr(w, "start", lambda kind, what, *a: said.append(what))
        w.bode.run()
        assert "0,2 … 20 Hz" in said[0], said
        result = bode_test(EmulatorRig(EmulatedValve(E04)), 10.0, 0.0, 0.2, 20.0, 6.0, "process")
        w.bode.show_result(result)
        text = w.bode.result.text()
        assert re.fullmatch(r"−3 dB: \d+,\d Hz, −90°: \d+,\d Hz\.", text), text
    finally:
        i18n.set_language("en")


def test_the_command_lines_report_is_in_the_systems_language(tmp_path):
    """`--characterize --report` wrote English whatever the language; it now writes the PDF in
    the program language the GUI would start in (the system's), the JSON staying English."""
    import json
    import os
    import subprocess
    import sys

    profile = tmp_path / "short.toml"
    profile.write_text(
        "[test]\nstep_amplitudes_pct = [25]\nbode_duration_s = 1\nbode_f_min_hz = 2\n"
        "bode_f_max_hz = 50\nstatic_period_s = 1\n",
        encoding="utf-8",
    )
    pdf, js = tmp_path / "de.pdf", tmp_path / "de.json"
    env = dict(os.environ, LANG="de_DE.UTF-8", LC_ALL="de_DE.UTF-8", QT_QPA_PLATFORM="offscreen")
    args = [sys.executable, "-m", "prm9tool", "--characterize", "--emulator", f"{E02}:35",
            "--profile", str(profile), "--report", str(pdf), "--json", str(js)]  # fmt: skip
    run = subprocess.run(args, env=env, capture_output=True, text=True, timeout=300)
    assert pdf.exists(), run.stderr
    text = " ".join(" ".join(p.extract_text() for p in PdfReader(str(pdf)).pages).split())
    assert "PRM9-Prüfbericht" in text and "Geprüfter Regelkreis" in text, text[:300]
    assert json.loads(js.read_text(encoding="utf-8"))["loop"] == "position"


def test_the_autotunes_verdict_names_the_built_in_profile_in_the_language(qtbot):
    from prm9tool.analysis.profile import DEFAULT

    i18n.set_language("de")
    try:
        w = TuningWindow(ParameterDocument(E02))
        qtbot.addWidget(w)
        profile = parse_profile({"test": {"step_amplitudes_pct": [25], "static_period_s": 4}}, "x")
        profile = dataclasses.replace(profile, name=DEFAULT.name)
        rig = EmulatorRig(EmulatedValve(E02))
        w.autotune.show_result(
            propose(rig, "model", "position", Targets(10, 0.04), 50, 60, profile)
        )
        assert "„Standard (eingebaut)“" in w.autotune.result.text()  # was „default“
    finally:
        i18n.set_language("en")
