#!/usr/bin/python3
"""Reference values for tests/test_statistics.cpp, computed with scipy (Debian's python3-scipy).

Run: /usr/bin/python3 scripts/statistics_reference.py   (prints the values the test hard-codes)
"""
import scipy
from scipy import stats

x = [0.31, 1.2, 0.05, 2.4, 0.77, 1.9, 0.42, 3.3, 0.9, 1.1]
y = [1.5, 2.2, 0.95, 3.1, 2.8, 1.7, 4.0, 2.5, 1.35, 2.9]
t1 = [12, 12, 13, 12, 14, 12, 13, 12, 12, 15]          # grid results: many ties
t2 = [12, 13, 13, 14, 14, 13, 15, 12, 16, 14, 13, 13]
blocks = [  # rows: problems, columns: algorithms
    [3.2, 1.1, 2.5, 4.0],
    [0.5, 0.7, 0.6, 0.9],
    [10.0, 8.0, 8.0, 12.0],
    [1.0, 2.0, 3.0, 4.0],
    [7.5, 7.5, 7.5, 6.0],
    [0.01, 0.02, 0.005, 0.03],
]
print("scipy", scipy.__version__)
for a, b, name in [(x, y, "x,y"), (t1, t2, "t1,t2"), (y, x, "y,x")]:
    r = stats.mannwhitneyu(a, b, alternative="two-sided", method="asymptotic", use_continuity=True)
    print(f"mannwhitneyu {name}: U={r.statistic!r} p={r.pvalue!r}")
f = stats.friedmanchisquare(*[[row[j] for row in blocks] for j in range(4)])
print(f"friedman: statistic={f.statistic!r} p={f.pvalue!r}")
import numpy as np
ranks = np.array([stats.rankdata(row) for row in blocks]).mean(axis=0)
print("average ranks:", [repr(float(r)) for r in ranks])
