"""Ctrl-C during a render: KeyboardInterrupt at the next tile, and the process renders on."""
import _thread
import signal
import threading
import time

import numpy as np
import pytest

import candela
from conftest import tiny_document

# A render of minutes if nothing stopped it.
LONG = {"spp": 1 << 24, "resolution": (64, 64), "threads": 2}


@pytest.mark.parametrize("interrupt", [
    lambda: _thread.interrupt_main(),              # what Ctrl-C does, as Python simulates it
    lambda: signal.raise_signal(signal.SIGINT),    # a real SIGINT (Python's handler takes it)
])
def test_interrupt_raises_keyboard_interrupt_and_rendering_goes_on(interrupt):
    scene = candela.Scene.from_dict(tiny_document())
    timer = threading.Timer(0.3, interrupt)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        candela.render(scene, **LONG)
    assert time.monotonic() - start < 5.0  # stopped at the next tile, not minutes later at the end
    timer.join()
    # The next render is whole and the same as ever.
    a = candela.render(scene, spp=4, threads=2)
    assert a.stats["end"] == "complete"
    assert np.array_equal(a, candela.render(scene, spp=4, threads=1))


def test_a_render_on_another_thread_is_not_interrupted_by_signals_meant_for_main():
    scene = candela.Scene.from_dict(tiny_document())
    result = {}
    worker = threading.Thread(target=lambda: result.update(image=candela.render(scene, spp=64, threads=1)))
    worker.start()
    worker.join()
    assert result["image"].stats["end"] == "complete"
