"""vissort.Grid, load_grid, render_volume and VolumeRenderer: grids from files and arrays, and
pictures equal to the command line's (docs/volume.md)."""

import math

import numpy as np
import pytest
from PIL import Image

import vissort

UNIT_CUBE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                      [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)


def test_load_grid_reads_builtin_grids_and_files():
    grid = vissort.load_grid("builtin:cube?n=3")
    assert grid.tets.shape == (6 * 27, 4)
    assert grid.points.shape == (64, 3)
    assert grid.scalars.shape == (64,)
    facts = grid.facts()
    assert facts["convex"] is True
    assert facts["boundary_faces"] == 6 * 9 * 2
    assert vissort.load_grid("builtin:torus?n=8").facts()["convex"] is False
    with pytest.raises(ValueError, match="missing.vtu: file not found"):
        vissort.load_grid("missing.vtu")


def test_grid_from_arrays_splits_hexahedra():
    grid = vissort.Grid(UNIT_CUBE, [[0, 1, 2, 3, 4, 5, 6, 7]], UNIT_CUBE[:, 0])
    tets = grid.tets
    assert tets.shape == (6, 4)
    p = grid.points
    volumes = [np.dot(np.cross(p[b] - p[a], p[c] - p[a]), p[d] - p[a]) / 6 for a, b, c, d in tets]
    assert all(v > 0 for v in volumes)
    assert math.isclose(sum(volumes), 1.0)
    with pytest.raises(ValueError, match="cell 0 names point 9 of 8"):
        vissort.Grid(UNIT_CUBE, [[0, 1, 2, 9]])
    with pytest.raises(ValueError, match="width 7"):
        vissort.Grid(UNIT_CUBE, [[0, 1, 2, 3, 4, 5, 6]])
    with pytest.raises(ValueError, match="one per point"):
        vissort.Grid(UNIT_CUBE, [[0, 1, 3, 4]], [1.0, 2.0])
    with pytest.raises(ValueError, match="degenerate"):
        vissort.Grid(UNIT_CUBE, [[0, 1, 2, 3]])  # four corners of one face: no volume


def test_render_volume_equals_the_command_line(cli, tmp_path):
    png = tmp_path / "lists.png"
    cli("volume", "builtin:torus?n=8", "--size", "48x40", "--method", "lists", "--tf", "bands", "-o", png)
    expected = np.asarray(Image.open(png).convert("RGBA"))
    image = vissort.render_volume(vissort.load_grid("builtin:torus?n=8"), size=(48, 40), method="lists",
                                  tf="bands")
    assert image.shape == (40, 48, 4)
    assert np.array_equal(image, expected)


def test_methods_against_the_ray_caster():
    grid = vissort.load_grid("builtin:knot?n=14")
    camera = vissort.Camera.perspective(eye=(1.2, 1.9, 2.6), target=(0, 0, 0))
    truth = vissort.render_volume(grid, camera, size=(48, 48), method="raycast", tf="bands", density=6)
    renderer = vissort.VolumeRenderer(grid, "vissort")
    image = renderer.render(camera, size=(48, 48), tf="bands", density=6)
    assert np.abs(image.astype(int) - truth).max() <= 1
    stats = renderer.stats
    assert stats["cells"] == len(grid.tets)
    assert stats["queries"] >= len(grid.tets) - 1  # pass 1: every cell but the first drawn
    assert stats["segments"] > 0
    mpvo = vissort.render_volume(grid, camera, size=(48, 48), method="mpvo", tf="bands", density=6)
    assert np.abs(mpvo.astype(int) - truth).max() > 16


def test_transfer_functions_as_rows_and_their_errors():
    grid = vissort.load_grid("builtin:cube?n=2")
    rows = [[0.0, 1.0, 0.0, 0.0, 2.0], [1.0, 0.0, 0.0, 1.0, 2.0]]
    image = vissort.render_volume(grid, size=(16, 16), tf=rows)
    centre = image[8, 8]
    assert centre[0] > 0 or centre[2] > 0
    with pytest.raises(ValueError, match="did you mean 'fire'"):
        vissort.render_volume(grid, size=(16, 16), tf="fier")
    with pytest.raises(ValueError, match="scalar, r, g, b, extinction"):
        vissort.render_volume(grid, size=(16, 16), tf=[[0, 1, 1]])
    with pytest.raises(ValueError, match="density"):
        vissort.render_volume(grid, size=(16, 16), density=-1)
    with pytest.raises(ValueError, match="unknown volume method 'ray'"):
        vissort.VolumeRenderer(grid, "ray")
    no_scalars = vissort.Grid(UNIT_CUBE, [[0, 1, 2, 3, 4, 5, 6, 7]])
    with pytest.raises(ValueError, match="no point scalars"):
        vissort.render_volume(no_scalars, size=(8, 8))
