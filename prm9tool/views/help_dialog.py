"""Help: the program's own help page (shipped HTML), the homepage, and About with versions."""

from __future__ import annotations

import platform

from PySide6 import __version__ as pyside_version
from PySide6.QtCore import QCoreApplication, QEvent, QFile, QUrl, qVersion
from PySide6.QtGui import QDesktopServices
from PySide6.QtWidgets import QDialog, QDialogButtonBox, QTextBrowser, QVBoxLayout, QWidget

from prm9tool import __version__
from prm9tool.buildinfo import build_info
from prm9tool.i18n import current_language
from prm9tool.views import resources_rc  # noqa: F401  (registers the :/help/ resources)

HELP_PREFIX = ":/help/"  # resources/help/, compiled into resources_rc
HOMEPAGE = "https://www.argo-hytos.com"


def help_file(language: str) -> str:
    """The resource path of the help page in ``language`` (English if there is none)."""
    path = f"{HELP_PREFIX}help_{language}.html"
    return path if QFile.exists(path) else f"{HELP_PREFIX}help_en.html"


class HelpWindow(QDialog):
    """Shows the local help page; follows the program language."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.browser = QTextBrowser()
        self.browser.setOpenExternalLinks(True)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        buttons.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        layout.addWidget(self.browser)
        layout.addWidget(buttons)
        self.resize(760, 640)
        self.retranslate()

    def retranslate(self) -> None:
        """Load the page in the current language."""
        self.setWindowTitle(self.tr("prm9tool help"))
        self.browser.setSource(QUrl("qrc" + help_file(current_language())))

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
    """(component, version) of the program and what it runs on."""
    info = build_info()
    return [
        ("prm9tool", __version__),
        ("commit", info.commit),
        ("built", info.built + (" (single executable)" if info.frozen else "")),
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
