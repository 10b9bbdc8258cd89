"""Procedures that move a valve for tuning and characterization (no Qt).

A :class:`~.rig.Rig` is the valve under test (an emulated valve stepped as fast as the CPU
allows, or any session at its link's stream rate); :mod:`.procedures` runs steps, sweeps and
static sweeps on it, on the frame every such test shares (:mod:`.frame`), and the autotunes
with the analysis functions of :mod:`prm9tool.analysis`, always leaving the
valve as it was; :mod:`.run` is the end-of-line characterization and its report data.
"""
