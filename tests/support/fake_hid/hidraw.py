"""The fake ``hid`` module under hidapi's Linux hidraw name (prm9tool imports ``hidraw`` first)."""

from hid import device, enumerate

__all__ = ["device", "enumerate"]
