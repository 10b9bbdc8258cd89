"""The CAN trace window: a decoded trace as a filterable table and a timeline of PDO values,
and recording the bus (Record… / Stop); docs/trace.md."""
