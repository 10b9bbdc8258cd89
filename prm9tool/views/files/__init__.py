"""Parameter files: open/save dialogs, reading files off the GUI thread, DCF export."""
