"""Where the cic binary is whose `cic worker` processes serve evaluations."""

import os

from . import _build


def executable():
    """The cic binary the package runs as its workers: $CIC_EXECUTABLE when set, else the one it was
    built or installed with (the build tree's, or PREFIX/bin/cic)."""
    return os.environ.get("CIC_EXECUTABLE") or _build.CIC_EXECUTABLE
