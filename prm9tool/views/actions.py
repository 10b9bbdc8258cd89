"""Every action of the main window, its menus (manual §8.5) and its toolbar (manual §8.6)."""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication, QObject
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import QMenu, QMenuBar, QToolBar

from prm9tool.i18n import LANGUAGE_NAMES, LANGUAGES
from prm9tool.views.icons import icon

SK = QKeySequence.StandardKey
_ACTIONS: tuple[tuple[str, str, object], ...] = (
    # name, icon, shortcut (StandardKey, text, a tuple of them, or None)
    ("new", "valve", SK.New),
    ("open", "open", SK.Open),
    ("save", "save", SK.Save),
    ("save_as", "save_as", (SK.SaveAs, "Ctrl+Shift+S")),  # Windows binds no SaveAs key
    ("save_copy", "", None),
    ("undo", "undo", SK.Undo),
    ("redo", "redo", ("Ctrl+Y", "Ctrl+Shift+Z")),
    ("print", "print", SK.Print),
    ("export_pdf", "pdf", "Ctrl+E"),
    ("export_dcf", "", None),
    ("export_eds", "", None),
    ("exit", "exit", (SK.Quit, "Ctrl+Q")),  # nor a Quit key
    ("view_diagram", "diagram", "Ctrl+1"),
    ("view_parameters", "parameters", "Ctrl+2"),
    ("view_scope", "scope", "Ctrl+3"),
    ("canopen", "canopen", "Ctrl+4"),
    ("od_browser", "", None),
    ("level_basic", "", None),
    ("level_expert", "", None),
    ("change_password", "", None),
    ("valve_selection", "valve", "Ctrl+T"),
    ("valve_status", "status", "Ctrl+I"),
    ("upload", "upload", "Ctrl+U"),
    ("download", "download", "Ctrl+D"),
    ("store", "", None),
    ("restore_factory", "factory", None),
    ("restart", "restart", None),
    ("verify_restart", "", None),
    ("hid_configuration", "hid", "Ctrl+H"),
    ("can_bus", "canopen", None),
    ("can_trace", "", None),
    ("online", "online", "F5"),
    ("offline", "offline", "Shift+F5"),
    ("help", "help", SK.HelpContents),
    ("homepage", "homepage", None),
    ("about", "about", None),
    ("compare_file", "", None),
    ("compare_valve", "", None),
    ("history", "", None),
)
TOOLBAR = (
    "open",
    "save",
    "print",
    None,
    "online",
    "offline",
    "download",
    "upload",
    "restart",
    None,
    "valve_selection",
    "view_diagram",
    "view_parameters",
    "view_scope",
    "canopen",
)


translate = QCoreApplication.translate


@dataclass
class _Texts:
    text: str
    tip: str = ""


def _texts() -> dict[str, _Texts]:
    """Menu texts and status tips in the current language (a function so tr() runs late)."""
    return {
        "new": _Texts(
            translate("MainActions", "&New…"),
            translate("MainActions", "New parameter set from a valve type key"),
        ),
        "open": _Texts(
            translate("MainActions", "&Open…"),
            translate("MainActions", "Open a parameter file (*.prm)"),
        ),
        "save": _Texts(
            translate("MainActions", "&Save"),
            translate("MainActions", "Save the parameter file (*.prm)"),
        ),
        "save_as": _Texts(
            translate("MainActions", "Save &As…"),
            translate("MainActions", "Save the parameters under another name"),
        ),
        "save_copy": _Texts(
            translate("MainActions", "Save bac&kup copy…"),
            translate(
                "MainActions",
                "Save a copy of the parameters to another file; you keep working on this one",
            ),
        ),
        "undo": _Texts(
            translate("MainActions", "&Undo"), translate("MainActions", "Undo the last change")
        ),
        "redo": _Texts(
            translate("MainActions", "&Redo"),
            translate("MainActions", "Redo the change undone last"),
        ),
        "print": _Texts(
            translate("MainActions", "&Print…"),
            translate("MainActions", "Print the current parameter record"),
        ),
        "od_browser": _Texts(
            translate("MainActions", "Object &dictionary…"),
            translate("MainActions", "Read, and at Expert level write, any object of the valve"),
        ),
        "export_dcf": _Texts(
            translate("MainActions", "Export &DCF…"),
            translate(
                "MainActions",
                "Save the valve's CANopen configuration as a CiA 306 DCF (for a PLC configurator)",
            ),
        ),
        "export_eds": _Texts(
            translate("MainActions", "Expor&t EDS…"),
            translate("MainActions", "Save the valve type's CiA 306 EDS (for a PLC configurator)"),
        ),
        "export_pdf": _Texts(
            translate("MainActions", "&Export PDF…"),
            translate("MainActions", "Save the parameter record as PDF"),
        ),
        "exit": _Texts(
            translate("MainActions", "E&xit"), translate("MainActions", "Quit prm9tool")
        ),
        "view_diagram": _Texts(
            translate("MainActions", "&Flow diagram"),
            translate("MainActions", "Show the signal-flow diagram"),
        ),
        "view_parameters": _Texts(
            translate("MainActions", "&Parameter list"),
            translate("MainActions", "Show all parameters as a table"),
        ),
        "view_scope": _Texts(
            translate("MainActions", "&Oscilloscope"),
            translate("MainActions", "Show values in real time (online mode only)"),
        ),
        "canopen": _Texts(
            translate("MainActions", "&CANopen window…"),
            translate("MainActions", "CANopen settings of the valve"),
        ),
        "level_basic": _Texts(
            translate("MainActions", "&Basic"), translate("MainActions", "Basic parameter settings")
        ),
        "level_expert": _Texts(
            translate("MainActions", "&Expert…"),
            translate("MainActions", "All settings including controllers and linearization"),
        ),
        "change_password": _Texts(translate("MainActions", "&Change Expert password…")),
        "valve_selection": _Texts(
            translate("MainActions", "Valve &selection…"),
            translate("MainActions", "Choose the valve configuration by its type key"),
        ),
        "valve_status": _Texts(
            translate("MainActions", "Valve s&tatus…"),
            translate("MainActions", "State, firmware, serial number and errors of the valve"),
        ),
        "upload": _Texts(
            translate("MainActions", "&Upload to valve"),
            translate("MainActions", "Write the parameters into the valve"),
        ),
        "download": _Texts(
            translate("MainActions", "&Download from valve"),
            translate("MainActions", "Read the parameters of the valve into the program"),
        ),
        "store": _Texts(
            translate("MainActions", "St&ore in valve"),
            translate(
                "MainActions",
                "Make the values the valve works with permanent: they stay after a restart",
            ),
        ),
        "restore_factory": _Texts(
            translate("MainActions", "Restore &factory values…"),
            translate("MainActions", "Return the parameters to the factory values"),
        ),
        "restart": _Texts(
            translate("MainActions", "&Restart valve…"),
            translate(
                "MainActions",
                "Restart the valve electronics (only with the hydraulics disconnected)",
            ),
        ),
        "verify_restart": _Texts(
            translate("MainActions", "&Verify by restart…"),
            translate(
                "MainActions",
                "After an upload: restart the valve (hydraulics disconnected) and read back "
                "that it kept the values",
            ),
        ),
        "hid_configuration": _Texts(
            translate("MainActions", "&HID configuration…"),
            translate("MainActions", "Choose the valve to communicate with"),
        ),
        "can_bus": _Texts(
            translate("MainActions", "&CAN bus…"),
            translate(
                "MainActions", "Find the valves on a CAN bus and go online with one (CANopen)"
            ),
        ),
        "can_trace": _Texts(
            translate("MainActions", "CAN &trace…"),
            translate("MainActions", "Record the CAN bus, or read a trace file in words"),
        ),
        "online": _Texts(
            translate("MainActions", "O&nline mode"),
            translate("MainActions", "Connect to the valve"),
        ),
        "offline": _Texts(
            translate("MainActions", "O&ffline mode"),
            translate("MainActions", "Disconnect from the valve"),
        ),
        "help": _Texts(
            translate("MainActions", "&Help"), translate("MainActions", "How to use prm9tool")
        ),
        "homepage": _Texts(
            translate("MainActions", "Home&page"),
            translate("MainActions", "Open the manufacturer's homepage"),
        ),
        "compare_file": _Texts(
            translate("MainActions", "Co&mpare with file…"),
            translate(
                "MainActions", "Compare the parameters with a *.prm file, take chosen values"
            ),
        ),
        "compare_valve": _Texts(
            translate("MainActions", "&Compare with valve"),
            translate("MainActions", "Compare the document with the valve, apply chosen values"),
        ),
        "history": _Texts(
            translate("MainActions", "&History…"),
            translate("MainActions", "Every operation recorded on a valve's parameters"),
        ),
        "about": _Texts(
            translate("MainActions", "&About prm9tool"),
            translate("MainActions", "Versions and contact"),
        ),
    }


class MainActions(QObject):
    """Owns the QActions; ``actions[name]`` for every name in ``_ACTIONS``."""

    def __init__(self, parent: QObject) -> None:
        super().__init__(parent)
        self.actions: dict[str, QAction] = {}
        for name, icon_name, shortcut in _ACTIONS:
            action = QAction(icon(icon_name) if icon_name else icon(""), name, parent)
            action.setObjectName(f"action_{name}")
            action.setShortcuts(_key_sequences(shortcut))
            self.actions[name] = action
        self.view_group = self._group(("view_diagram", "view_parameters", "view_scope"))
        self.level_group = self._group(("level_basic", "level_expert"))
        self.language_actions: dict[str, QAction] = {}
        self.language_group = QActionGroup(self)
        for language in LANGUAGES:
            action = QAction(LANGUAGE_NAMES[language], parent)
            action.setObjectName(f"action_language_{language}")
            action.setCheckable(True)
            action.setData(language)
            self.language_group.addAction(action)
            self.language_actions[language] = action
        self.menus: dict[str, QMenu] = {}
        self.toolbar: QToolBar | None = None
        self._online = False

    def _group(self, names: tuple[str, ...]) -> QActionGroup:
        group = QActionGroup(self)
        for name in names:
            self.actions[name].setCheckable(True)
            group.addAction(self.actions[name])
        return group

    def __getitem__(self, name: str) -> QAction:
        return self.actions[name]

    def build_menus(self, bar: QMenuBar) -> None:
        """File, View, Valve, Communication, Help (manual §8.5)."""
        layout: dict[str, tuple[str | None, ...]] = {
            "file": ("new", "open", "recent", "save", "save_as", "save_copy", None, "undo",
                     "redo", None, "print", "export_pdf", "export_dcf", "export_eds", None,
                     "compare_file", None, "exit"),
            "view": ("view_diagram", "view_parameters", "view_scope", None, "access", "language",
                     None, "canopen", "od_browser"),
            "valve": ("valve_selection", "valve_status", None, "upload", "download", "store",
                      "compare_valve", "history", None, "restore_factory", "restart",
                      "verify_restart"),
            "communication": ("hid_configuration", "can_bus", "can_trace", None, "online", "offline"),
            "help": ("help", "homepage", None, "about"),
        }  # fmt: skip
        for menu_name, items in layout.items():
            menu = bar.addMenu(menu_name)
            menu.setObjectName(f"menu_{menu_name}")
            self.menus[menu_name] = menu
            for item in items:
                self._add_menu_item(menu, item)

    def _add_menu_item(self, menu: QMenu, item: str | None) -> None:
        if item is None:
            menu.addSeparator()
        elif item == "recent":
            self.menus["recent"] = menu.addMenu("recent")
        elif item == "access":
            sub = menu.addMenu("access")
            sub.addActions([self["level_basic"], self["level_expert"]])
            sub.addSeparator()
            sub.addAction(self["change_password"])
            self.menus["access"] = sub
        elif item == "language":
            sub = menu.addMenu("language")
            for language in ("de", "en", "cs"):  # the manual's order
                sub.addAction(self.language_actions[language])
            self.menus["language"] = sub
        else:
            menu.addAction(self[item])

    def build_toolbar(self, toolbar: QToolBar) -> None:
        """The toolbar of manual §8.6."""
        self.toolbar = toolbar
        toolbar.setObjectName("main_toolbar")
        for item in TOOLBAR:
            if item is None:
                toolbar.addSeparator()
            else:
                toolbar.addAction(self[item])

    def set_online(self, online: bool) -> None:
        """Tips of the actions that are off while online say why (the window disables them)."""
        self._online = online
        self.retranslate()

    def retranslate(self) -> None:
        """Set every text in the current language."""
        texts_of = _texts()
        if self._online:
            texts_of["hid_configuration"].tip = translate(
                "MainActions",
                "Not while online: go offline first, then choose the valve to communicate with",
            )
        for name, texts in texts_of.items():
            action = self.actions[name]
            action.setText(texts.text)
            action.setStatusTip(texts.tip)
            action.setToolTip(_tool_tip(texts, action))
        titles = {
            "file": translate("MainActions", "&File"),
            "view": translate("MainActions", "&View"),
            "valve": translate("MainActions", "V&alve"),
            "communication": translate("MainActions", "&Communication"),
            "help": translate("MainActions", "&Help"),
            "recent": translate("MainActions", "Open re&cent"),
            "access": translate("MainActions", "&Access level"),
            "language": translate("MainActions", "&Language"),
        }
        for name, title in titles.items():
            if name in self.menus:
                self.menus[name].setTitle(title)
        if self.toolbar is not None:
            self.toolbar.setWindowTitle(translate("MainActions", "Toolbar"))


def _key_sequences(shortcut: object) -> list[QKeySequence]:
    """The platform's keys of a StandardKey and explicit key texts, each key once."""
    specs = shortcut if isinstance(shortcut, tuple) else (shortcut,)
    keys: list[QKeySequence] = []
    for spec in specs:
        if isinstance(spec, SK):
            keys.extend(QKeySequence.keyBindings(spec))
        elif isinstance(spec, str):
            keys.append(QKeySequence(spec))
    return [key for i, key in enumerate(keys) if not key.isEmpty() and key not in keys[:i]]


def _tool_tip(texts: _Texts, action: QAction) -> str:
    label = texts.text.replace("&", "").rstrip("…")
    shortcut = action.shortcut().toString(QKeySequence.SequenceFormat.NativeText)
    tip = f"{label} ({shortcut})" if shortcut else label
    return f"{tip}\n{texts.tip}" if texts.tip else tip
