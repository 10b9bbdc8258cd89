"""Tuning and characterization analysis: plain functions on numpy arrays (no Qt, no device).

Step figures (:mod:`prm9tool.scope.measure`), frequency response (:mod:`.frequency`), static
characteristic and linearization (:mod:`.static`), controller rules (:mod:`.pid`), model
identification and model-based gain design (:mod:`.model`), acceptance limits (:mod:`.profile`).
The procedures that move a valve (:mod:`prm9tool.characterize`) compose these with a session.
"""
