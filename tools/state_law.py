"""The state law file (doc/state_law.md) read in Python with the C++ reader's rule, for the plots and the tests
that check what the continuum reads: linear in h at the two neighbouring pressures, between them a power law
where both values are positive (linear in ln p otherwise); h held beyond the grid; p clamped to the grid.
Standard library only."""
import bisect
import json
import math


class StateLaw:
    def __init__(self, path):
        with open(path) as f:
            doc = json.load(f)
        self.p = [float(x) for x in doc["pressure"]]
        self.lp = [math.log(x) for x in self.p]
        self.h = [float(x) for x in doc["worn_depth"]]
        self.fields = doc["fields"]

    def grid(self, field, band="mean"):
        """The table [pressure][depth] of a field; a missing band falls back to the mean."""
        node = self.fields[field]
        return node.get(band, node["mean"])

    def grid_index(self, p, rel=1e-6):
        """The index of grid pressure p, or None."""
        i = min(range(len(self.p)), key=lambda k: abs(math.log(self.p[k] / p)))
        return i if abs(self.p[i] / p - 1.0) <= rel else None

    def value(self, field, p, h, band="mean"):
        g = self.grid(field, band)
        lp = min(max(math.log(p), self.lp[0]), self.lp[-1])
        i = min(max(bisect.bisect_right(self.lp, lp), 1), len(self.lp) - 1) - 1
        wp = (lp - self.lp[i]) / (self.lp[i + 1] - self.lp[i])
        h = min(max(h, 0.0), self.h[-1])
        j = min(max(bisect.bisect_right(self.h, h), 1), len(self.h) - 1) - 1
        wh = (h - self.h[j]) / (self.h[j + 1] - self.h[j])
        lo = (1 - wh) * g[i][j] + wh * g[i][j + 1]
        hi = (1 - wh) * g[i + 1][j] + wh * g[i + 1][j + 1]
        if lo > 0.0 and hi > 0.0:
            return lo * (hi / lo) ** wp
        return (1 - wp) * lo + wp * hi
