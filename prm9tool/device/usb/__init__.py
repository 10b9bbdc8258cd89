"""The USB link (HID reports): the session, the protocol, the transports (hidapi and the emulator), discovery."""
