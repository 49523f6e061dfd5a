"""Arrays in: shapes, dtypes and strides the module accepts (with the same answers), and every
kind of bad input a clear ValueError, never a crash. Arrays out: dtypes, shapes, ownership."""

import pathlib

import numpy as np
import pytest

import vissort
from conftest import SOURCE_DIR

CAMERA = vissort.Camera.perspective((0.3, 0.4, 6), (0, 0, 0))


def overlapping_triangles(count=12, seed=3):
    """Triangles in a slab in front of the camera, overlapping each other on screen."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(-1, 1, (count, 1, 3)) * [1, 1, 0.5]
    return (centres + rng.uniform(-0.8, 0.8, (count, 3, 3))).astype(np.float32)


def order_of(positions, **kwargs):
    return vissort.order(positions, camera=CAMERA, size=(64, 64), level="triangle",
                         **kwargs).order.tolist()


def test_strides_dtypes_and_indexed_vertices_give_the_same_order():
    corners = overlapping_triangles()
    expected = order_of(corners)
    assert sorted(expected) == list(range(len(corners)))
    # Non-contiguous: every other triangle of a twice-as-long array, and a Fortran-ordered copy.
    doubled = np.repeat(corners, 2, axis=0)[::2]
    assert not doubled.flags.c_contiguous
    assert order_of(doubled) == expected
    assert order_of(np.asfortranarray(corners)) == expected
    # Other float types, converted once.
    assert order_of(corners.astype(np.float64)) == expected
    # (V, 3) vertices with (T, 3) indices, in another vertex order.
    vertices = corners.reshape(-1, 3)[::-1].copy()
    indices = (len(vertices) - 1 - np.arange(len(vertices))).reshape(-1, 3)
    assert order_of(vertices, triangles=indices.astype(np.int32)) == expected
    assert order_of(vertices, triangles=indices.astype(np.uint64)) == expected
    # Nested lists.
    assert order_of(corners.tolist()) == expected


def test_float32_vertex_buffers_are_read_where_they_are():
    """float32 vertices with x, y, z adjacent and uint32 indices go to the library's gather
    (vertex_positions.h) as they are: packed, interleaved with normals, or as corners. Each
    layout must order as the same corners written out plainly, triangle by triangle."""
    corners = overlapping_triangles()
    expected = order_of(corners)
    vertices = corners.reshape(-1, 3)[::-1].copy()
    indices = (len(vertices) - 1 - np.arange(len(vertices))).reshape(-1, 3).astype(np.uint32)
    assert np.array_equal(vertices[indices], corners)  # numpy's gather: the same corners
    assert order_of(vertices, triangles=indices) == expected
    # Interleaved: position then a normal, the positions a view with a 24-byte row stride; the
    # normals are NaN, so reading them would be an error.
    interleaved = np.full((len(vertices), 6), np.nan, np.float32)
    interleaved[:, :3] = vertices
    positions = interleaved[:, :3]
    assert positions.strides == (24, 4)
    assert order_of(positions, triangles=indices) == expected
    # Corners (T, 3, 3) interleaved the same way.
    corner_buffer = np.full((len(corners), 3, 6), np.nan, np.float32)
    corner_buffer[:, :, :3] = corners
    assert order_of(corner_buffer[:, :, :3]) == expected
    # The library's refusals are ValueErrors naming the array.
    outside = indices.copy()
    outside[3, 1] = len(vertices)
    with pytest.raises(ValueError, match=f"names vertex {len(vertices)}, outside 0..{len(vertices) - 1}"):
        order_of(vertices, triangles=outside)
    broken = interleaved.copy()
    broken[int(indices[5, 2]), 1] = np.inf
    with pytest.raises(ValueError, match="positions: triangle 5, corner 2 is not finite"):
        order_of(broken[:, :3], triangles=indices)


BAD_POSITIONS = [
    (np.zeros((0, 3, 3), np.float32), "no triangles"),
    (np.zeros((4, 3), np.float32), r"shape \(T, 3, 3\)"),
    (np.zeros((4, 3, 2), np.float32), r"got shape \(4, 3, 2\)"),
    (np.zeros((4, 3, 3), np.int32), "floating-point"),
    (np.zeros((4, 3, 3), np.complex64), "floating-point"),
    (np.array([[["a", "b", "c"]] * 3]), "floating-point"),
    (np.zeros(5, np.float32), r"got shape \(5,\)"),
    ("bunnies", "shape"),
    (None, "no positions"),
]


@pytest.mark.parametrize("positions,message", BAD_POSITIONS)
def test_bad_positions_raise_value_error(positions, message):
    with pytest.raises(ValueError, match=message):
        vissort.order(positions, camera=CAMERA)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf, 1e39])
def test_non_finite_coordinates_name_the_triangle(value):
    corners = overlapping_triangles()
    corners = corners.astype(np.float64)
    corners[5, 2, 1] = value
    with pytest.raises(ValueError, match="triangle 5, corner 2 is not finite"):
        vissort.order(corners, camera=CAMERA)
    with pytest.raises(ValueError, match="not finite"):
        vissort.collide(corners, objects=[6, 6])


def test_bad_indices_raise_value_error():
    vertices = overlapping_triangles().reshape(-1, 3)
    with pytest.raises(ValueError, match="names vertex 36, outside 0..35"):
        vissort.order(vertices, triangles=[[0, 1, 36]], camera=CAMERA)
    with pytest.raises(ValueError, match="names vertex -1"):
        vissort.order(vertices, triangles=[[0, 1, -1]], camera=CAMERA)
    with pytest.raises(ValueError, match="integer vertex indices"):
        vissort.order(vertices, triangles=[[0.0, 1.0, 2.0]], camera=CAMERA)
    with pytest.raises(ValueError, match=r"shape \(T, 3\)"):
        vissort.order(vertices, triangles=[0, 1, 2], camera=CAMERA)
    with pytest.raises(ValueError, match="not with a Scene"):
        vissort.order(vissort.builtin("slabs"), triangles=[[0, 1, 2]])


def test_bad_objects_raise_value_error():
    corners = overlapping_triangles()
    for objects, message in [([[0, 5], [5, 8]], "object 1"), ([0, 12], "object 0"),
                             ([[0, 2, 3]], "shape"), (np.zeros((0, 2), int), "no objects"),
                             ([1.5, 2], "integer"), ([[-1, 2]], "object 0"),
                             # first + count beyond 64 bits: refused, not wrapped around
                             ([[2**62, 2**62]], "object 0"), ([[1, 2**63 - 1]], "object 0")]:
        with pytest.raises(ValueError, match=message):
            vissort.order(corners, objects, camera=CAMERA)
    with pytest.raises(ValueError, match="brings its own objects"):
        vissort.order(vissort.builtin("slabs"), objects=[1])
    # Ordering takes objects that share triangles, as the library's orderer does; collision
    # detection refuses them (a triangle would collide with itself).
    shared = [[0, 6], [5, 7]]
    assert sorted(vissort.order(corners, shared, camera=CAMERA).order.tolist()) == [0, 1]
    with pytest.raises(ValueError, match="collision objects 0 and 1 share triangles"):
        vissort.collide(corners, shared)


def test_bad_names_sizes_cameras_and_times():
    scene = vissort.builtin("slabs", layers=3)
    for kwargs, message in [({"level": "pixel"}, "unknown level 'pixel'"),
                            ({"oracle": "magic"}, "unknown oracle 'magic'"),
                            ({"size": (0, 10)}, "out of range"),
                            ({"size": (20000, 10)}, "out of range"),
                            ({"size": (16384, 16384)}, "pixels"),
                            ({"size": "64x64"}, "width, height"),
                            ({"size": (1.5, 2)}, "width, height"),
                            ({"time": float("nan")}, "finite")]:
        with pytest.raises(ValueError, match=message):
            vissort.order(scene, **kwargs)
    with pytest.raises(ValueError, match="eye"):
        vissort.Camera.perspective((0, 0, 0), (0, 0, 0))
    with pytest.raises(ValueError, match="up"):
        vissort.Camera.perspective((0, 5, 0), (0, 0, 0), up=(0, 1, 0))
    with pytest.raises(ValueError, match="field of view"):
        vissort.Camera.perspective((0, 0, 5), (0, 0, 0), fov_deg=180)
    with pytest.raises(ValueError, match="direction"):
        vissort.Camera.orthographic((0, 0, 0))
    with pytest.raises(ValueError, match="finite"):
        vissort.Camera.orthographic((0, np.nan, 1))
    with pytest.raises(ValueError, match="three numbers"):
        vissort.Camera.perspective((0, 0), (0, 0, 0))
    with pytest.raises(ValueError, match="camera must be a vissort.Camera"):
        vissort.order(scene, camera="front")
    with pytest.raises(ValueError, match="scene must be a vissort.Scene"):
        vissort.Camera.orthographic((0, 0, -1), scene=3)
    with pytest.raises(ValueError, match="time must be a number"):
        vissort.order(scene, time="now")
    ortho = vissort.Camera.orthographic((0, 0, -2))
    assert ortho.projection == "orthographic" and ortho.eye is None and ortho.fov_deg is None
    assert ortho.direction == (0, 0, -2) or ortho.direction == (0.0, 0.0, -2.0)


def test_paths_and_a_scene_given_late():
    path = vissort.load(pathlib.Path(SOURCE_DIR) / "tests" / "data" / "meshes" / "cameras.gltf")
    assert path.triangle_count > 0 and [c[0] for c in path.cameras] == ["front", "top"]
    # An orderer made without objects takes a scene's when it is given one.
    scene = vissort.builtin("bunnies", n=3)
    assert len(vissort.Orderer().order(scene, size=(32, 32)).order) == 3


def test_bad_scenes_raise_value_error(tmp_path):
    with pytest.raises(ValueError, match="not found"):
        vissort.load(str(tmp_path / "missing.obj"))
    hostile = tmp_path / "nan.obj"
    hostile.write_text("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(ValueError):
        vissort.load(str(hostile))
    with pytest.raises(ValueError, match="unknown"):
        vissort.builtin("teapots")
    with pytest.raises(ValueError):
        vissort.builtin("bunnies", n=-3)
    with pytest.raises(ValueError, match="n"):
        vissort.builtin("bunnies", n="2&seed=4")
    with pytest.raises(ValueError, match="number or a string"):
        vissort.builtin("bunnies", n=[2])


def test_an_orderer_keeps_its_triangle_count():
    corners = overlapping_triangles()
    orderer = vissort.Orderer(level="triangle")
    orderer.order(corners, camera=CAMERA, size=(32, 32))
    with pytest.raises(ValueError, match="orders 12 triangles; got 6"):
        orderer.order(corners[:6], camera=CAMERA, size=(32, 32))


def test_outputs_own_their_memory_and_have_documented_types():
    scene = vissort.builtin("bunnies", n=3)
    result = vissort.order(scene, size=(64, 64), level="triangle")
    assert result.order.dtype == np.uint32 and result.order.shape == (scene.triangle_count,)
    assert sorted(result.order.tolist()) == list(range(scene.triangle_count))
    assert all(c.dtype == np.uint32 for c in result.cycles)
    assert scene.positions.dtype == np.float32
    assert scene.positions.shape == (scene.triangle_count, 3, 3)
    assert scene.triangles.shape == (scene.triangle_count, 3)
    assert scene.object_ranges.tolist() == [[o.first_triangle, o.triangle_count]
                                            for o in scene.objects]
    assert [o.name for o in scene.objects] == ["bunny_0", "bunny_1", "bunny_2"]
    assert all(len(o.colour) == 4 and o.transparent for o in scene.objects)
    # Writable, and owned: changing them changes nothing else.
    first_order = result.order[0]
    result.order[0] = 123456
    positions = scene.positions
    original = positions[0].copy()
    assert original.any()
    positions[0] = 0
    np.testing.assert_array_equal(scene.positions[0], original)
    assert vissort.order(scene, size=(64, 64), level="triangle").order[0] == first_order
    # A frame of a dynamic scene moves.
    assert not np.array_equal(scene.frame(0.0), scene.frame(1.0))
    assert np.array_equal(scene.frame(0.0), scene.positions)
