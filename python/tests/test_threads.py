# SPDX-License-Identifier: MIT
"""Threads: results equal the sequential ones, and the GIL is released while the C++ runs."""

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import roiclip

QUAD = [[100, 50], [900, 120], [950, 900], [60, 880]]


def _random_polygon(seed, n):
    """A heavily self-intersecting polygon: n random vertices in a 1000 px square."""
    return np.random.default_rng(seed).integers(0, 1000, (n, 2)).astype(np.float64)


def _fingerprint(region):
    return (region.area, region.ring_count,
            [(p.exterior.tobytes(), [h.tobytes() for h in p.holes], p.parent) for p in region])


def test_parallel_results_equal_sequential():
    inputs = [_random_polygon(seed, 300) for seed in range(8)]
    jobs = [lambda p=p: _fingerprint(roiclip.intersect(p, QUAD)) for p in inputs]
    jobs += [lambda p=p: _fingerprint(roiclip.simplify(p, "nonzero")) for p in inputs]
    jobs += [lambda p=p: [a.tobytes() for a in roiclip.clip_lines(p, QUAD)] for p in inputs]
    jobs += [lambda p=p: roiclip.rasterize(p, (1000, 1000)).tobytes() for p in inputs[:3]]
    sequential = [job() for job in jobs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(lambda job: job(), jobs))
    assert parallel == sequential


def _ticks_during(call):
    """Run `call` while another Python thread records a timestamp every millisecond; return the
    call's (start, end) and the timestamps. While a thread holds the GIL inside C++, no other
    Python thread can run at all, so no timestamp can fall inside the call (apart from a few ms
    at its edges, where the interpreter may switch threads before entering the C++ code)."""
    stamps = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            stamps.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    try:
        time.sleep(0.02)
        start = time.perf_counter()
        call()
        end = time.perf_counter()
    finally:
        stop.set()
        thread.join()
    return start, end, stamps


def _assert_other_threads_ran(call):
    start, end, stamps = _ticks_during(call)
    duration = end - start
    assert duration > 0.1, f"the call took {duration:.3f} s, too short to tell"
    # The middle half of the call: far from its edges, on a loaded machine too.
    middle = [s for s in stamps if start + duration / 4 < s < end - duration / 4]
    assert middle, (f"no other Python thread ran during the middle {duration / 2:.3f} s of the "
                    f"call: the GIL was held")


def test_gil_released_while_clipping():
    heavy = _random_polygon(7, 1500)  # about 0.5 s on an idle core
    _assert_other_threads_ran(lambda: roiclip.intersect(heavy, QUAD))


def test_gil_released_while_detecting(scene_gray):
    big = np.tile(scene_gray, (3, 3))  # 2400 x 1800: about 0.6 s at full resolution
    detector = roiclip.Detector(quad_decimate=1)  # automatic decimation is too fast to tell
    found = []
    _assert_other_threads_ran(lambda: found.extend(detector.detect(big)))
    assert len(found) == 36


def test_one_detector_from_several_threads(scene_gray):
    detector = roiclip.Detector()
    expected = [(t.id, t.corners.tobytes()) for t in detector.detect(scene_gray)]
    with ThreadPoolExecutor(max_workers=3) as pool:
        results = list(pool.map(lambda _: [(t.id, t.corners.tobytes())
                                           for t in detector.detect(scene_gray)], range(6)))
    assert all(r == expected for r in results)
