"""The CAN bus: the bus dialog, LSS commissioning, and the CANopen window with its tables."""
