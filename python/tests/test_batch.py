"""vissort.batch (docs/batch.md): chunks, renders within 1/255 of the plain module loop, pairs
equal to brute force and orders valid by the exact ground truth on every frame, in this process
and on a LocalCluster of two worker processes, scenes by name and as arrays, a worker killed in
the middle of a batch, files written whole, errors at once, and the command python3 -m
vissort.batch."""

import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest
from distributed import Client, LocalCluster

import vissort
import vissort.batch as batch
from vissort.batch._chunks import Chunk, cut

SCENE = "builtin:bunnies"
SIZE = (96, 72)


def plain_renders(frames, path, size=SIZE):
    """The single-process run: one Renderer over the frames in order."""
    scene = vissort.load(SCENE)
    base = vissort.Camera.default(scene, size, frames=frames)
    renderer = vissort.Renderer(scene)
    return [renderer.render(base.on_path(scene, path, f), size, time=f * vissort.FRAME_INTERVAL)
            for f in range(frames)]


def plain_pairs(frames, scene_spec=SCENE):
    """Each frame's own ground truth: brute force over every pair of triangles."""
    scene = vissort.load(scene_spec)
    detector = vissort.CollisionDetector(scene, method="brute")
    return [detector.collide(scene, time=f * vissort.FRAME_INTERVAL) for f in range(frames)]


def assert_images_close(images, expected):
    assert len(images) == len(expected)
    for f, (image, reference) in enumerate(zip(images, expected)):
        assert image.shape == reference.shape, f"frame {f}"
        difference = np.abs(image.astype(np.int16) - reference.astype(np.int16)).max()
        assert difference <= 1, f"frame {f} differs by {difference}/255"


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=":0")
    with Client(cluster) as c:
        yield c
    cluster.close()


def test_chunks_cover_the_frames_in_order_each_seeded_by_the_one_before():
    chunks = cut(5, 7, 3)
    assert chunks == [Chunk(5, 8, None), Chunk(8, 11, 7), Chunk(11, 12, 10)]
    assert [f for c in chunks for f in c.frames] == list(range(5, 12))
    assert cut(0, 2) == [Chunk(0, 2, None)]  # the default chunk holds them
    # Collisions carry no order from frame to frame: no seeds.
    assert cut(5, 7, 3, seeded=False) == [Chunk(5, 8, None), Chunk(8, 11, None),
                                          Chunk(11, 12, None)]
    for bad in [(-1, 3, 2), (0, 0, 2), (0, 3, 0), (0, 3, 1.5), (0, True, 2)]:
        with pytest.raises(ValueError):
            cut(*bad)


def test_each_worker_is_asked_for_a_contiguous_run_of_chunks():
    from vissort.batch._runner import contiguous_runs

    assert contiguous_runs(7, 2) == [[0, 1, 2, 3], [4, 5, 6]]
    assert contiguous_runs(3, 8) == [[0], [1], [2]]
    assert contiguous_runs(0, 2) == [] and contiguous_runs(4, 0) == [[0, 1, 2, 3]]
    for count in range(20):
        for workers in range(1, 6):
            runs = contiguous_runs(count, workers)
            assert [i for run in runs for i in run] == list(range(count))
            assert len(runs) <= workers
            assert max(map(len, runs), default=0) - min(map(len, runs), default=0) <= 1


def test_camera_on_a_path_moves_as_the_command_line_moves_it():
    scene = vissort.load(SCENE)
    base = vissort.Camera.default(scene, SIZE)
    assert repr(base.on_path(scene, "static", 7)) == repr(base)
    assert repr(base.on_path(scene, "orbit", 0)) == repr(base)
    # 3 degrees a frame about the vertical axis through the scene's centre: 90 degrees.
    moved = base.on_path(scene, "orbit", 30)
    centre = np.add(*scene.bounds) / 2
    before, after = np.subtract(base.eye, centre), np.subtract(moved.eye, centre)
    assert after[1] == pytest.approx(before[1])
    assert np.hypot(after[0], after[2]) == pytest.approx(np.hypot(before[0], before[2]))
    assert np.dot(after[[0, 2]], before[[0, 2]]) == pytest.approx(0, abs=1e-3)
    with pytest.raises(ValueError, match="camera path"):
        base.on_path(scene, "spiral", 1)
    with pytest.raises(ValueError, match="at least 0"):
        base.on_path(scene, "orbit", -1)


def test_write_image_writes_what_it_is_given_and_refuses_the_rest(tmp_path):
    from PIL import Image

    image = np.random.default_rng(3).integers(0, 256, (5, 7, 4), dtype=np.uint8)
    image[..., 3] = 255
    vissort.write_image(tmp_path / "a.png", image)
    assert np.array_equal(np.asarray(Image.open(tmp_path / "a.png").convert("RGBA")), image)
    with pytest.raises(ValueError, match="RGBA"):
        vissort.write_image(tmp_path / "b.png", image[..., :3])
    with pytest.raises(ValueError, match="uint8"):
        vissort.write_image(tmp_path / "b.png", image.astype(np.float32))
    with pytest.raises(ValueError, match="extension"):
        vissort.write_image(tmp_path / "b.bmp", image)
    with pytest.raises(ValueError, match="cannot write"):
        vissort.write_image(tmp_path / "missing" / "b.png", image)


@pytest.mark.skipif(not vissort.has_gl, reason="render needs OpenGL; this build has none")
def test_renders_here_equal_the_plain_loop():
    result = batch.render(SCENE, 5, size=SIZE, path="orbit", chunk_frames=2, progress=False)
    assert result.frame_numbers == list(range(5))
    assert_images_close(result.results, plain_renders(5, "orbit"))
    assert list(result.stats["frame"]) == list(range(5))
    assert (result.stats["total_ms"] > 0).all()


@pytest.mark.skipif(not vissort.has_gl, reason="render needs OpenGL; this build has none")
def test_renders_on_two_workers_equal_the_plain_loop(client, tmp_path):
    frames = 7
    expected = plain_renders(frames, "orbit")
    result = batch.render(SCENE, frames, size=SIZE, path="orbit", chunk_frames=2, client=client,
                          progress=False)
    assert_images_close(result.results, expected)
    pattern = str(tmp_path / "frame_%04d.png")
    files = batch.render(SCENE, frames, size=SIZE, path="orbit", chunk_frames=3, client=client,
                         output=pattern, progress=False)
    from PIL import Image

    assert files.results == [pattern % f for f in range(frames)]
    assert_images_close([np.asarray(Image.open(p).convert("RGBA")) for p in files.results],
                        expected)
    assert sorted(os.listdir(tmp_path)) == [f"frame_{f:04d}.png" for f in range(frames)]


def test_pairs_on_two_workers_equal_brute_force_on_every_frame(client):
    frames = 9
    expected = plain_pairs(frames)
    result = batch.collide(SCENE, frames, chunk_frames=4, client=client, progress=False)
    assert result.frame_numbers == list(range(frames))
    assert sum(len(p) for p in expected) > 0
    for f in range(frames):
        assert np.array_equal(result.results[f], expected[f]), f"frame {f}"
    here = batch.collide(SCENE, frames, chunk_frames=4, progress=False)
    assert all(np.array_equal(a, b) for a, b in zip(here.results, expected))


def check_order(order_verdict, frames, frame, order, cycles, path="orbit", scene=SCENE):
    """The exact ground truth's verdict on one frame's order (conftest's order_verdict)."""
    return order_verdict(scene, SIZE, path, frames, frame, order, cycles)


def test_orders_on_two_workers_are_valid_on_every_frame(client, order_verdict):
    # Orders are not unique (a chunk's seed starts from no order), so each frame's is checked
    # against the exact ground truth, not against the plain loop's.
    frames = 7
    result = batch.order(SCENE, frames, size=SIZE, path="orbit", chunk_frames=3, client=client,
                         progress=False)
    assert result.frame_numbers == list(range(frames))
    for f in range(frames):
        verdict = check_order(order_verdict, frames, f, result.results[f], result.cycles[f])
        assert verdict["permutation"] == 1, f"frame {f}"
        assert verdict["violations"] == 0, f"frame {f}: {verdict}"
        assert verdict["checked"] > 0, f"frame {f}"
    assert list(result.stats["queries"] > 0) == [True] * frames
    # The check can fail: frame 0's order reversed is wrong where bunnies overlap.
    wrong = check_order(order_verdict, frames, 0, result.results[0][::-1], [])
    assert wrong["violations"] > 0


def crossing_triangles():
    """A static Scene made from arrays: 20 objects of 10 random triangles each in a unit cube,
    crossing one another."""
    corners = np.random.default_rng(5).random((200, 3, 3), dtype=np.float32)
    return vissort.Scene(corners, np.full(20, 10), colours=(0.4, 0.6, 0.9, 0.5),
                         name="crossing triangles")


def brute_pairs(scene):
    return vissort.CollisionDetector(scene, method="brute").collide(scene)


def test_a_static_scene_travels_to_the_workers_as_its_arrays(client, order_verdict):
    # The plant loaded here (a static Scene): the workers get it pickled, and each frame's order
    # is checked by the exact ground truth of the plant loaded by name.
    frames, spec = 5, "builtin:plant"
    result = batch.order(vissort.load(spec), frames, size=SIZE, path="orbit", chunk_frames=2,
                         client=client, progress=False)
    assert result.frame_numbers == list(range(frames))
    for f in range(frames):
        verdict = check_order(order_verdict, frames, f, result.results[f], result.cycles[f],
                              scene=spec)
        assert verdict["permutation"] == 1 and verdict["violations"] == 0, f"frame {f}"
        assert verdict["checked"] > 0, f"frame {f}"
    # Collisions of a Scene made from arrays, against brute force.
    crossing = crossing_triangles()
    expected = brute_pairs(crossing)
    assert len(expected) > 0
    pairs = batch.collide(crossing, 3, chunk_frames=2, client=client, progress=False)
    assert all(np.array_equal(p, expected) for p in pairs.results)
    here = batch.collide(crossing, 2, progress=False)  # here, the caller's Scene itself
    assert all(np.array_equal(p, expected) for p in here.results)


def test_a_cluster_whose_workers_join_later_still_runs_the_batch():
    cluster = LocalCluster(n_workers=0, threads_per_worker=1, processes=True,
                           dashboard_address=":0")
    with Client(cluster) as late:
        joining = threading.Timer(1.0, lambda: cluster.scale(1))
        joining.start()
        result = batch.collide(SCENE, 3, chunk_frames=2, client=late, progress=False)
        joining.join()
    cluster.close()
    assert result.frame_numbers == [0, 1, 2]
    assert all(np.array_equal(a, b) for a, b in zip(result.results, plain_pairs(3)))
    # A scene of arrays waits for a worker to hold them.
    cluster = LocalCluster(n_workers=0, threads_per_worker=1, processes=True,
                           dashboard_address=":0")
    with Client(cluster) as late:
        joining = threading.Timer(1.0, lambda: cluster.scale(1))
        joining.start()
        crossing = batch.collide(crossing_triangles(), 2, client=late, progress=False)
        joining.join()
    cluster.close()
    expected = brute_pairs(crossing_triangles())
    assert len(expected) > 0 and all(np.array_equal(p, expected) for p in crossing.results)


def test_statistics_are_a_list_of_dicts_without_pandas(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now fails
    result = batch.collide(SCENE, 3, chunk_frames=2, progress=False)
    assert isinstance(result.stats, list)
    assert [row["frame"] for row in result.stats] == [0, 1, 2]
    assert all("total_ms" in row for row in result.stats)


def test_a_scene_that_cannot_be_loaded_fails_at_once(client):
    started = time.monotonic()
    with pytest.raises(ValueError, match="unknown built-in scene 'builtin:nope'"):
        batch.collide("builtin:nope", 100, client=client, progress=False)
    with pytest.raises((ValueError, OSError), match="missing.obj"):
        batch.order("/nonexistent/missing.obj", 100, client=client, progress=False)
    assert time.monotonic() - started < 5
    with pytest.raises(ValueError, match="dynamic scene 'builtin:bunnies' cannot travel"):
        batch.collide(vissort.load(SCENE), 2)
    with pytest.raises(ValueError, match="static vissort.Scene"):
        batch.collide(42, 2)


def test_a_task_that_fails_ends_the_batch_with_its_error(client):
    # The method is checked where the detector is made: on the workers, in the first task.
    started = time.monotonic()
    with pytest.raises(ValueError, match="nope"):
        batch.collide(SCENE, 300, method="nope", chunk_frames=2, client=client, progress=False)
    assert time.monotonic() - started < 10
    # The cluster is still usable afterwards.
    assert batch.collide(SCENE, 2, client=client, progress=False).frame_numbers == [0, 1]


@pytest.mark.skipif(not vissort.has_gl, reason="render needs OpenGL; this build has none")
def test_a_frame_that_fails_to_be_written_fails_the_batch_and_leaves_no_partial_file(tmp_path):
    (tmp_path / "frame_0001.png").mkdir()  # a folder where frame 1 goes: its write fails
    with pytest.raises(ValueError, match="frame_0001.png"):
        batch.render(SCENE, 2, size=SIZE, output=str(tmp_path / "frame_%04d.png"),
                     progress=False)
    assert sorted(os.listdir(tmp_path)) == ["frame_0000.png", "frame_0001.png"]
    assert (tmp_path / "frame_0001.png").is_dir()


@pytest.mark.skipif(not vissort.has_gl, reason="render needs OpenGL; this build has none")
def test_a_batch_removes_what_killed_writers_left_beside_its_frames(tmp_path):
    # write_image's temporary files (.NAME.vissort-XXXXXXXX.partial) of writers killed mid-frame.
    for name in ("frame_0001.png", "frame_0009.png", "other.png"):
        (tmp_path / f".{name}.vissort-1234abcd.partial").write_bytes(b"\x89PNG half")
    result = batch.render(SCENE, 3, size=SIZE, output=str(tmp_path / "frame_%04d.png"),
                          progress=False)
    assert result.frame_numbers == [0, 1, 2]
    # The batch's frames' leftovers are gone; another frame's and another file's stay.
    assert sorted(os.listdir(tmp_path)) == [".frame_0009.png.vissort-1234abcd.partial",
                                            ".other.png.vissort-1234abcd.partial",
                                            "frame_0000.png", "frame_0001.png", "frame_0002.png"]


def test_bad_outputs_and_sizes_are_refused(tmp_path):
    with pytest.raises(ValueError, match="integer field"):
        batch.render(SCENE, 3, output=str(tmp_path / "frame.png"))
    with pytest.raises(ValueError, match="does not exist"):
        batch.render(SCENE, 3, output=str(tmp_path / "nowhere" / "f_%04d.png"))
    with pytest.raises(ValueError, match="size"):
        batch.order(SCENE, 3, size=(0, 10))


@pytest.mark.skipif(not vissort.has_gl, reason="render needs OpenGL; this build has none")
def test_a_worker_killed_in_the_middle_still_gives_every_frame(tmp_path):
    frames, size = 24, (160, 120)
    expected = plain_renders(frames, "orbit", size)
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=":0")
    killed = []
    with Client(cluster) as client:
        client.run(lambda: vissort.load(SCENE) and None)  # both workers' imports done
        pids = list(client.run(os.getpid).values())
        pattern = str(tmp_path / "frame_%04d.png")

        def kill_one_after_the_first_frame():
            deadline = time.monotonic() + 60
            while not os.listdir(tmp_path) and time.monotonic() < deadline:
                time.sleep(0.005)
            os.kill(pids[0], signal.SIGKILL)
            killed.append(len(os.listdir(tmp_path)))  # frames written when it died

        killer = threading.Thread(target=kill_one_after_the_first_frame)
        killer.start()
        result = batch.render(SCENE, frames, size=size, path="orbit", chunk_frames=2,
                              client=client, output=pattern, progress=False)
        killer.join()
    cluster.close()
    assert killed and killed[0] < frames, f"no worker was killed in the middle: {killed}"
    from PIL import Image

    assert result.frame_numbers == list(range(frames))
    assert_images_close([np.asarray(Image.open(p).convert("RGBA")) for p in result.results],
                        expected)
    # Whole files only: no partial file left behind by the killed worker.
    assert sorted(os.listdir(tmp_path)) == [f"frame_{f:04d}.png" for f in range(frames)]


def test_the_command_runs_a_batch_on_local_workers(tmp_path):
    env = dict(os.environ)
    run = lambda *args: subprocess.run([sys.executable, "-m", "vissort.batch", *args],
                                       capture_output=True, text=True, env=env, timeout=300)
    done = run("collide", SCENE, "--frames", "4", "--chunk-frames", "2", "--local-workers", "2",
               "-q", "-o", str(tmp_path / "pairs.npz"), "--csv", str(tmp_path / "stats.csv"))
    assert done.returncode == 0, done.stderr
    saved = np.load(tmp_path / "pairs.npz")
    expected = plain_pairs(4)
    assert all(np.array_equal(saved[f"frame_{f:06d}"], expected[f]) for f in range(4))
    lines = (tmp_path / "stats.csv").read_text().splitlines()
    assert lines[0].startswith("frame,time_s,") and len(lines) == 5
    failed = run("order", "builtin:nope", "--frames", "3")
    assert failed.returncode == 1
    assert failed.stderr.strip().splitlines() == [
        failed.stderr.strip().splitlines()[0]] and "unknown built-in scene" in failed.stderr
    no_output = run("render", SCENE, "--frames", "2")
    assert no_output.returncode == 1 and "needs -o" in no_output.stderr
