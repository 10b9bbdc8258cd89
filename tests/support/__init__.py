"""Test helpers imported as a package (``from support.bad_node import ...``)."""
