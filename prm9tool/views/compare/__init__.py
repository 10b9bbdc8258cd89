"""Comparing parameter sets: the comparison view and the workflow that opens it."""
