"""Model runs release the GIL: two Python threads run at once and give the sequential results."""
import threading
import time

import numpy as np
import rockroll

from conftest import LOADED, without_run_specifics


def test_two_threads_run_concurrently_with_the_sequential_results():
    sc = rockroll.load(LOADED)
    speeds = [14.0, 17.0]
    t0 = time.perf_counter()
    sequential = [rockroll.run(sc, model="halfcar", speed_mph=v, duration_s=1.5) for v in speeds]
    t_sequential = time.perf_counter() - t0

    rockroll._rockroll._reset_concurrency()
    threaded = [None, None]

    def work(i):
        threaded[i] = rockroll.run(sc, model="halfcar", speed_mph=speeds[i], duration_s=1.5)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    t_threaded = time.perf_counter() - t0
    running, peak = rockroll._rockroll._concurrency()

    # Both runs were inside their GIL-released section at the same time.
    assert running == 0 and peak == 2
    for a, b in zip(sequential, threaded):
        assert without_run_specifics(a.summary) == without_run_specifics(b.summary)
        assert a.history.dtype == b.history.dtype
        assert np.array_equal(a.history.view(np.float64), b.history.view(np.float64))
    print(f"\ntwo 1.5 s halfcar runs: sequential {t_sequential:.2f} s wall, two threads {t_threaded:.2f} s wall")
