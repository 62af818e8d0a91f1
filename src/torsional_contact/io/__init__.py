"""Input and output at the top of the package: the command line and the figure helpers."""
