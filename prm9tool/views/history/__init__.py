"""The valve history window: records, details, notes, retention and the database settings."""
