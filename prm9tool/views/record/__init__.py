"""The printed parameter record: the document and the actions that print or export it."""
