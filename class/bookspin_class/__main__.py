"""`python3 -m bookspin_class ...`: what the `bookspin-class` program runs (docs/class.md)."""
import sys

from bookspin_class.server import main

sys.exit(main(sys.argv[1:]))
