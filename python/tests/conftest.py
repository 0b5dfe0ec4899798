"""Shared fixtures of the Python module's tests.

CTest runs them as `python3 -m pytest python/tests` with PYTHONPATH naming the built package
and two variables: SHOCKMAP_EXECUTABLE, the `shockmap` command line built beside the module
(the tests hold the module to what the command line stores and prints), and
SHOCKMAP_SOURCE_DIR, the repository (its scenes/ and studies/). A missing variable fails the
tests that need it, naming it; nothing is skipped for want of it.
"""

import os
import pathlib
import subprocess

import pytest


def _required_path(variable):
    value = os.environ.get(variable, "")
    if not value:
        pytest.fail(f"{variable} is not set: the tests need it (see python/tests/conftest.py)")
    path = pathlib.Path(value)
    if not path.exists():
        pytest.fail(f"{variable}={value}: no such file or directory")
    return path


@pytest.fixture(scope="session")
def executable():
    """The `shockmap` command line built with the module."""
    return _required_path("SHOCKMAP_EXECUTABLE")


@pytest.fixture(scope="session")
def source_dir():
    """The repository's root (scenes/, studies/)."""
    return _required_path("SHOCKMAP_SOURCE_DIR")


@pytest.fixture(scope="session")
def cli(executable):
    """Runs the command line; returns the completed process (text output)."""

    def run(*args, expect=0, cwd=None):
        done = subprocess.run(
            [str(executable), *map(str, args)],
            capture_output=True,
            text=True,
            cwd=cwd,
            timeout=300,
        )
        if expect is not None and done.returncode != expect:
            pytest.fail(
                f"shockmap {' '.join(map(str, args))} exited {done.returncode}, not {expect}\n"
                f"stdout: {done.stdout}\nstderr: {done.stderr}"
            )
        return done

    return run
