"""``python -m oceanrender`` = the ``oceanrender`` command."""

import sys

from .cli import main

sys.exit(main())
