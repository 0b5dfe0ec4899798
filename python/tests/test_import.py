"""`import shockmap` under an interpreter that cannot run it says which one can, and what to
install."""

import os
import subprocess
import sys

from shockmap import _built_for, _interpreter


def _import_without(package):
    """`import shockmap` in a fresh interpreter where importing `package` fails."""
    code = f"import sys; sys.modules[{package!r}] = None; import shockmap"
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ), timeout=120)


def test_a_missing_package_names_the_interpreter_built_for_and_what_to_install():
    done = _import_without("pandas")
    assert done.returncode != 0
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: import shockmap: "), done.stderr
    assert "pandas" in last
    assert f"under {sys.executable} (Python " in last
    assert f"built for {_built_for.PYTHON} (Python {_built_for.PYTHON_VERSION})" in last
    assert f"run {_built_for.PYTHON}" in last
    assert "apt install python3-numpy python3-pandas" in last
    assert "docs/python.md" in last


def test_another_python_version_is_told_to_build_the_module_for_it(monkeypatch):
    monkeypatch.setattr(_interpreter, "PYTHON_VERSION", "2.7")
    message = _interpreter.import_failure(ImportError("No module named 'shockmap._shockmap'"))
    assert f"cmake -DPython_EXECUTABLE={sys.executable}" in message
    assert "pip install" not in message
