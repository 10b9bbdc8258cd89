"""The main window's central area: one page per view (diagram, parameter list, oscilloscope),
a view built on first use, a view wider than a small screen scrolled."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from PySide6.QtWidgets import QScrollArea, QStackedWidget, QWidget

MAX_PAGE_WIDTH = 960  # the manual's minimum display is 1024 × 768


class PageStack(QStackedWidget):
    """The pages in the order of ``names``; ``views`` builds a missing view with ``build``."""

    def __init__(
        self, names: Sequence[str], build: Callable[[str], QWidget], parent: QWidget
    ) -> None:
        super().__init__(parent)
        self._names = tuple(names)
        self.views: dict[str, QWidget] = _LazyViews(build)
        self._pages: dict[str, QWidget] = {}

    def add(self, name: str, view: QWidget) -> None:
        """Put ``view`` in as the page ``name``."""
        self.views[name] = view
        self._pages[name] = _page(view)
        self.insertWidget(self._names.index(name), self._pages[name])

    def show_page(self, name: str) -> None:
        """Show the page ``name``, building its view on first use."""
        self.views[name]  # builds the view on first use
        self.setCurrentWidget(self._pages[name])

    def current_name(self) -> str:
        """Name of the page shown."""
        current = self.currentWidget()
        return next(name for name, page in self._pages.items() if page is current)


class _LazyViews(dict[str, QWidget]):
    """The views by name; a view missing at first is built by ``build`` when asked for."""

    def __init__(self, build: Callable[[str], QWidget]) -> None:
        super().__init__()
        self._build = build

    def __missing__(self, name: str) -> QWidget:
        return self._build(name)


def _page(view: QWidget) -> QWidget:
    """A view as a page of the main area; a view wider than a 1024-pixel screen scrolls.

    The stack is as wide as its widest page, so one wide view would widen the whole window.
    """
    if view.minimumSizeHint().width() <= MAX_PAGE_WIDTH:
        return view
    area = QScrollArea()
    area.setWidgetResizable(True)
    area.setFrameShape(QScrollArea.Shape.NoFrame)
    area.setWidget(view)
    return area
