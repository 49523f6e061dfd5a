"""Never overwrite an input (issue 56, docs/cli.md "Outputs"): vissort.batch refuses, before any
work, an output that is a file the scene reads or another output, and writes its files whole;
vissort.write_image replaces a file whole or not at all; Scene.source_files lists what loading
read."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import vissort
import vissort.batch as batch
from vissort.batch import _outputs

DATA = Path(__file__).resolve().parents[2] / "tests" / "data"


@pytest.fixture()
def crabs(tmp_path):
    """crabs.obj with its material library, in a folder of their own."""
    for name in ("crabs.obj", "crabs.mtl"):
        shutil.copy(DATA / "meshes" / name, tmp_path / name)
    return tmp_path / "crabs.obj"


def snapshot(folder):
    return {p: p.read_bytes() for p in Path(folder).rglob("*") if p.is_file()}


def test_a_loaded_scene_lists_the_files_its_loading_read(crabs, tmp_path):
    scene = vissort.load(str(crabs))
    files = [os.path.realpath(f) for f in scene.source_files]
    assert files == [str((tmp_path / "crabs.obj").resolve()), str((tmp_path / "crabs.mtl").resolve())]
    (tmp_path / "scene.json").write_text('{"objects": [{"mesh": "crabs.obj"}]}')
    from_json = [os.path.realpath(f) for f in vissort.load(str(tmp_path / "scene.json")).source_files]
    assert from_json[0] == str((tmp_path / "scene.json").resolve())
    assert set(from_json[1:]) == set(files)
    assert vissort.load("builtin:bunnies?n=2").source_files == []


def test_a_frame_that_would_replace_the_scene_file_is_refused_before_any_work(tmp_path, crabs):
    shutil.copy(crabs, tmp_path / "m_0002.obj")
    before = snapshot(tmp_path)
    with pytest.raises(ValueError, match=r"output '.*m_%04d\.obj' \(frame 2: '.*m_0002\.obj'\) "
                                         r"is a file the scene read '.*m_0002\.obj': vissort never "
                                         r"overwrites an input"):
        batch.render(str(tmp_path / "m_0002.obj"), 3, output=str(tmp_path / "m_%04d.obj"),
                     size=(16, 16))
    # A loaded Scene carries its files, and a JSON scene's meshes count.
    with pytest.raises(ValueError, match="never overwrites an input"):
        batch.render(vissort.load(str(tmp_path / "m_0002.obj")), 3,
                     output=str(tmp_path / "m_%04d.obj"), size=(16, 16))
    (tmp_path / "s.json").write_text('{"objects": [{"mesh": "m_0002.obj"}]}')
    with pytest.raises(ValueError, match="m_0002"):
        batch.render(str(tmp_path / "s.json"), 3, first=1, output=str(tmp_path / "m_%04d.obj"),
                     size=(16, 16))
    (tmp_path / "s.json").unlink()
    assert snapshot(tmp_path) == before
    # Frames that do not reach it: no clash (the run itself then fails on the extension).
    with pytest.raises(ValueError) as later:
        batch.render(str(tmp_path / "m_0002.obj"), 2, output=str(tmp_path / "m_%04d.obj"),
                     size=(16, 16))
    assert "never overwrites" not in str(later.value)


def test_a_link_or_another_spelling_of_an_input_is_that_input(tmp_path, crabs):
    os.symlink(crabs, tmp_path / "f_1.obj")
    with pytest.raises(ValueError, match=r"-o '.*f_%d\.obj' \(frame 1: '.*f_1\.obj'\) is the "
                                         r"scene file '.*crabs\.obj'"):
        _outputs.check([_outputs.FileUse("the scene file", str(crabs))],
                       [_outputs.FileUse("-o", str(tmp_path / "f_%d.obj"), range(0, 3))])
    (tmp_path / "sub").mkdir()
    for spelling in (str(tmp_path / "sub" / ".." / "crabs.obj"), str(tmp_path / "f_1.obj")):
        with pytest.raises(ValueError, match="never overwrites an input"):
            _outputs.check([_outputs.FileUse("the scene file", str(crabs))],
                           [_outputs.FileUse("--csv", spelling)])
    # Two outputs on one path, two patterns sharing a frame; /dev/null and "-" are no files.
    with pytest.raises(ValueError, match="are one file"):
        _outputs.check([], [_outputs.FileUse("-o", "a.npz"), _outputs.FileUse("--csv", "./a.npz")])
    with pytest.raises(ValueError, match="are one file"):
        _outputs.check([], [_outputs.FileUse("-o", str(tmp_path / "x_%05d.png"), range(100000)),
                            _outputs.FileUse("--csv", str(tmp_path / "x_99999.png"))])
    _outputs.check([], [_outputs.FileUse("-o", "/dev/null"), _outputs.FileUse("--csv", "/dev/null"),
                        _outputs.FileUse("--json", "-"), _outputs.FileUse("--csv", "-")])


def test_the_command_refuses_a_clash_and_leaves_every_file(tmp_path, crabs):
    run = lambda *args: subprocess.run([sys.executable, "-m", "vissort.batch", *map(str, args)],
                                       capture_output=True, text=True, timeout=300)
    before = snapshot(tmp_path)
    for args, needle in [
        (("collide", crabs, "--csv", crabs), "is the scene file"),
        (("order", crabs, "-o", tmp_path / "o.npz", "--csv", tmp_path / "o.npz"), "are one file"),
        (("order", crabs, "-o", tmp_path / "o", "--csv", tmp_path / "o.npz"), "are one file"),
    ]:
        done = run(*args, "-q")
        assert done.returncode == 1, done.stderr
        lines = done.stderr.strip().splitlines()
        assert len(lines) == 1 and needle in lines[0], done.stderr
        assert snapshot(tmp_path) == before
    written = run("collide", crabs, "-q", "-o", tmp_path / "p.npz", "--csv", tmp_path / "s.csv")
    assert written.returncode == 0, written.stderr
    assert (tmp_path / "s.csv").read_text().startswith("frame,time_s,")
    assert "frame_000000" in np.load(tmp_path / "p.npz")
    assert not [p for p in tmp_path.iterdir() if ".partial" in p.name]


def test_write_image_replaces_a_file_whole_or_not_at_all(tmp_path):
    image = np.zeros((4, 5, 4), dtype=np.uint8)
    target = tmp_path / "a.png"
    target.write_bytes(b"old")
    with pytest.raises(ValueError, match="extension"):
        vissort.write_image(tmp_path / "a.bmp", image)
    vissort.write_image(target, image)
    assert target.read_bytes().startswith(b"\x89PNG")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png"]
    os.chmod(target, 0o640)
    vissort.write_image(target, image)
    assert os.stat(target).st_mode & 0o777 == 0o640


def test_a_failed_whole_write_leaves_the_old_file(tmp_path):
    target = tmp_path / "stats.csv"
    target.write_text("old\n")

    def failing(path):
        Path(path).write_text("half")
        raise OSError("disk full, say")

    with pytest.raises(OSError, match="disk full"):
        _outputs.write_whole(str(target), failing)
    assert target.read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["stats.csv"]
