"""The module's intersecting pairs equal the command line's (--pairs-out) and brute force's,
frame by frame."""

import numpy as np
import pytest

import vissort
from conftest import source_file


def cli_pairs(cli, tmp_path, *args):
    path = tmp_path / "pairs.txt"
    cli("collide", *args, "--pairs-out", path)
    frames = {}
    for line in path.read_text().splitlines():
        if line and not line.startswith("#"):
            frame, a, b = map(int, line.split())
            frames.setdefault(frame, []).append([a, b])
    return frames


def test_pairs_equal_the_cli_over_frames(cli, tmp_path):
    scene = vissort.builtin("bunnies", n=10, seed=1)
    frames = 40
    expected = cli_pairs(cli, tmp_path, "builtin:bunnies?n=10&seed=1", "--frames", frames)
    detector = vissort.CollisionDetector(scene)
    found = 0
    for f in range(frames):
        pairs = detector.collide(time=f / 30)
        assert pairs.dtype == np.uint32 and pairs.ndim == 2 and pairs.shape[1] == 2
        assert pairs.tolist() == expected.get(f, []), f"frame {f}"
        found += len(pairs)
    assert found > 0, "the bunnies touch in these frames: the comparison is not of empty lists"
    assert detector.stats["intersecting"] == len(pairs)


@pytest.mark.parametrize("method", ["brute", "bullet"])
def test_methods_agree_with_brute_force_on_arrays(method):
    scene = vissort.builtin("bunnies", n=10, seed=1)
    positions = scene.frame(1.0)
    reference = vissort.collide(positions, scene.object_ranges, method="brute")
    assert len(reference) > 0
    np.testing.assert_array_equal(vissort.collide(positions, scene.object_ranges,
                                                  method=method), reference)
    np.testing.assert_array_equal(vissort.collide(scene, time=1.0), reference)


@pytest.mark.parametrize("object_stage", ["adaptive", "always", "never"])
def test_every_object_stage_gives_brute_forces_pairs(object_stage):
    scene = vissort.builtin("bunnies", n=10, seed=1)
    brute = vissort.CollisionDetector(scene, method="brute")
    detector = vissort.CollisionDetector(scene, object_stage=object_stage, threads=2)
    stage_frames = 0
    for f in range(8):
        np.testing.assert_array_equal(detector.collide(time=f / 30), brute.collide(time=f / 30))
        stage_frames += detector.stats["directions"] > 0
    if object_stage == "always":
        assert stage_frames == 8
    elif object_stage == "never":
        assert stage_frames == 0
    else:  # the first frame tries it; later frames only while it pays
        assert stage_frames >= 1
    with pytest.raises(ValueError, match="unknown object stage 'sometimes'"):
        vissort.CollisionDetector(scene, object_stage="sometimes")


def test_bullet_on_threads_gives_brute_forces_pairs():
    scene = vissort.builtin("bunnies", n=10, seed=1)
    for threads in (1, 2, 0):
        np.testing.assert_array_equal(
            vissort.collide(scene, time=0.5, method="bullet", threads=threads),
            vissort.collide(scene, time=0.5, method="brute"))


def test_two_triangles_through_each_other():
    # A vertical triangle pierces a horizontal one; a third, far away, touches nothing.
    triangles = np.array([[[-1, 0, -1], [1, 0, -1], [0, 0, 1]],
                          [[0, -1, 0], [0, 1, 0.2], [0, 1, -0.2]],
                          [[5, 5, 5], [6, 5, 5], [5, 6, 5]]], dtype=np.float32)
    pairs = vissort.collide(triangles, objects=[1, 1, 1])
    assert pairs.tolist() == [[0, 1]]
    # Within one object they are not a collision.
    assert vissort.collide(triangles, objects=[[0, 2], [2, 1]]).shape == (0, 2)


def test_collide_needs_objects_for_arrays():
    with pytest.raises(ValueError, match="needs objects"):
        vissort.collide(np.zeros((2, 3, 3), np.float32))
    with pytest.raises(ValueError, match="unknown collision method"):
        vissort.collide(vissort.builtin("slabs"), method="gjk")


def test_object_pairs_are_the_objects_of_the_pairs(cli_json):
    # The colliding objects: the objects of each intersecting pair's triangles (mapped here from
    # the scene's object ranges), as the command line's JSON lists them.
    scene = vissort.builtin("bunnies", n=10, seed=1)
    detector = vissort.CollisionDetector(scene)
    assert detector.object_pairs is None
    pairs = detector.collide(time=1.0)
    ranges = scene.object_ranges
    object_of = np.repeat(np.arange(len(ranges)), ranges[:, 1])
    expected = sorted({tuple(sorted((int(object_of[a]), int(object_of[b])))) for a, b in pairs})
    assert len(expected) > 0, "the bunnies touch at 1 s"
    objects = detector.object_pairs
    assert objects.dtype == np.uint32 and objects.shape == (len(expected), 2)
    assert [tuple(p) for p in objects.tolist()] == expected
    assert detector.stats["colliding_object_pairs"] == len(expected)
    cli = cli_json("collide", "builtin:bunnies?n=10&seed=1", "--frames", 31)
    assert cli["frames"][30]["object_pairs_colliding"] == objects.tolist()


def test_a_mesh_files_grouping_decides_what_collides():
    # crabs.obj: two crabs, each a shell pierced by its claw, four meshes in two nodes. By mesh,
    # each claw meets its shell (both of the shell's triangles); by node or file, a crab is one
    # object and does not collide with itself.
    path = source_file("tests/data/meshes/crabs.obj")
    by_mesh = vissort.load(path)
    assert len(by_mesh.objects) == 4
    assert vissort.collide(by_mesh).tolist() == [[0, 2], [1, 2], [3, 5], [4, 5]]
    for grouping, objects in (("node", 2), ("file", 1)):
        scene = vissort.load(path, objects=grouping)
        assert len(scene.objects) == objects
        assert [p["name"] for o in scene.objects for p in o.parts] == [o.name for o in
                                                                       by_mesh.objects]
        assert vissort.collide(scene).shape == (0, 2)
    with pytest.raises(ValueError, match="did you mean 'node'"):
        vissort.load(path, objects="nodes")
