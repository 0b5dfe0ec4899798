#!/usr/bin/env python3
"""Runs a notebook's code cells in order in one namespace, from the notebook's folder, as a
kernel would (without Jupyter, which the tests do not install): a cell that raises fails the
run, naming the cell. The value of a cell's last expression is printed, as a notebook shows it.

    python3 python/tests/run_notebook.py examples/advice_check.ipynb
"""

import ast
import json
import os
import pathlib
import sys


def run(notebook):
    cells = json.loads(notebook.read_text())["cells"]
    os.chdir(notebook.parent)
    namespace = {"__name__": "__main__"}
    for number, cell in enumerate(cells, start=1):
        if cell["cell_type"] != "code":
            continue
        tree = ast.parse("".join(cell["source"]), f"{notebook.name}, cell {number}")
        shown = tree.body.pop() if tree.body and isinstance(tree.body[-1], ast.Expr) else None
        exec(compile(tree, f"{notebook.name}, cell {number}", "exec"), namespace)
        if shown is not None:
            value = eval(compile(ast.Expression(shown.value), f"cell {number}", "eval"), namespace)
            if value is not None:
                print(value)


if __name__ == "__main__":
    run(pathlib.Path(sys.argv[1]).resolve())
