#!/usr/bin/python3
"""Reference values for tests/test_bootstrap.cpp, computed with cocopp's own functions.

cocopp (numbbo/coco-postprocess) is run from its source tree, unmodified: the package is copied to
a temporary directory, beside it a stand-in for `platformdirs` (Debian 12's 2.6 lacks
`user_cache_dir(..., ensure_exists=...)`) and the `cocopp/_version.py` that its packaging would
write. Nothing under the source tree is changed.

Run: /usr/bin/python3 scripts/cocopp_bootstrap_reference.py [COCOPP_SRC]
     (COCOPP_SRC defaults to /tmp/coco-postprocess/src/cocopp; prints the values the test hard-codes)

The samples are random (cocopp draws from numpy's global generator, seeded here), so the test
compares its own samples with these statistically: the tolerances are in the test.
"""
import os
import sys
import warnings

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cocopp_check import import_cocopp  # noqa: E402  the same stand-ins as the export's check

source = sys.argv[1] if len(sys.argv) > 1 else "/tmp/coco-postprocess/src/cocopp"
with warnings.catch_warnings():
    warnings.simplefilter("ignore")  # cocopp's online archive, unreachable here
    cocopp = import_cocopp(source)
from cocopp import toolsstats  # noqa: E402

print("numpy", np.__version__)

# --- One target, 15 runs: 5 reached it (hit after these evaluations), 10 did not (evaluations).
hits = [230, 410, 415, 980, 1200]
fails = [3000, 3000, 3000, 2500, 1800, 3200, 2900, 3000, 3000, 2750]
data = np.array(sorted(hits) + sorted(fails), dtype=float)  # sorted: draw() sorts its data
succ = np.array([True] * len(hits) + [False] * len(fails))
ert = toolsstats.sp(data, issuccessful=succ)[0]
print(f"sp (ERT): {ert!r}")

# Simulated restarts, cocopp's drawSP (the ERT tables' 10/50/90 percentiles, pptable.py).
n = 100000
np.random.seed(1)
percentiles, sample = toolsstats.drawSP(np.array(hits, float), np.array(fails, float), [10, 50, 90], n)
sample = np.asarray(sample)
print(f"drawSP n={n}: percentiles 10, 50, 90 = {[float(p) for p in percentiles]}, mean {sample.mean()!r}")
thresholds = [230, 415, 1200, 2000, 3500, 5000, 7000, 10000, 15000, 25000]
print("drawSP CDF at", thresholds, ":", [repr(float(np.mean(sample <= t))) for t in thresholds])
# Quantile brackets for a second sample of the same size: a two-sample KS bound at alpha = 0.001.
eps = 1.949 * np.sqrt(2.0 / n)
for p in (10, 50, 90):
    lo, hi = toolsstats.prctile(sample, [p - 100 * eps, p + 100 * eps], issorted=True)
    print(f"drawSP percentile {p} +- {100 * eps:.4f}: [{lo!r}, {hi!r}]")

# The bootstrap distribution of the ERT itself: cocopp's draw() with func=sp (resampling runs).
m = 20000
np.random.seed(2)
ci, boot = toolsstats.draw(data, [10, 50, 90], samplesize=m, func=toolsstats.sp, args=[np.inf, succ])
boot = np.asarray(boot)
print(f"draw(sp) m={m}: percentiles 10, 50, 90 = {[float(p) for p in ci]}")
ert_thresholds = [600, 800, 1000, 1200, 1500, 2000, 3000, 5000, 10000]
print("draw(sp) CDF at", ert_thresholds, ":", [repr(float(np.mean(boot <= t))) for t in ert_thresholds])
eps = 1.949 * np.sqrt(2.0 / m)
for p in (10, 50, 90):
    lo, hi = toolsstats.prctile(boot, [p - 100 * eps, p + 100 * eps], issorted=True)
    print(f"draw(sp) percentile {p} +- {100 * eps:.4f}: [{lo!r}, {hi!r}]")

# --- cocopp's percentile (prctile) on hand data, beside numpy's Hazen percentile.
x = [3.0, 1.0, 4.0, 1.0, 5.0, 9.0, 2.0, 6.0]
ps = [0, 5, 10, 25, 50, 75, 90, 95, 100]
print("prctile", ps, ":", [repr(float(v)) for v in toolsstats.prctile(x, ps)])
print("numpy hazen", ps, ":", [repr(float(v)) for v in np.percentile(x, ps, method="hazen")])

# --- The ECDF with simulated restarts as pprldmany builds it (compall/pprldmany.py, main):
# for every (function, target) pair `samplesize` runtimes from drawSP, divided by the dimension,
# or `samplesize` times inf when no run reached the target; one ECDF over all of them.
pairs = [  # (dim, hits, evaluations of the runs that missed)
    (2, [40, 60, 80, 100], [200]),                     # f_a, easy target
    (2, [150], [200, 200, 180, 200]),                  # f_a, hard target
    (5, [500, 700, 900, 1100, 1300, 1500], []),        # f_b, easy target: every run reached it
    (5, [], [2000, 2000, 2000, 2000, 2000, 2000]),     # f_b, hard target: no run reached it
    (10, [3000, 4000], [10000, 10000, 8000]),          # f_c
    (10, [9000], [10000, 10000, 10000, 8000]),         # f_c
]
samplesize = 10000
np.random.seed(3)
values = []
for dim, h, u in pairs:
    if h:
        values.extend(toolsstats.drawSP(np.array(h, float) / dim, np.array(u, float) / dim, [50], samplesize)[1])
    else:
        values.extend(samplesize * [np.inf])
values = np.asarray(values)
log_budgets = [1.0, 1.5, 1.8, 2.0, 2.3, 2.5, 2.8, 3.0, 3.3, 3.6, 4.0]
print(f"pprldmany ECDF, {len(pairs)} pairs x {samplesize} simulated runs, at log10(evals/dim)", log_budgets, ":",
      [repr(float(np.mean(values <= 10.0**b))) for b in log_budgets])
