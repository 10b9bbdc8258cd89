"""The parameter set being edited: the document, its undo stack, access levels, edit rules."""
