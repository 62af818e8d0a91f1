"""Input and output at the top of the package: the command line, the one writer of user-named files, signal files."""
