"""Qt widgets only: they observe the models through signals and never talk to the device."""
