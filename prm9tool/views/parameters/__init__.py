"""The parameter table: its model, the view and the dialog for one parameter."""
