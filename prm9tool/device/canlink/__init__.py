"""The CANopen link: python-can bus, ``canopen`` master, discovery, the CANopen valve session."""
