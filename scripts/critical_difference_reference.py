#!/usr/bin/python3
"""Reference values for tests/test_critical_difference.cpp, computed with scipy (Debian's python3-scipy).

Run: /usr/bin/python3 scripts/critical_difference_reference.py   (prints the values the test hard-codes)

Nemenyi's q_alpha (Demsar 2006, JMLR 7, table 5a) is the upper alpha quantile of the studentized
range of k means with infinite degrees of freedom, divided by sqrt(2).
"""
import numpy as np
import scipy
from scipy.stats import studentized_range

print("scipy", scipy.__version__)
for alpha in (0.01, 0.05, 0.10):
    for k in (2, 3, 4, 5, 6, 7, 8, 9, 10, 15, 20, 50):
        q = studentized_range.ppf(1 - alpha, k, np.inf)
        print(f"alpha={alpha} k={k}: q={q!r} q/sqrt2={q / np.sqrt(2)!r}")
for k, q in ((2, 1.0), (3, 3.0), (5, 2.5), (10, 4.0), (20, 5.5)):
    print(f"cdf(q={q}, k={k}) = {studentized_range.cdf(q, k, np.inf)!r}")
