"""vissort.Scene from arrays (docs/python.md): objects, colours, transparency, names and camera
as given, every bad argument a ValueError naming it; and scenes pickled as their arrays (what a
Dask worker or another process receives): a static scene comes back the same in every field, a
dynamic one and a state that is not a scene's are refused."""

import json
import pickle

import numpy as np
import pytest

import vissort

CORNERS = np.random.default_rng(1).random((10, 3, 3), dtype=np.float32)


def fields(scene):
    """Everything a scene holds that Python can see, for comparing two scenes."""
    return dict(
        name=scene.name, positions=scene.positions.tobytes(),
        objects=[(o.name, o.colour, o.transparent, o.first_triangle, o.triangle_count, o.parts)
                 for o in scene.objects],
        camera=repr(scene.camera),
        cameras=[(n, repr(c), p) for n, c, p in scene.cameras])


def test_a_scene_from_arrays_holds_what_it_was_given():
    camera = vissort.Camera.perspective(eye=(0, 0, 5), target=(0, 0, 0))
    scene = vissort.Scene(CORNERS, [4, 6], colours=[(1, 0, 0, 0.5), (0, 1, 0)], names=["a", "b"],
                          camera=camera, name="two")
    assert (scene.name, scene.triangle_count, scene.is_dynamic) == ("two", 10, False)
    assert np.array_equal(scene.positions, CORNERS)
    assert [(o.name, o.colour, o.transparent) for o in scene.objects] == [
        ("a", (1.0, 0.0, 0.0, 0.5), True), ("b", (0.0, 1.0, 0.0, 1.0), False)]
    assert np.array_equal(scene.object_ranges, [[0, 4], [4, 6]])
    assert repr(scene.camera) == repr(camera)
    plain = vissort.Scene(CORNERS)  # one grey opaque object, no camera
    assert [(o.name, o.transparent, o.triangle_count) for o in plain.objects] == [
        ("object 0", False, 10)]
    assert plain.camera is None and plain.name == "arrays"
    assert vissort.Scene(CORNERS, transparent=True).objects[0].transparent
    # Vertices with triangles, as every call that takes geometry reads them.
    vertices = CORNERS.reshape(-1, 3)
    indexed = vissort.Scene(vertices, triangles=np.arange(30).reshape(10, 3))
    assert np.array_equal(indexed.positions, CORNERS)


@pytest.mark.parametrize("arguments, message", [
    (dict(objects=[4, 5]), "objects cover 9 triangles, the scene has 10"),
    (dict(objects=[(0, 4), (3, 7)]), "object 1 .* starts at triangle 3, expected 4"),
    (dict(objects=[4, 0, 6]), "object 1 .* is empty"),
    (dict(colours=(1, 2, 3)), "colours must be"),
    (dict(objects=[4, 6], colours=[(1, 0, 0)]), "one per object \\(2\\), got 1"),
    (dict(objects=[4, 6], transparent=[True]), "transparent must be one bool or one bool per"),
    (dict(transparent=1), "transparent must be one bool"),
    (dict(names="ab"), "names must be one string per object"),
    (dict(objects=[4, 6], names=["a", 2]), "names must be one string per object"),
    (dict(camera="front"), "camera must be a vissort.Camera"),
])
def test_bad_arguments_are_refused_by_name(arguments, message):
    with pytest.raises(ValueError, match=message):
        vissort.Scene(CORNERS, **arguments)


def test_bad_positions_are_refused_as_everywhere():
    bad = CORNERS.copy()
    bad[3, 1, 2] = np.nan
    with pytest.raises(ValueError, match="triangle 3, corner 1 is not finite"):
        vissort.Scene(bad)
    with pytest.raises(ValueError, match="no triangles"):
        vissort.Scene(np.zeros((0, 3, 3), np.float32))


def test_a_static_scene_pickles_as_its_arrays_whole(tmp_path):
    made = vissort.Scene(CORNERS, [4, 6], colours=[(1, 0, 0, 0.5), (0, 1, 0)],
                         camera=vissort.Camera.orthographic((0, -1, 0)))
    assert fields(pickle.loads(pickle.dumps(made))) == fields(made)
    # A JSON scene with a camera path (kept for --path scene), and the plant with its camera.
    path_scene = tmp_path / "path.json"
    path_scene.write_text(json.dumps({
        "camera_path": [{"time": 0, "eye": [0, 1, 8], "target": [0, 0, 0]},
                        {"time": 0.5, "eye": [8, 1, 0], "target": [0, 0, 0], "fov": 60}],
        "objects": [{"shape": "box"}, {"shape": "box", "translate": [0, 0, -3]}]}))
    for scene in [vissort.load(str(path_scene)), vissort.load("builtin:plant")]:
        assert fields(pickle.loads(pickle.dumps(scene))) == fields(scene)
    scene = vissort.load(str(path_scene))
    copy = pickle.loads(pickle.dumps(scene))
    base = vissort.Camera.default(scene, (64, 48), frames=20)
    for f in [0, 7, 19]:  # the camera path travelled too
        assert repr(base.on_path(copy, "scene", f)) == repr(base.on_path(scene, "scene", f))
    assert repr(base.on_path(copy, "scene", 7)) != repr(base.on_path(copy, "scene", 0))


def test_a_dynamic_scene_and_a_foreign_state_are_refused():
    with pytest.raises(TypeError, match="cannot pickle the dynamic scene 'builtin:bunnies'"):
        pickle.dumps(vissort.load("builtin:bunnies?n=2"))
    state = vissort.Scene(CORNERS).__getstate__()
    for change, message in [(dict(version=99), "version 1"),
                            (dict(objects=[("a", (1, 1, 1, 1), False, 0, 5, [])]),
                             "objects cover 5 triangles"),
                            (dict(positions=np.full((2, 3, 3), np.inf, np.float32)),
                             "not finite"),
                            (dict(objects="x"), "not a vissort.Scene state")]:
        broken = vissort.Scene.__new__(vissort.Scene)
        with pytest.raises(ValueError, match=message):
            broken.__setstate__({**state, **change})
