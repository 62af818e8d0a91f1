"""Entry point for ``python -m torsional_contact``."""

import sys

from .io.cli import main

sys.exit(main())
