"""Entry point for ``python -m torsional_contact``."""

import sys

try:
    from .io.cli import main
except KeyboardInterrupt:  # Ctrl-C while the modules load: one line, as during a run
    sys.stderr.write("torsional_contact: interrupted\n")
    sys.exit(130)

sys.exit(main())
