import sys

from polymimic.cli import main

sys.exit(main())
