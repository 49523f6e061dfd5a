"""The module's images equal the command line's PNGs on the same scene, camera, size and
settings, and stay exact over coherent frames."""

import numpy as np
import pytest
from PIL import Image

from conftest import source_file

import vissort


def cli_image(cli, tmp_path, *args):
    path = tmp_path / "cli.png"
    cli("render", *args, "-o", path)
    return np.asarray(Image.open(path).convert("RGBA"))


@pytest.mark.parametrize("method", ["vissort", "linked-list", "peel", "weighted"])
def test_images_equal_the_cli(cli, tmp_path, method):
    scene = vissort.builtin("bunnies", n=4, seed=2)
    image = vissort.render(scene, size=(96, 72), method=method)
    assert image.shape == (72, 96, 4) and image.dtype == np.uint8
    expected = cli_image(cli, tmp_path, "builtin:bunnies?n=4&seed=2", "--size", "96x72",
                         "--method", method)
    np.testing.assert_array_equal(image, expected)
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 10, "a picture, not a blank"


def test_settings_and_camera_equal_the_cli(cli, tmp_path):
    scene = vissort.builtin("plant", layers=2)
    camera = vissort.Camera.perspective((30, 12, 25), (0, 2, 0), fov_deg=50)
    image = vissort.render(scene, camera, (80, 64), level="triangle", all_transparent=True,
                           alpha=0.4, shading="flat")
    expected = cli_image(cli, tmp_path, "builtin:plant?layers=2", "--size", "80x64", "--level",
                         "triangle", "--all-transparent", "--alpha", "0.4", "--shading", "flat",
                         "--eye", "30,12,25", "--target", "0,2,0", "--fov", "50")
    np.testing.assert_array_equal(image, expected)


def test_membrane_and_samples_equal_the_cli(cli, tmp_path):
    scene = vissort.builtin("bunnies", n=4, seed=2)
    image = vissort.render(scene, size=(64, 48), shading="membrane", samples=4)
    expected = cli_image(cli, tmp_path, "builtin:bunnies?n=4&seed=2", "--size", "64x48",
                         "--shading", "membrane", "--samples", "4")
    np.testing.assert_array_equal(image, expected)
    # The samples show: one sample a pixel is another picture.
    one = vissort.render(scene, size=(64, 48), shading="membrane")
    assert np.abs(image.astype(int) - one.astype(int)).max() > 1


@pytest.mark.parametrize("samples", [0, 3, 16])
def test_samples_other_than_1_2_4_8_are_refused(samples):
    with pytest.raises(ValueError, match="samples must be 1, 2, 4 or 8"):
        vissort.Renderer(vissort.builtin("bunnies", n=1), samples=samples)


def test_exact_against_linked_list_over_coherent_frames():
    # The renderer keeps the order from frame to frame; every frame stays within 1/255 of the
    # per-pixel linked-list reference (an independent method).
    scene = vissort.builtin("bunnies", n=6, seed=4)
    renderer = vissort.Renderer(scene, all_transparent=True)
    reference = vissort.Renderer(scene, method="linked-list", all_transparent=True)
    for f in range(3):
        a = renderer.render(time=f / 30, size=(64, 64)).astype(int)
        b = reference.render(time=f / 30, size=(64, 64)).astype(int)
        assert np.abs(a - b).max() <= 1
    assert renderer.stats["iterations"] >= 1
    assert reference.stats["fragments"] > 0
    # The ordering's counts, under the names an order's stats has (one field table for both).
    order_stats = vissort.order(scene, size=(64, 64)).stats
    assert set(order_stats) - {"ms"} <= set(renderer.stats)


def test_positions_of_another_count_are_refused():
    scene = vissort.builtin("bunnies", n=2)
    renderer = vissort.Renderer(scene)
    with pytest.raises(ValueError, match="triangles"):
        renderer.render(size=(16, 16), positions=scene.positions[:10])


def test_background_fills_empty_pixels():
    scene = vissort.builtin("slabs", layers=2)
    image = vissort.render(scene, size=(64, 64), background=(0, 0, 1))
    assert image[0, 0].tolist() == [0, 0, 255, 255]
    with pytest.raises(ValueError, match="background"):
        vissort.render(scene, size=(8, 8), background=(2, 0, 0))


def test_camera_of_scene_is_the_cli_camera(cli, tmp_path):
    # The command line's camera policy, by the same options: the same picture.
    scene = vissort.builtin("bunnies", n=4, seed=2)
    camera = vissort.Camera.of_scene(scene, azimuth=120, elevation=-15, size=(80, 60))
    image = vissort.render(scene, camera, (80, 60))
    expected = cli_image(cli, tmp_path, "builtin:bunnies?n=4&seed=2", "--size", "80x60",
                         "--azimuth", "120", "--elevation", "-15")
    np.testing.assert_array_equal(image, expected)
    # The eye lies in the direction the angles give from the target (sin A cos E, sin E,
    # cos A cos E), worked out here.
    a, e = np.radians(120), np.radians(-15)
    direction = np.subtract(camera.eye, camera.target)
    np.testing.assert_allclose(direction / np.linalg.norm(direction),
                               [np.sin(a) * np.cos(e), np.sin(e), np.cos(a) * np.cos(e)],
                               atol=1e-9)
    # Nothing asked is the default camera.
    default = vissort.Camera.default(scene, size=(80, 60))
    assert vissort.Camera.of_scene(scene, size=(80, 60)).eye == default.eye


def test_camera_of_scene_names_its_keywords_in_errors():
    scene = vissort.builtin("bunnies", n=2)
    with pytest.raises(ValueError, match="ortho_dir cannot be combined with eye, target, up "
                                         "or fov_deg"):
        vissort.Camera.of_scene(scene, ortho_dir=(0, 0, -1), fov_deg=30)
    with pytest.raises(ValueError, match="azimuth, elevation and distance place the eye"):
        vissort.Camera.of_scene(scene, azimuth=10, eye=(0, 0, 5))
    with pytest.raises(ValueError, match="frames must be between 1 and 100000"):
        vissort.Camera.of_scene(scene, frames=0)


def test_highlighted_collisions_equal_the_cli(cli, tmp_path):
    path = source_file("tests/data/scenes/crossed_bars.json")
    scene = vissort.load(path)
    renderer = vissort.Renderer(scene, highlight_collisions=True)
    image = renderer.render(size=(96, 72))
    expected = cli_image(cli, tmp_path, path, "--size", "96x72", "--highlight-collisions")
    np.testing.assert_array_equal(image, expected)
    stats = renderer.stats
    assert stats["colliding_pairs"] > 0 and stats["colliding_triangles"] > 0
    # The highlight shows: without it, another picture, and no collision counts.
    plain = vissort.Renderer(scene)
    assert np.abs(plain.render(size=(96, 72)).astype(int) - image.astype(int)).max() > 1
    assert "colliding_pairs" not in plain.stats


def test_levels_of_detail_equal_the_cli_and_zero_is_every_triangle(cli, tmp_path):
    scene = vissort.builtin("powerplant", scale=0.05)
    image = vissort.render(scene, size=(96, 72), lod_error=2)
    expected = cli_image(cli, tmp_path, "builtin:powerplant?scale=0.05", "--size", "96x72",
                         "--lod-error", "2")
    np.testing.assert_array_equal(image, expected)
    renderer = vissort.Renderer(scene, lod_error=2)
    renderer.render(size=(96, 72))
    assert 0 < renderer.stats["triangles"] < scene.triangle_count
    full = vissort.Renderer(scene, lod_error=0)
    np.testing.assert_array_equal(full.render(size=(96, 72)), vissort.render(scene, size=(96, 72)))
    assert full.stats["triangles"] == scene.triangle_count
    with pytest.raises(ValueError, match="lod_error"):
        vissort.Renderer(scene, lod_error=-1)
