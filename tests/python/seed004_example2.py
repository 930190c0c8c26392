"""Seed 004's Example 2 for the tests of `gesmi estimate` and `gesmi.estimate`: the
scenario file, its model written again in numpy (not the C++ code), and the outlier
sets that a brute-force grid established (docs/setinversion.md, section 5)."""
import os

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLE2 = os.path.join(ROOT, "missions", "setinv", "seed004_example2.yaml")
FRAME = ((-2.0, 8.0), (0.0, 3.0))
LO = np.array([0, 0.3, 0.3, 0.1, 0.4, -1])
HI = np.array([0.2, 2, 2, 0.2, 2, 0.1])

# docs/setinversion.md, section 5 (a 2001 x 2000 grid): the sets of exactly q data,
# numbered from 1, for q = 0..6. q = 0 and q = 6 have none.
SECTION5 = {
    1: {(5,)},
    2: {(2, 3), (2, 5), (3, 5), (4, 5)},
    3: {(1, 3, 5), (2, 3, 4), (2, 3, 5), (2, 3, 6), (2, 4, 5), (3, 4, 5)},
    4: {(1, 2, 3, 5), (1, 3, 4, 5), (2, 3, 4, 5), (2, 3, 4, 6), (2, 3, 5, 6)},
    5: {(1, 2, 3, 4, 5), (2, 3, 4, 5, 6)},
}


def phi_codes(p1, p2):
    """phi at each point as a bit mask (bit i: datum i + 1 misses its bounds)."""
    codes = np.zeros(np.broadcast(p1, p2).shape, dtype=int)
    for i in range(6):
        t = i + 1
        f = np.exp(-(t - p1) ** 2 / (2 * p2)) / np.sqrt(2 * np.pi * p2)
        codes |= ((f < LO[i]) | (f > HI[i])).astype(int) << i
    return codes


def members(code):
    return tuple(i + 1 for i in range(6) if code >> i & 1)


def grid(n1=1001, n2=1000):
    """Points of the frame (p2 > 0, where the density is defined) and their phi codes."""
    p1, p2 = np.meshgrid(np.linspace(-2, 8, n1), np.linspace(3.0 / n2, 3, n2), indexing="ij")
    return p1, p2, phi_codes(p1, p2)


def grid_sets():
    """Outlier sets (from 1) met on a grid of the frame, by size."""
    sets = {}
    for code in np.unique(grid()[2]):
        s = members(code)
        sets.setdefault(len(s), set()).add(s)
    return sets
