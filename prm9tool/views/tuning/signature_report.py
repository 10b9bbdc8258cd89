"""The drift report in the program language: its table, its sentence, its plots and its PDF.

What :class:`prm9tool.characterize.drift.DriftReport` holds, as the Tuning window's "Birth
certificate" page and ``--signature --report OUT.pdf`` show it: each figure today, at the birth
certificate, the change and its drift limit with the verdict; today's steps and Bode drawn over
the birth certificate's (when its record kept them: recorded since issue 31).
"""

from __future__ import annotations

import html
import math
import os
import re
import tempfile
from pathlib import Path

import numpy as np
from PySide6.QtCore import QCoreApplication, QUrl
from PySide6.QtGui import QTextDocument
from PySide6.QtPrintSupport import QPrinter

from prm9tool.characterize.drift import DriftItem, DriftReport, signed_change
from prm9tool.characterize.run import Figure
from prm9tool.views.paged_print import PageFrame, configure_pdf, print_paged
from prm9tool.views.record.document import signature_line
from prm9tool.views.tuning.plot import COLOURS, Plot, Series, plot_image
from prm9tool.views.tuning.report import (
    _local,
    date_text,
    ensure_app,
    figure_label,
    link_text,
    loop_name,
    profile_name,
)

translate = QCoreApplication.translate


def _label(item: DriftItem) -> str:
    """The figure's name in the program language, a step down with its minus sign."""
    text = figure_label(Figure(item.name, item.label, item.today, item.unit, None))
    return re.sub(r"(?<=\s)-(?=\d)", "−", text)


def value_text(value: float | None, unit: str, above: bool = False) -> str:
    """A figure's value with its unit (times in ms) in the program language; ``—`` for none."""
    if value is None:
        return "—"
    if math.isnan(value):
        return translate("SignatureReport", "not reached")
    text = f"{value * 1000:.3g} ms" if unit == "s" else f"{value:.3g} {unit}".strip()
    if above:
        return translate("SignatureReport", "above %1").replace("%1", _local(text))
    return _local(text)


def change_text(item: DriftItem) -> str:
    """``−19 %`` (Hz, s), ``+0,8 pp`` (figures in %), ``−0,040`` (the gain); ``—``."""
    if item.reference is None or not math.isfinite(item.change):
        return "—"
    if item.today_above or item.reference_above:
        return "—"
    if item.unit and item.unit != "%" and not math.isfinite(item.relative_pct):
        return "—"
    number, kind = signed_change(item)
    if kind == "pp":  # the unit after localizing: a Czech "p. b." keeps its points
        return f"{_local(number)} " + translate("SignatureReport", "pp")
    return _local(f"{number} {kind}".strip())


def limit_text(item: DriftItem) -> str:
    """The drift limit (``± 15 %``, ``± 0,5 pp``) or ``—`` (not judged)."""
    limit = item.limit
    if limit is None:
        return "—"
    parts = []
    if limit.relative is not None:
        parts.append(_local(f"± {limit.relative:g} %"))
    if limit.absolute is not None:
        if item.unit == "s":
            parts.append(_local(f"± {limit.absolute * 1000:g} ms"))
        else:
            unit = translate("SignatureReport", "pp") if item.unit == "%" else item.unit
            parts.append(f"{_local(f'± {limit.absolute:g}')} {unit}".strip())
    return ", ".join(parts)


def verdict_text(drifted: bool | None) -> str:
    """DRIFTED / within / not judged."""
    if drifted is None:
        return translate("SignatureReport", "not judged")
    return (
        translate("SignatureReport", "DRIFTED")
        if drifted
        else translate("SignatureReport", "within")
    )


def since_text(report: DriftReport) -> str:
    """``the end-of-line test on 20.11.2026 09:12 UTC`` in the program language."""
    ref = report.reference
    when = date_text(ref.date)
    if ref.end_of_line:
        return translate("SignatureReport", "the end-of-line test on %1").replace("%1", when)
    return translate("SignatureReport", "the first characterization on %1").replace("%1", when)


def summary_text(report: DriftReport) -> str:
    """The verdict and, in words and figures, each figure that drifted: "Drifted since the
    end-of-line test on …: −3 dB frequency 24.1 Hz, was 29.7 Hz: −19 %; …"."""
    since = since_text(report)
    if report.passed:
        return translate("SignatureReport", "No figure drifted beyond its limit since %1.").replace(
            "%1", since
        )
    parts = []
    for item in report.drifted:
        part = translate("SignatureReport", "%1 %2, was %3").replace("%1", _label(item)).replace(
            "%2", value_text(item.today, item.unit, item.today_above)).replace(
            "%3", value_text(item.reference, item.unit, item.reference_above))  # fmt: skip
        change = change_text(item)
        parts.append(part if change == "—" else f"{part}: {change}")
    return (
        translate("SignatureReport", "Drifted since %1: %2.").replace("%1", since).replace("%2", "; ".join(parts))
    )  # fmt: skip


def table_rows(report: DriftReport) -> list[tuple[str, str, str, str, str, str, bool | None]]:
    """(figure, today, birth certificate, change, drift limit, verdict, drifted) per figure,
    the drifted first."""
    order = sorted(report.items, key=lambda i: {True: 0, False: 1, None: 2}[i.drifted])
    return [
        (
            _label(i),
            value_text(i.today, i.unit, i.today_above),
            value_text(i.reference, i.unit, i.reference_above),
            change_text(i),
            limit_text(i),
            verdict_text(i.drifted),
            i.drifted,
        )
        for i in order
    ]


def headers() -> list[str]:
    """The table's column titles."""
    return [
        translate("SignatureReport", "Figure"),
        translate("SignatureReport", "Today"),
        translate("SignatureReport", "Birth certificate"),
        translate("SignatureReport", "Change"),
        translate("SignatureReport", "Drift limit"),
        translate("SignatureReport", "Result"),
    ]


# --- plots ----------------------------------------------------------------------------------
def _array(values: list[float | None]) -> np.ndarray:
    return np.array([math.nan if v is None else v for v in values], dtype=float)


def step_plots(report: DriftReport) -> list[Plot]:
    """One plot per step size: today's step up, today's step down mirrored (×−1, so an
    asymmetry shows) and the birth certificate's step up (dashed) where its record kept one."""
    from prm9tool.characterize.frame import LOOPS

    lp = LOOPS[report.today.loop]
    kept = {}
    for step in (report.reference.curves or {}).get("steps", []):
        kept[float(step.get("amplitude_pct", math.nan))] = step
    sizes = sorted({abs(s.amplitude_pct) for s in report.today.steps})
    plots = []
    for size in sizes:
        up = [s for s in report.today.steps if s.amplitude_pct == size]
        down = [s for s in report.today.steps if s.amplitude_pct == -size]
        series = []  # drawn in order: the birth certificate and the step down beneath today's
        old = kept.get(size)
        if old is not None:
            t_old, y_old = _array(old["t"]) * 1000, _array(old["actual"])
            label = translate("SignatureReport", "birth certificate")
            series.append(Series(t_old, y_old, label, COLOURS[3], True))
        for step in down[:1]:
            t, y = step.record.t * 1000, -step.record.channels[lp.actual]
            label = translate("SignatureReport", "today, step down ×−1")
            series.append(Series(t, y, label, COLOURS[4]))
        for step in up[:1]:
            t, ch = step.record.t * 1000, step.record.channels
            label = translate("SignatureReport", "setpoint")
            series.append(Series(t, ch[lp.setpoint], label, COLOURS[0], True))
            series.append(
                Series(t, ch[lp.actual], translate("SignatureReport", "today"), COLOURS[1])
            )
        title = translate("SignatureReport", "Step response ±%1 %").replace(
            "%1", _local(f"{size:g}")
        )
        plots.append(Plot(title, translate("SignatureReport", "time [ms]"), "%", series))
    return plots


def bode_plots(report: DriftReport) -> list[Plot]:
    """Magnitude and phase today, the birth certificate's under them (dashed)."""
    bode = report.today.bode
    if bode is None:
        return []
    r = bode.response
    ok = r.reliable()  # the points the figures were found on (coherent enough)
    hz = translate("SignatureReport", "frequency [Hz]")
    today = translate("SignatureReport", "today")
    magnitude = [Series(r.frequency[ok], r.magnitude_db[ok], today, COLOURS[1])]
    phase = [Series(r.frequency[ok], r.phase_deg[ok], today, COLOURS[1])]
    old = (report.reference.curves or {}).get("bode")
    if old:
        f = _array(old["frequency"])
        label = translate("SignatureReport", "birth certificate")
        magnitude.append(Series(f, _array(old["magnitude_db"]), label, COLOURS[3], True))
        phase.append(Series(f, _array(old["phase_deg"]), label, COLOURS[3], True))
    return [
        Plot(translate("SignatureReport", "Frequency response: magnitude"), hz, "dB", magnitude,
             logx=True, hlines=[(-3.0, "")]),
        Plot(translate("SignatureReport", "Frequency response: phase"), hz, "°", phase, logx=True,
             hlines=[(-90.0, "")]),
    ]  # fmt: skip


def plots(report: DriftReport) -> list[Plot]:
    """The steps (the largest up and down and the smallest up) and the Bode."""
    steps = step_plots(report)
    return steps + bode_plots(report)


def no_curves_note(report: DriftReport) -> str:
    """What the plots lack when the birth certificate's record kept no curves ("" otherwise)."""
    if report.reference.curves:
        return ""
    return translate(
        "SignatureReport",
        "The birth certificate's record keeps its figures but not its curves (recorded by an "
        "older prm9tool): the plots show today's only.",
    )


# --- PDF -------------------------------------------------------------------------------------
def build_document(report: DriftReport) -> QTextDocument:
    """The drift report as a text document (its plots as resources)."""
    e = html.escape
    c, ref = report.today, report.reference
    doc = QTextDocument()
    doc.setDocumentMargin(0)
    rows = [
        (translate("SignatureReport", "Type key"), c.info.type_key),
        (translate("SignatureReport", "Serial number"), str(c.info.serial)),
        (translate("SignatureReport", "Firmware"), c.info.firmware),
        (translate("SignatureReport", "Date"), date_text(c.date)),
        (translate("SignatureReport", "Link"), f"{link_text(c.info.link)}, {_local(f'{c.info.sample_rate_hz:g}')} Hz"),
        (translate("SignatureReport", "Loop tested"), loop_name(c.loop)),
        (translate("SignatureReport", "Birth certificate"), since_text(report)),
        (translate("SignatureReport", "Drift limits"), profile_name(c.profile.name)),
        (translate("SignatureReport", "Motion"), _local(f"{report.plan.motion_s:.1f} s")),
        (translate("SignatureReport", "Result"), translate("SignatureReport", "no drift") if report.passed
         else translate("SignatureReport", "DRIFTED")),
    ]  # fmt: skip
    rows += [(translate("SignatureReport", "Limited by the link"), str(n)) for n in c.notes]
    head = "".join(f"<tr><td><b>{e(k)}</b></td><td>{e(v)}</td></tr>" for k, v in rows)
    title = e(translate("SignatureReport", "PRM9 field signature and drift report"))
    body = [f"<h2>{title}</h2><table cellpadding='2'>{head}</table>",
            f"<p><b>{e(summary_text(report))}</b></p>"]  # fmt: skip
    cells = "".join(f"<th align='left'>{e(h)}</th>" for h in headers())
    lines = []
    for *texts, drifted in table_rows(report):
        colour = {True: "#c0392b", False: "#1a7f37", None: "#555555"}[drifted]
        tds = "".join(f"<td>{e(str(t))}</td>" for t in texts[:-1])
        lines.append(f"<tr>{tds}<td style='color:{colour}'><b>{e(str(texts[-1]))}</b></td></tr>")
    body.append(f"<table cellpadding='2'><tr>{cells}</tr>{''.join(lines)}</table>")
    if note := no_curves_note(report):
        body.append(f"<p>{e(note)}</p>")
    for k, plot in enumerate(plots(report)):
        url = f"prm9tool://signature{k}.png"
        doc.addResource(QTextDocument.ResourceType.ImageResource, QUrl(url), plot_image(plot))
        body.append(f'<p><img src="{url}" width="520"></p>')
    del ref
    doc.setHtml("".join(body) + signature_line())
    return doc


def write_signature_pdf(report: DriftReport, path: Path) -> None:
    """Write the drift report to ``path`` (complete or not at all; OSError if it cannot)."""
    ensure_app()
    doc = build_document(report)
    info = report.today.info
    subject = translate("SignatureReport", "{0} · serial number {1}").format(
        info.type_key, info.serial
    )
    frame = PageFrame(
        subject, translate("SignatureReport", "PRM9 drift report"), date_text(report.today.date)
    )
    fd, temporary = tempfile.mkstemp(suffix=".pdf", dir=path.parent)
    os.close(fd)
    try:
        printer = QPrinter(QPrinter.PrinterMode.HighResolution)
        configure_pdf(printer, Path(temporary), f"{info.type_key} {info.serial}")
        print_paged(doc, printer, frame)
        if os.path.getsize(temporary) == 0:
            raise OSError(f"cannot write {path}")
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
