"""docs/python.md's examples run as written, each in an empty directory, and its stubs name
everything the module has."""

import ast
import os
import re
import subprocess
import sys

import pytest

import vissort
from conftest import SOURCE_DIR

DOC = (SOURCE_DIR / "docs" / "python.md").read_text()
EXAMPLES = re.findall(r"```python\n(.*?)```", DOC, re.S)


def test_the_guide_has_examples():
    assert len(EXAMPLES) >= 3


@pytest.mark.parametrize("index", range(len(EXAMPLES)))
def test_example_runs(index, tmp_path):
    script = tmp_path / "example.py"
    script.write_text(EXAMPLES[index])
    environment = dict(os.environ, MPLBACKEND="Agg", VISSORT_SOURCE_DIR=str(SOURCE_DIR))
    completed = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=environment,
                               capture_output=True, text=True, timeout=300)
    assert completed.returncode == 0, f"example {index}:\n{EXAMPLES[index]}\n{completed.stderr}"


def test_the_stubs_name_every_class_function_and_member():
    stubs = ast.parse((SOURCE_DIR / "python" / "vissort" / "__init__.pyi").read_text())
    top = {node.name for node in stubs.body if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
    top |= {target.id for node in stubs.body if isinstance(node, ast.AnnAssign)
            for target in [node.target] if isinstance(target, ast.Name)}
    public = {name for name in vissort.__all__}
    assert public <= top, f"missing from the stubs: {sorted(public - top)}"
    for node in stubs.body:
        if not isinstance(node, ast.ClassDef):
            continue
        members = {item.name for item in node.body if isinstance(item, ast.FunctionDef)}
        actual = {name for name in dir(getattr(vissort, node.name)) if not name.startswith("_")}
        assert actual <= members, f"{node.name}: missing from the stubs: {actual - members}"
