"""Entry point for ``python -m torsional_contact``."""

import sys

from .cli import main

sys.exit(main())
