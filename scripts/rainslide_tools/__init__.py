"""Helpers the entry points in scripts/ import (results folders, slope analysis, speed-vs-error sweep); not run."""
