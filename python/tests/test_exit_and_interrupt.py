"""The module's calls against the interpreter's exit and Ctrl-C, in child processes:

- daemon threads still inside minimize, plan or Campaign.run when the main thread ends: the
  process exits 0 (the module's atexit hook stops them and waits until they have left its C++
  frames; a thread that takes the GIL during finalisation is ended by a forced unwinding, which
  C++ frames turned into std::terminate);
- SIGINT during a long Campaign.run (Python functions, registered problems or an algorithm written
  in Python, one job or two) or minimize of a registered problem: KeyboardInterrupt within a fraction of a second, with the runs
  finished before it stored and none cut short."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import pride

CHILD_ENV = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))


def python(code, **kw):
    return subprocess.Popen([sys.executable, "-c", textwrap.dedent(code)], env=CHILD_ENV, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, **kw)


DAEMONS = """
    import os, sys, tempfile, threading, time
    import numpy as np
    import pride

    folder = tempfile.mkdtemp()
    started = threading.Semaphore(0)

    def f(x):
        started.release()
        return float(x @ x)

    def rows(X):
        started.release()
        return np.sum(X * X, axis=1)

    def length(cells):
        started.release()
        return float(len(cells))

    grid = pride.Grid(np.zeros((30, 30), dtype=int))
    calls = [
        lambda i: pride.minimize("pso", f, bounds=(-1, 1), dim=5, evals=10**9),
        lambda i: pride.minimize("ga", rows, bounds=(-1, 1), dim=5, evals=10**9, vectorized=True),
        lambda i: pride.minimize("pso", "sphere", dim=20, evals=20_000),    # short runs, one after another
        lambda i: pride.minimize("pso", "rastrigin", dim=20, evals=10**9),  # one long run
        lambda i: pride.minimize("pso", "sphere", dim=5, evals=10**9, callback=lambda *a: started.release()),
        lambda i: pride.plan(grid, (0, 0), (29, 29), algo="pso", objective=length, evals=10**9),
        lambda i: pride.Campaign("d", seeds=50, evals=100_000, algorithms=["pso"],
                                 problems=[{"id": "s", "problem": "sphere", "dim": 20}]).run(
                                     os.path.join(folder, f"r{i}.sqlite"), jobs=2),
        lambda i: pride.Campaign("d", seeds=50, evals=10**7, algorithms=["pso"],
                                 problems=[{"id": "f", "function": f, "bounds": (-1, 1), "dim": 3}]).run(
                                     os.path.join(folder, f"f{i}.sqlite"), jobs=2),
    ]

    def loop(i, call):
        while True:
            call(i)

    for i, call in enumerate(calls):
        threading.Thread(target=loop, args=(i, call), daemon=True).start()
    for _ in range(5):  # the Python functions, observer and path objective are being called
        started.acquire()
    time.sleep(0.3)
    print("exiting", flush=True)
"""


def test_daemon_threads_inside_the_module_at_exit():
    for attempt in range(5):
        p = python(DAEMONS)
        out, err = p.communicate(timeout=120)
        assert out == "exiting\n", err
        assert p.returncode == 0, f"attempt {attempt}: status {p.returncode}: {err[-2000:]}"
        for word in ("terminate", "abort", "Abort", "FATAL", "Segmentation", "Traceback"):
            assert word not in err, f"attempt {attempt}: {err[-2000:]}"


def test_calls_once_the_exit_has_begun():
    # Hooks registered before pride's run after it (atexit runs the last registered first): by
    # then another thread's call raises SystemExit (it would start work the exit cannot wait
    # for), and the main thread's still runs.
    p = python("""
        import atexit, threading

        def at_exit():
            outcome = []

            def late():
                try:
                    pride.minimize("pso", "sphere", dim=2, evals=100)
                    outcome.append("ran")
                except SystemExit as e:
                    outcome.append(f"SystemExit: {e}")

            t = threading.Thread(target=late)
            t.start()
            t.join()
            print(outcome[0], flush=True)
            print(pride.minimize("pso", "sphere", dim=2, evals=100).evaluations, flush=True)

        atexit.register(at_exit)
        import pride
    """)
    out, err = p.communicate(timeout=60)
    assert p.returncode == 0, err
    assert out == "SystemExit: pride: the interpreter is exiting; the call was stopped\n100\n", err


INTERRUPTED = """
    import os, sys, time
    import numpy as np
    import pride

    kind, jobs, store = sys.argv[1], int(sys.argv[2]), sys.argv[3]

    def slow(x):  # about 1 ms a call
        return float(sum(v * v for v in x.tolist() * 200))

    def random_search(problem, seed):  # an algorithm written in Python
        rng = np.random.default_rng(seed)
        while True:
            problem.evaluate(rng.uniform(problem.lower, problem.upper, size=(10, problem.dim)))

    pride.register_algorithm("py-rs", random_search)

    if kind == "function":  # 1200 runs of 2000 calls: about 40 minutes of work
        c = pride.Campaign("i", seeds=1200, evals=2_000, algorithms=["pso"],
                           problems=[{"id": "slow", "function": slow, "bounds": (-1, 1), "dim": 3}])
    elif kind == "short":  # 4000 runs of 10 ms: 40 s, and runs finish before the interrupt
        c = pride.Campaign("i", seeds=4000, evals=20_000, algorithms=["pso"],
                           problems=[{"id": "r", "problem": "rastrigin", "dim": 10}])
    elif kind == "registered":  # runs of 10^9 evaluations
        c = pride.Campaign("i", seeds=40, evals=10**9, algorithms=["pso", "ga"],
                           problems=[{"id": "r", "problem": "rastrigin", "dim": 10}])
    elif kind == "python":  # runs of 10^9 evaluations, by a Python algorithm beside a C++ one
        c = pride.Campaign("i", seeds=40, evals=10**9, algorithms=["py-rs", "pso"],
                           problems=[{"id": "r", "problem": "rastrigin", "dim": 10}])
    print("running", flush=True)
    if kind == "minimize":
        pride.minimize("pso", "rastrigin", dim=10, evals=10**12 // 10**3)
    elif kind == "python-minimize":
        pride.minimize("py-rs", "rastrigin", dim=10, evals=10**12 // 10**3)
    else:
        c.run(store, jobs=jobs)
    print("ended without an interrupt", flush=True)
"""


def interrupt(kind, jobs, store, after=1.5):
    p = subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(INTERRUPTED), kind, str(jobs), store], env=CHILD_ENV,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert p.stdout.readline() == "running\n"
    time.sleep(after)
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=120)
    took = time.monotonic() - sent
    return p.returncode, took, out, err


@pytest.mark.parametrize("kind, jobs", [("function", 1), ("function", 2), ("registered", 1), ("registered", 2),
                                        ("short", 1), ("short", 2), ("minimize", 1), ("python", 1),
                                        ("python", 2), ("python-minimize", 1)])
def test_ctrl_c_stops_a_campaign_or_a_run_promptly(tmp_path, kind, jobs):
    store = str(tmp_path / "s.sqlite")
    status, took, out, err = interrupt(kind, jobs, store)
    assert "KeyboardInterrupt" in err and "ended without an interrupt" not in out, err[-2000:]
    assert status == -signal.SIGINT, err[-2000:]  # Python ends by SIGINT on an uncaught KeyboardInterrupt
    assert took < 5.0, f"{kind}, jobs={jobs}: {took:.2f} s from SIGINT to the end"
    if kind in ("minimize", "python-minimize"):
        return
    # What the store holds is whole runs only: each with its full budget, none cut short.
    runs = pride.read_store(store, dataframe=False)
    budget = {"function": 2_000, "short": 20_000, "registered": 10**9, "python": 10**9}[kind]
    assert all(r["evaluations"] == budget for r in runs), sorted({r["evaluations"] for r in runs})
    if kind == "short":
        assert len(runs) > 0  # the runs that finished before the interrupt were kept
    if kind in ("registered", "python"):
        assert runs == []


class Custom(Exception):
    pass


def with_sigint_handler(handler, call, after=0.5):
    """call() with `handler` for SIGINT, and a SIGINT sent to this process after `after` s."""
    previous = signal.signal(signal.SIGINT, handler)
    timer = threading.Timer(after, lambda: os.kill(os.getpid(), signal.SIGINT))
    try:
        timer.start()
        start = time.monotonic()
        try:
            return call(), time.monotonic() - start
        finally:
            timer.join()
    finally:
        signal.signal(signal.SIGINT, previous)


def test_a_custom_sigint_handler_runs_during_a_run_and_what_it_raises_stops_it():
    # Python's own handlers run on the main thread between bytecodes; the module runs them every
    # 20 ms while C++ works there, so a handler that raises stops the run promptly...
    def raises(signum, frame):
        raise Custom("from the handler")

    with pytest.raises(Custom, match="from the handler"):
        with_sigint_handler(raises, lambda: pride.minimize("pso", "rastrigin", dim=10, evals=10**12 // 10**3))
    # ... and one that does not raise leaves the run whole.
    seen = []
    (r, ended), took = with_sigint_handler(
        lambda *a: seen.append(time.monotonic()),
        lambda: (pride.minimize("pso", "rastrigin", dim=10, evals=6_000_000, seed=1), time.monotonic()), after=0.2)
    assert len(seen) == 1 and seen[0] < ended, "the handler ran during the run"
    assert r.evaluations == 6_000_000
    assert r.history.tobytes() == pride.minimize("pso", "rastrigin", dim=10, evals=6_000_000, seed=1).history.tobytes()
