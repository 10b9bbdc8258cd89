"""The link to a valve as the GUI sees it: connection, sync, polling, tuning simulator (QtCore)."""
