"""The characterization test report: one PDF per valve (QTextDocument → QPrinter PDF).

Header (type key, serial, firmware, date, link and its sample rate, profile, verdict), every
figure against its limit with pass/fail, the step responses at the profile's amplitudes, the
Bode plot, the static characteristic and the parameter set. The raw data go to CSV beside it
(:func:`prm9tool.characterize.run.write_csv_files`).
"""

from __future__ import annotations

import html
import math
import os
import re
import tempfile
from collections.abc import Mapping
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QDateTime, QLocale, Qt, QUrl
from PySide6.QtGui import QGuiApplication, QTextDocument
from PySide6.QtPrintSupport import QPrinter
from PySide6.QtWidgets import QApplication

from prm9tool.analysis.profile import Limit
from prm9tool.catalogue import CATALOGUE
from prm9tool.characterize.run import Characterization, Figure
from prm9tool.i18n import current_language, format_value
from prm9tool.messages import Message, localized_number
from prm9tool.translate import translated
from prm9tool.views.paged_print import PageFrame, configure_pdf, print_paged
from prm9tool.views.record.document import signature_line
from prm9tool.views.tuning.plot import COLOURS, Plot, Series, plot_image

translate = QCoreApplication.translate
_APP: list[QApplication] = []


def figure_label(figure: Figure) -> str:
    """The figure's name in the program language."""
    parts = figure.name.split("_")
    base = {
        "overshoot": translate("TuningReport", "overshoot"),
        "rise": translate("TuningReport", "rise time (10–90 %)"),
        "settling": translate("TuningReport", "settling time (±2 %)"),
        "bandwidth": translate("TuningReport", "−3 dB frequency"),
        "phase90": translate("TuningReport", "−90° frequency"),
        "gain": translate("TuningReport", "gain"),
        "hysteresis": translate("TuningReport", "hysteresis"),
        "linearity": translate("TuningReport", "linearity error"),
        "dead": translate("TuningReport", "dead band"),
    }
    if parts[0] == "flow":  # E04: actuator velocity over opening
        what = base.get(parts[1], figure.name)
        return translate("TuningReport", "flow characteristic: %1").replace("%1", what)
    if parts[0] == "step" and len(parts) > 3 and parts[3] in base:  # step_<from>_<to>_…
        start, end = (p.replace("-", "−") for p in parts[1:3])
        return (
            translate("TuningReport", "step %1 → %2 %: %3")
            .replace("%1", start)
            .replace("%2", end)
            .replace("%3", base[parts[3]])
        )
    if parts[0] == "step":
        what = base.get(parts[2], parts[2])
        return (
            translate("TuningReport", "step %1 %: %2").replace("%1", parts[1]).replace("%2", what)
        )
    return base.get(parts[1], figure.name)


def loop_name(loop: str) -> str:
    """The loop a test ran on, in the program language."""
    if loop == "process":
        return translate("TuningReport", "process controller (E04): process actual value")
    return translate("TuningReport", "position controller: spool position")


_CAN_LINK = re.compile(
    r"CANopen node (\d+) \((.*)\), (TPDO1 at the tool's SYNC|SDO polling), one sample per ([\d.]+) ms"
)


def link_text(link: str) -> str:
    """The rig's description of its link (English in the JSON and the history) in the program
    language: the emulator's, USB, or a CANopen node's with its sampling."""
    if link == "emulator (stepped faster than real time)":
        return translate("TuningReport", "emulator (stepped faster than real time)")
    found = _CAN_LINK.fullmatch(link)
    if found is None:
        return link
    node, bus, how, period = found.groups()
    how = (
        translate("TuningReport", "TPDO1 at the tool's SYNC")
        if how.startswith("TPDO1")
        else translate("TuningReport", "SDO polling")
    )
    return translate("TuningReport", "CANopen node {0} ({1}), {2}, one sample per {3} ms").format(
        node, bus, how, _local(period)
    )


def date_text(iso: str) -> str:
    """The run's date (ISO 8601 in the JSON) as the program language writes dates, in UTC:
    ``02.12.2026 00:13 UTC`` in German; an unreadable one as it is."""
    when = QDateTime.fromString(iso, Qt.DateFormat.ISODate)
    if not when.isValid():
        return iso
    locale, utc = QLocale(current_language()), when.toUTC()
    day = locale.dateFormat(QLocale.FormatType.ShortFormat)
    day = day if "yyyy" in day else day.replace("yy", "yyyy")  # the year in full
    hour = locale.timeFormat(QLocale.FormatType.ShortFormat)
    return f"{locale.toString(utc.date(), day)} {locale.toString(utc.time(), hour)} UTC"


def profile_name(name: str) -> str:
    """The built-in profile's name in the program language, a file's as it is."""
    return translate("TuningReport", "default (built in)") if name == "default" else name


def _text(note: object) -> str:
    return translated(note) if isinstance(note, Message) else str(note)


def verdict(passed: bool | None) -> str:
    """PASS / FAIL / — in the program language."""
    if passed is None:
        return "—"
    return translate("TuningReport", "PASS") if passed else translate("TuningReport", "FAIL")


def value_short(f: Figure) -> tuple[str, str]:
    """A table cell's text and tooltip: what was seen instead of a value goes to the tooltip
    ("not reached" in the cell), so the columns keep their width."""
    if math.isnan(f.value) and f.note is not None:
        return translate("TuningReport", "not reached"), translated(f.note)
    return value_text(f), ""


def value_text(f: Figure) -> str:
    """The figure's value with its unit (times in ms), with the program language's decimal
    separator (``5,75 %`` in German and Czech)."""
    if math.isnan(f.value):  # what it saw instead, e.g. an oscillation at 80 Hz
        return translate("TuningReport", "not reached") if f.note is None else translated(f.note)
    if f.above:  # not reached by the sweep's end
        return translate("TuningReport", "above {0}").format(_local(f"{f.value:.3g} {f.unit}"))
    if f.unit == "s":
        return _local(f"{f.value * 1000:.1f} ms")
    return _local(f"{f.value:.3g} {f.unit}".strip())


def limit_text(f: Figure) -> str:
    """The figure's limit with its unit (decimal separator as :func:`value_text`)."""
    if f.limit is None:
        return "—"
    if f.unit == "s":
        lo, hi = f.limit.minimum, f.limit.maximum
        in_ms = Limit(None if lo is None else lo * 1000, None if hi is None else hi * 1000)
        return _local(f"{in_ms.text()} ms")
    return _local(f"{f.limit.text()} {f.unit}".strip())


def _local(text: str) -> str:
    return localized_number(text, current_language())


def step_plot(c: Characterization, index: int) -> Plot:
    """One step response: setpoint and actual value over time."""
    step = c.steps[index]
    rec = step.record
    keys = list(rec.channels)
    return Plot(
        translate("TuningReport", "Step response %1 %").replace(
            "%1", _local(f"{step.amplitude_pct:g}")
        ),
        translate("TuningReport", "time [ms]"),
        "%",
        [
            Series(
                rec.t * 1000,
                rec.channels[keys[0]],
                translate("TuningReport", "setpoint"),
                COLOURS[0],
                True,
            ),
            Series(
                rec.t * 1000, rec.channels[keys[1]], translate("TuningReport", "actual"), COLOURS[1]
            ),
        ],
    )


def bode_plots(c: Characterization) -> tuple[Plot, Plot]:
    """Magnitude (dB) and phase (°) over frequency, −3 dB and −90° marked."""
    assert c.bode is not None
    r = c.bode.response
    hz = translate("TuningReport", "frequency [Hz]")
    magnitude = Plot(
        translate("TuningReport", "Frequency response ±%1 %: magnitude").replace(
            "%1", _local(f"{c.bode.amplitude_pct:g}")
        ),
        hz,
        "dB",
        [Series(r.frequency, r.magnitude_db, translate("TuningReport", "magnitude"), COLOURS[0])],
        logx=True,
        vlines=[(r.bandwidth_hz(), _local(f"−3 dB: {r.bandwidth_hz():.1f} Hz"))],
        hlines=[(-3.0, "")],
    )
    phase = Plot(
        translate("TuningReport", "Phase and coherence"),
        hz,
        "°",
        [Series(r.frequency, r.phase_deg, translate("TuningReport", "phase"), COLOURS[1]),
         Series(r.frequency, r.coherence * 100.0, translate("TuningReport", "coherence ×100"), COLOURS[2], True)],
        logx=True,
        vlines=[(r.phase_90_hz(), _local(f"−90°: {r.phase_90_hz():.1f} Hz"))],
    )  # fmt: skip
    return magnitude, phase


def static_plot(c: Characterization) -> Plot:
    """Actual value over demand, rising and falling branch, and the best straight line."""
    assert c.static is not None
    s = c.static.characteristic
    return Plot(
        translate("TuningReport", "Static characteristic"),
        translate("TuningReport", "demand [%]"),
        translate("TuningReport", "actual [%]"),
        [
            Series(s.x, s.up, translate("TuningReport", "rising"), COLOURS[0]),
            Series(s.x, s.down, translate("TuningReport", "falling"), COLOURS[1]),
            Series(
                s.x,
                s.gain * s.x + s.intercept,
                translate("TuningReport", "best line"),
                COLOURS[2],
                True,
            ),
        ],
    )


def flow_plot(c: Characterization) -> Plot:
    """E04: the actuator's velocity over the spool's opening (binned means)."""
    assert c.flow is not None
    f = c.flow.characteristic
    return Plot(
        translate("TuningReport", "Flow characteristic"),
        translate("TuningReport", "spool opening [%]"),
        translate("TuningReport", "actuator velocity [%/s]"),
        [Series(f.x, f.velocity, translate("TuningReport", "measured"), COLOURS[0])],
    )


def build_report(c: Characterization) -> QTextDocument:
    """The report as a text document (its images as resources)."""
    doc = QTextDocument()
    doc.setDocumentMargin(0)
    plots: list[Plot] = [step_plot(c, k) for k in range(len(c.steps))]
    if c.bode is not None:
        plots.extend(bode_plots(c))
    if c.static is not None:
        plots.append(static_plot(c))
    if c.flow is not None:
        plots.append(flow_plot(c))
    images = []
    for k, plot in enumerate(plots):
        url = f"prm9tool://plot{k}.png"
        doc.addResource(QTextDocument.ResourceType.ImageResource, QUrl(url), plot_image(plot))
        images.append(f'<p><img src="{url}" width="520"></p>')
    doc.setHtml(_header(c) + _figures(c) + "".join(images) + _parameters(c) + signature_line())
    return doc


def report_frame(c: Characterization) -> PageFrame:
    """What each page of the report repeats: the valve, the title, the date."""
    subject = translate("TuningReport", "{0} · serial number {1}").format(
        c.info.type_key, c.info.serial
    )
    return PageFrame(subject, translate("TuningReport", "PRM9 test report"), date_text(c.date))


def _header(c: Characterization) -> str:
    e = html.escape
    rows = [
        (translate("TuningReport", "Type key"), c.info.type_key),
        (translate("TuningReport", "Serial number"), str(c.info.serial)),
        (translate("TuningReport", "Firmware"), c.info.firmware),
        (translate("TuningReport", "Date"), date_text(c.date)),
        (
            translate("TuningReport", "Link"),
            f"{link_text(c.info.link)}, {_local(f'{c.info.sample_rate_hz:g}')} Hz",
        ),
        (translate("TuningReport", "Loop tested"), loop_name(c.loop)),
        (translate("TuningReport", "Acceptance profile"), profile_name(c.profile.name)),
        (translate("TuningReport", "Result"), verdict(c.passed)),
    ]
    rows += [(translate("TuningReport", "Limited by the link"), _text(n)) for n in c.notes]
    body = "".join(f"<tr><td><b>{e(k)}</b></td><td>{e(v)}</td></tr>" for k, v in rows)
    title = e(translate("TuningReport", "PRM9 test report"))
    return f"<h2>{title}</h2><table cellpadding='2'>{body}</table>"


def _figures(c: Characterization) -> str:
    e = html.escape
    head = [
        translate("TuningReport", "Figure"),
        translate("TuningReport", "Value"),
        translate("TuningReport", "Limit"),
        translate("TuningReport", "Result"),
    ]
    rows = []
    for f in c.figures:
        colour = {True: "#1a7f37", False: "#c0392b", None: "#555555"}[f.passed]
        rows.append(
            f"<tr><td>{e(figure_label(f))}</td><td>{e(value_text(f))}</td><td>{e(limit_text(f))}</td>"
            f"<td style='color:{colour}'><b>{e(verdict(f.passed))}</b></td></tr>"
        )
    heading = "".join(f"<th align='left'>{e(h)}</th>" for h in head)
    title = translate("TuningReport", "Figures")
    return f"<h3>{e(title)}</h3><table cellpadding='2'><tr>{heading}</tr>{''.join(rows)}</table>"


def parameter_rows(parameters: Mapping[str, int | str]) -> list[tuple[str, str]]:
    """(mnemonic, value with its unit) in display units, in catalogue order: what a customer
    reads (the raw 2458 of DTAMP is 15 %)."""
    rows = []
    for param in CATALOGUE:
        if param.mnemonic in parameters:
            raw = parameters[param.mnemonic]
            rows.append((param.mnemonic, f"{format_value(param, raw)} {param.unit}".strip()))
    return rows


def _parameters(c: Characterization) -> str:
    items = parameter_rows(c.parameters)
    third = (len(items) + 2) // 3
    columns = [items[k * third : (k + 1) * third] for k in range(3)]
    rows = []
    for i in range(third):
        cells = []
        for column in columns:
            name, value = column[i] if i < len(column) else ("", "")
            cells.append(
                f"<td>{html.escape(name)}</td><td align='right'>{html.escape(value)}</td>"
                "<td width='12'></td>"
            )
        rows.append(f"<tr>{''.join(cells)}</tr>")
    title = html.escape(translate("TuningReport", "Parameter set"))
    return f"<h3>{title}</h3><table cellpadding='1' style='font-size:7pt'>{''.join(rows)}</table>"


def ensure_app() -> None:
    """An application object for painting text (offscreen when none runs: headless lines).

    A QApplication, not a QGuiApplication: a later GUI in the same process (tests) needs one.
    """
    if QGuiApplication.instance() is None:
        os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
        _APP.append(QApplication(["prm9tool"]))


def write_pdf(c: Characterization, path: Path) -> None:
    """Write the report to ``path`` (complete or not at all; OSError if it cannot be written)."""
    ensure_app()
    doc = build_report(c)
    fd, temporary = tempfile.mkstemp(suffix=".pdf", dir=path.parent)
    os.close(fd)
    try:
        printer = QPrinter(QPrinter.PrinterMode.HighResolution)
        configure_pdf(printer, Path(temporary), f"{c.info.type_key} {c.info.serial}")
        print_paged(doc, printer, report_frame(c))
        if os.path.getsize(temporary) == 0:
            raise OSError(f"cannot write {path}")
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)  # mkstemp made it private; a report is not
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
