"""The device layer: USB protocol, transports, valve sessions and the emulator (no Qt)."""
