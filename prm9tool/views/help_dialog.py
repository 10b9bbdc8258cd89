"""Help: the program's own help pages (shipped HTML: the main page and one per topic — CAN
bus, tuning, compare, history), F1 in a window opening the page about it, the homepage, and
About with versions."""

from __future__ import annotations

import platform

from PySide6 import __version__ as pyside_version
from PySide6.QtCore import QCoreApplication, QEvent, QFile, Qt, QUrl, qVersion
from PySide6.QtGui import QDesktopServices, QKeySequence, QShortcut
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QTextBrowser,
    QVBoxLayout,
    QWidget,
)
from shiboken6 import Shiboken

from prm9tool._version import __version__
from prm9tool.buildinfo import build_info
from prm9tool.i18n import current_language
from prm9tool.views import resources_rc  # noqa: F401  (registers the :/help/ resources)

HELP_PREFIX = ":/help/"  # resources/help/, compiled into resources_rc
HOMEPAGE = "https://www.argo-hytos.com"


TOPICS = ("help", "can", "tuning", "compare", "history")  # help_en.html, can_en.html, …
_HELP: list[HelpWindow] = []  # the one help window, once made


def help_file(language: str, topic: str = "help") -> str:
    """The resource path of the page ``topic`` in ``language`` (English if there is none)."""
    path = f"{HELP_PREFIX}{topic}_{language}.html"
    return path if QFile.exists(path) else f"{HELP_PREFIX}{topic}_en.html"


def help_window(parent: QWidget | None = None) -> HelpWindow:
    """The program's one help window (made on first use, beside ``parent``'s window)."""
    window = _HELP[0] if _HELP else None
    if window is None or not Shiboken.isValid(window):  # deleted with the window it belonged to
        root = parent
        while root is not None and root.parentWidget() is not None:
            root = root.parentWidget()  # the main window, not a dialog closed (deleted) soon
        window = HelpWindow(root)
        _HELP[:] = [window]
    return window


def show_help(parent: QWidget | None = None, topic: str = "help") -> HelpWindow:
    """Show the help page ``topic`` (the main page by default) and bring it to the front."""
    window = help_window(parent)
    window.show_topic(topic)
    window.show()
    window.raise_()
    return window


show_help_page = show_help  # the name the main window uses beside its own show_help


def add_context_help(widget: QWidget, topic: str) -> QShortcut:
    """F1 in ``widget`` (a dialog or window) opens the help page ``topic``."""
    shortcut = QShortcut(QKeySequence(QKeySequence.StandardKey.HelpContents), widget)
    shortcut.setContext(Qt.ShortcutContext.WidgetWithChildrenShortcut)
    shortcut.activated.connect(lambda: show_help(widget, topic))
    return shortcut


class HelpWindow(QDialog):
    """Shows the local help pages; follows the program language."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.topic = "help"
        self.browser = QTextBrowser()
        self.browser.setOpenExternalLinks(True)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        buttons.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        layout.addWidget(self.browser)
        layout.addWidget(buttons)
        self.resize(760, 640)
        self.retranslate()

    def show_topic(self, topic: str) -> None:
        """Show the page ``topic`` (see :data:`TOPICS`) in the current language."""
        self.topic = topic if topic in TOPICS else "help"
        self.browser.setSource(QUrl("qrc" + help_file(current_language(), self.topic)))

    def retranslate(self) -> None:
        """Load the page in the current language."""
        self.setWindowTitle(self.tr("prm9tool help"))
        self.show_topic(self.topic)

    def changeEvent(self, event: QEvent) -> None:
        """Reload when the program language changes."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)


def open_homepage(parent: QWidget | None = None) -> bool:
    """Open the manufacturer's homepage in the browser; without one, say so and give the
    address (False)."""
    if QDesktopServices.openUrl(QUrl(HOMEPAGE)):
        return True
    from prm9tool.views import prompts

    prompts.inform(
        parent,
        prompts.Icon.Information,
        QCoreApplication.translate("Help", "Home page"),
        QCoreApplication.translate(
            "Help", "No web browser could be started. The home page is {0}"
        ).format(HOMEPAGE),
    )
    return False


def _version(package: str) -> str:
    from importlib import metadata  # slow to import; About is rare

    try:
        return metadata.version(package)
    except metadata.PackageNotFoundError:
        return "—"


def versions() -> list[tuple[str, str]]:
    """(component, version) of the program and what it runs on; the build's rows in the program
    language (German About read "built  unknown")."""
    info = build_info()

    def known(value: str) -> str:
        return QCoreApplication.translate("Help", "unknown") if value == "unknown" else value

    built = known(info.built)
    if info.frozen:
        built = QCoreApplication.translate("Help", "{0} (single executable)").format(built)
    return [
        ("prm9tool", __version__),
        (QCoreApplication.translate("Help", "commit"), known(info.commit)),
        (QCoreApplication.translate("Help", "built"), built),
        ("Python", platform.python_version()),
        ("Qt", qVersion()),
        ("PySide6", pyside_version),
        ("pyqtgraph", _version("pyqtgraph")),
        ("numpy", _version("numpy")),
        ("hidapi", _version("hidapi")),
        ("python-can", _version("python-can")),
        (platform.system(), platform.release()),
    ]


def about_html(title: str, description: str, licence: str) -> str:
    """The About text: description, versions, links."""
    rows = "".join(f"<tr><td>{name}</td><td>{version}</td></tr>" for name, version in versions())
    return (
        f"<h3>{title}</h3><p>{description}</p><table>{rows}</table>"
        f"<p>{licence}</p>"
        f"<p><a href='{HOMEPAGE}'>{HOMEPAGE}</a></p>"
    )
