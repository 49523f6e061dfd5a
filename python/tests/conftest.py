"""Shared fixtures: the command line tool the module is compared with, the exact ground truth's
order check, and the repository."""

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


@pytest.fixture(scope="session")
def order_verdict():
    """The exact ground truth's verdict on one frame's order (tests/support/order_check): the
    frame the command line and the module order for (scene, size, path, frames, frame) with the
    default camera. Returns {"permutation": 0/1, "violations": V, "checked": C}."""
    tool = os.environ.get("VISSORT_ORDER_CHECK")
    if not tool:
        pytest.fail("VISSORT_ORDER_CHECK must name the built order_check tool (ctest sets it)")

    def verdict(scene, size, path, frames, frame, order, cycles):
        text = " ".join(map(str, order)) + "\n" + "".join(
            " ".join(map(str, c)) + "\n" for c in cycles)
        done = subprocess.run([tool, scene, str(size[0]), str(size[1]), path, str(frames),
                               str(frame)], input=text, capture_output=True, text=True,
                              check=True)
        words = done.stdout.split()
        return dict(zip(words[::2], map(int, words[1::2])))

    return verdict
