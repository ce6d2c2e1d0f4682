"""What the Python module's guarantees cost (docs/reliability.md, "Python: what the module
guarantees"): a program that prints numbers, not a test.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_safety.py [--repeats 9]

1. An observed run with a large population (5000 x 200): the observer gets copies of the
   population and its values; the run observed and unobserved, and one copy of 8 MB by numpy.
2. A tiny minimize, 3000 times: on the main thread (where Ctrl-C is taken: a SIGINT handler in
   front of Python's around the run), on another thread (nothing), and on the main thread under
   a SIGINT handler of the user's (the run on a helper thread while the main one runs handlers).
"""
import argparse
import signal
import statistics
import threading
import time

import numpy as np

import pride


def median_time(fn, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def per_call(n):
    start = time.perf_counter()
    for _ in range(n):
        pride.minimize("pso", "sphere", dim=2, evals=100)
    return (time.perf_counter() - start) / n


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument("--calls", type=int, default=3000)
    args = parser.parse_args()

    kw = dict(dim=200, evals=5000 * 21, pop=5000, seed=1)
    observed = median_time(lambda: pride.minimize("pso", "sphere", callback=lambda *a: None, **kw), args.repeats)
    plain = median_time(lambda: pride.minimize("pso", "sphere", **kw), args.repeats)
    a = np.random.default_rng(1).random((5000, 200))
    copy = median_time(a.copy, 51)
    print(f"observed run, 5000 x 200, 21 iterations: {observed * 1e3:.1f} ms; unobserved {plain * 1e3:.1f} ms; "
          f"one 8 MB copy {copy * 1e3:.2f} ms")

    main_thread = per_call(args.calls)
    other = []
    t = threading.Thread(target=lambda: other.append(per_call(args.calls)))
    t.start()
    t.join()
    previous = signal.signal(signal.SIGINT, lambda *a: None)
    try:
        custom = per_call(args.calls)
    finally:
        signal.signal(signal.SIGINT, previous)
    print(f"tiny minimize: main thread {main_thread * 1e6:.0f} us a call, another thread {other[0] * 1e6:.0f} us, "
          f"main thread under a custom SIGINT handler {custom * 1e6:.0f} us")


if __name__ == "__main__":
    main()
