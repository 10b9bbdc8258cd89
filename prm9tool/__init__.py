"""prm9tool: parameterization tool for PRM9 proportional directional valves."""

__version__ = "0.1.0"
