"""Files: *.prm parameter sets (read, write, check), atomic saving, backups, CiA 306 EDS. No Qt."""
