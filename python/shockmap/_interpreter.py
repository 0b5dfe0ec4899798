"""Why `import shockmap` failed, when the interpreter is not the one the module was built for or
lacks a package the module uses (docs/python.md, "Installing")."""

import sys

from ._built_for import PYTHON, PYTHON_VERSION

PACKAGES = "numpy pandas"


def import_failure(error):
    """The message of the ImportError `error`, met importing the module: which interpreter runs,
    which one the module was built for, and what to run or install instead."""
    running = f"{sys.executable} (Python {sys.version_info.major}.{sys.version_info.minor})"
    built_for = f"{PYTHON} (Python {PYTHON_VERSION})"
    same_version = f"{sys.version_info.major}.{sys.version_info.minor}" == PYTHON_VERSION
    remedy = (f"or install them for this one ({sys.executable} -m pip install {PACKAGES})"
              if same_version else
              f"or build the module for this one (cmake -DPython_EXECUTABLE={sys.executable})")
    return (f"import shockmap: {error} under {running}; the module was built for {built_for}, "
            f"which has the packages it uses ({PACKAGES}; on Debian: apt install python3-numpy "
            f"python3-pandas): run {PYTHON}, {remedy} (docs/python.md)")
