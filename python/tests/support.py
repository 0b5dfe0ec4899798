"""Plain helpers shared by the tests (fixtures are in conftest.py)."""

import json
import sqlite3

CLI_ERROR_PREFIX = "shockmap: error: "  # app/error_report.cpp, for an InputError
# The module's refusal of a text holding a NUL byte: the argument, the text escaped, the index.
NUL_REFUSAL = (
    '{}: "{}" holds a NUL byte at character {}; a path, a name or SQL text cannot hold one'
)


def cli_error_message(stderr):
    """The message of the command line's one error line, without its prefix."""
    lines = [line for line in stderr.splitlines() if line.startswith(CLI_ERROR_PREFIX)]
    assert len(lines) == 1, f"expected one '{CLI_ERROR_PREFIX}' line on stderr, got:\n{stderr}"
    return lines[0][len(CLI_ERROR_PREFIX) :]


def write_json(path, data):
    path.write_text(json.dumps(data, indent=1))
    return path


def read_only(db):
    """A read-only connection to a study database."""
    return sqlite3.connect(f"file:{db}?mode=ro", uri=True)
