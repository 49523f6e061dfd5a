"""The GIL is released while the library works: another Python thread runs during an order, a
collision query and a render; OpenGL work from several threads takes turns and gives the same
images."""

import threading
import time

import numpy as np
import pytest

import vissort


def ticks_during(work):
    """Runs work() on a second thread while this one counts loop turns; returns the turns
    counted in the middle half of the call (none if the call held the GIL throughout)."""
    stamps, window = [], {}

    def worker():
        window["start"] = time.perf_counter()
        work()
        window["end"] = time.perf_counter()

    thread = threading.Thread(target=worker)
    thread.start()
    while thread.is_alive():
        stamps.append(time.perf_counter())
    thread.join()
    length = window["end"] - window["start"]
    low, high = window["start"] + length / 4, window["end"] - length / 4
    return sum(low <= s <= high for s in stamps), length


def test_another_thread_runs_while_an_order_is_computed():
    scene = vissort.builtin("bunnies", n=18, seed=2)
    counted, seconds = ticks_during(
        lambda: vissort.order(scene, level="triangle", size=(512, 512), oracle="cpu-reference"))
    assert counted > 100, f"{counted} turns of the other thread in {seconds:.2f} s"


def test_another_thread_runs_while_collisions_are_found():
    scene = vissort.builtin("bunnies", n=30, seed=1)
    counted, seconds = ticks_during(lambda: [vissort.collide(scene, time=t / 30, method="brute")
                                             for t in range(3)])
    assert counted > 100, f"{counted} turns of the other thread in {seconds:.2f} s"


def test_another_thread_runs_while_rendering():
    scene = vissort.builtin("bunnies", n=8)
    counted, seconds = ticks_during(lambda: vissort.render(scene, size=(256, 256),
                                                           method="linked-list"))
    assert counted > 100, f"{counted} turns of the other thread in {seconds:.2f} s"


def run_on_threads(work, threads, repeats):
    """Runs work() `repeats` times on each of `threads` threads at once; returns the results,
    and raises the first exception a thread met (an assertion in a thread is otherwise lost)."""
    results, errors = [], []

    def loop():
        try:
            for _ in range(repeats):
                results.append(work())
        except Exception as error:
            errors.append(error)

    started = [threading.Thread(target=loop) for _ in range(threads)]
    for t in started:
        t.start()
    for t in started:
        t.join()
    if errors:
        raise errors[0]
    return results


def test_opengl_from_several_threads_takes_turns():
    scene = vissort.builtin("bunnies", n=3, seed=2)
    expected = vissort.render(scene, size=(48, 48))
    expected_order = vissort.order(scene, size=(48, 48), oracle="gl").order.tolist()
    results = run_on_threads(lambda: (vissort.render(scene, size=(48, 48)),
                                      vissort.order(scene, size=(48, 48), oracle="gl")), 3, 3)
    assert len(results) == 9
    for image, order in results:
        np.testing.assert_array_equal(image, expected)
        assert order.order.tolist() == expected_order


def test_one_orderer_from_two_threads_is_serialised():
    scene = vissort.builtin("bunnies", n=4)
    orderer = vissort.Orderer(scene, level="triangle")
    expected = vissort.order(scene, level="triangle", size=(64, 64), time=0.4).order.tolist()
    results = run_on_threads(lambda: orderer.order(time=0.4, size=(64, 64)).order.tolist(), 2, 4)
    assert len(results) == 8 and all(r == expected for r in results)


def test_the_cpu_oracles_threads_never_change_an_order(order_verdict):
    """The default, threads=0 (one per core), 1, 2 and 3 give the same orders and counts over two
    frames of the pile's motion (its stuck set goes to the one-pass graph), and every frame of
    every run is exact by its own ground truth (order_check)."""
    spec, size = "builtin:pile?n=200", (320, 240)
    scene = vissort.builtin("pile", n=200)
    runs = []
    for threads in (None, 0, 1, 2, 3):
        options = {} if threads is None else {"threads": threads}
        orderer = vissort.Orderer(scene, **options)
        run = []
        for f in range(2):
            result = orderer.order(size=size, time=f / 30)
            verdict = order_verdict(spec, size, "static", 2, f, result.order, result.cycles)
            assert verdict["permutation"] == 1, (threads, f)
            assert verdict["violations"] == 0, (threads, f, verdict)
            assert verdict["checked"] > 0, (threads, f)
            run.append((result.order.tolist(), [c.tolist() for c in result.cycles],
                        {k: v for k, v in result.stats.items() if k != "ms"}))
        runs.append(run)
    assert runs[0][0][2]["graph_passes"] >= 1
    for run in runs[1:]:
        assert run == runs[0]
    one = vissort.order(scene, size=size, threads=3)
    assert one.order.tolist() == runs[0][0][0]


def test_a_negative_thread_count_is_refused():
    scene = vissort.builtin("slabs")
    try:
        vissort.Orderer(scene, threads=-1)
    except TypeError as error:
        assert "threads" in str(error) or "incompatible" in str(error)
    else:
        raise AssertionError("threads=-1 was accepted")


@pytest.mark.skipif(not vissort.has_gl, reason="render needs OpenGL; this build has none")
def test_renders_are_exact_and_the_same_on_every_thread_count():
    """Each picture within 1/255 of the per-pixel linked-list reference (an independent method),
    and the same bytes at 0, 1 and 3 threads."""
    scene = vissort.builtin("bunnies", n=6, seed=1)
    settings = dict(size=(160, 120), all_transparent=True)
    reference = vissort.render(scene, method="linked-list", **settings).astype(int)
    images = [vissort.render(scene, threads=t, **settings) for t in (0, 1, 3)]
    for image in images:
        assert np.abs(image.astype(int) - reference).max() <= 1
    assert np.array_equal(images[0], images[1])
    assert np.array_equal(images[0], images[2])
