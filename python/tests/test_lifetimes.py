"""Objects outliving each other: an orderer, renderer or detector keeps its scene alive; results
outlive whatever made them."""

import gc
import weakref

import numpy as np

import vissort


def drop(name, namespace):
    del namespace[name]
    gc.collect()


def test_a_scene_dropped_while_an_orderer_uses_it():
    scene = vissort.builtin("bunnies", n=4, seed=6)
    expected = vissort.order(scene, level="triangle", size=(64, 64), time=0.5).order.tolist()
    orderer = vissort.Orderer(scene, level="triangle")
    objects = scene.objects
    del scene
    gc.collect()
    result = orderer.order(time=0.5, size=(64, 64))
    assert result.order.tolist() == expected
    assert objects[0].name == "bunny_0"


def test_a_scene_dropped_while_a_renderer_and_a_detector_use_it():
    scene = vissort.builtin("bunnies", n=4, seed=6)
    expected_image = vissort.render(scene, size=(32, 32), time=0.2)
    expected_pairs = vissort.collide(scene, time=0.2)
    renderer = vissort.Renderer(scene)
    detector = vissort.CollisionDetector(scene)
    del scene
    gc.collect()
    np.testing.assert_array_equal(renderer.render(time=0.2, size=(32, 32)), expected_image)
    np.testing.assert_array_equal(detector.collide(time=0.2), expected_pairs)


def test_results_outlive_their_maker():
    scene = vissort.builtin("slabs", layers=5)
    orderer = vissort.Orderer(scene)
    result = orderer.order(size=(32, 32))
    order = result.order
    camera = result.camera
    del orderer, result, scene
    gc.collect()
    # The slabs are a stack seen from the front: one order, nearest first.
    assert order.tolist() == [4, 3, 2, 1, 0]
    assert camera.projection == "perspective"


def test_the_orderer_does_not_keep_the_callers_arrays():
    corners = np.random.default_rng(1).uniform(-1, 1, (20, 3, 3)).astype(np.float32)
    reference = weakref.ref(corners)
    orderer = vissort.Orderer(level="triangle")
    first = orderer.order(corners, size=(32, 32)).order.tolist()
    copy = corners.copy()
    del corners
    gc.collect()
    assert reference() is None, "read once, not kept"
    assert sorted(orderer.order(copy, size=(32, 32)).order.tolist()) == sorted(first)


def test_many_scenes_and_orderers_made_and_dropped():
    # Reference counting across the boundary: nothing leaks or is freed twice.
    for i in range(30):
        scene = vissort.builtin("soup", n=50, seed=i)
        orderer = vissort.Orderer(scene, level="triangle")
        assert len(orderer.order(size=(16, 16)).order) == 50
        if i % 2:
            del scene
        del orderer
    gc.collect()
