"""Threads: the GIL is released while rendering; two renders at once give their own bits."""
import threading
import time

import numpy as np

import candela
from conftest import tiny_document


def test_two_renders_from_two_threads_give_each_ones_own_bits():
    scenes = [candela.Scene.from_dict(tiny_document(albedo=a)) for a in (0.3, 0.8)]
    keywords = {"spp": 16, "resolution": (48, 32), "threads": 1}
    alone = [candela.render(s, **keywords) for s in scenes]
    together = [None, None]

    def run(i):
        for _ in range(3):
            image = candela.render(scenes[i], **keywords)
            assert together[i] is None or np.array_equal(image, together[i])
            together[i] = image

    threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(alone, together):
        assert np.array_equal(a, b)
    assert not np.array_equal(alone[0], alone[1])


def test_python_runs_while_a_render_does():
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        image = candela.render(candela.Scene.from_dict(tiny_document()), spp=1 << 24, resolution=(64, 64),
                               time_limit=0.5, threads=1)
    finally:
        stop.set()
        ticker.join()
    assert image.stats["end"] == "time_limit"
    # 10 ms apart over 0.5 s: about 50 while the GIL is free, one or two if the render held it (at least
    # 5 leaves room for a loaded machine)
    assert len(ticks) >= 5
