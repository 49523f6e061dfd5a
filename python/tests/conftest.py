"""Shared fixtures: the command line tool the module is compared with, and the repository."""

import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("VISSORT_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def _cli_path():
    path = os.environ.get("VISSORT_CLI")
    if not path or not Path(path).is_file():
        pytest.fail("VISSORT_CLI must name the built vissort command (ctest sets it; "
                    "e.g. VISSORT_CLI=build/vissort)")
    return path


@pytest.fixture(scope="session")
def cli():
    """Runs `vissort ARGS...` quietly; returns the completed process (checked)."""
    path = _cli_path()

    def run(*args):
        completed = subprocess.run([path, *map(str, args), "--quiet"], capture_output=True,
                                   text=True)
        assert completed.returncode == 0, completed.stderr
        return completed

    return run


@pytest.fixture(scope="session")
def cli_json(cli, tmp_path_factory):
    """Runs `vissort ARGS... --json FILE` and returns the parsed document."""
    directory = tmp_path_factory.mktemp("cli_json")
    counter = [0]

    def run(*args):
        counter[0] += 1
        path = directory / f"{counter[0]}.json"
        cli(*args, "--json", path)
        return json.loads(path.read_text())

    return run


def source_file(relative):
    return str(SOURCE_DIR / relative)
