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


def sample_rows(path):
    """The sliding rows (s > 0) of a cell's output (columns of the in.rve_wall contract: step s h h_cf mu_body rq
    rsk area_fraction ...), with h made non-decreasing by a running maximum, as `runin homogenise` reads them."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    rows = [r for r in rows if r[1] > 0.0]
    top = 0.0
    for r in rows:
        top = max(top, r[2])
        r[2] = top
    return rows


def sample_at_depth(rows, column, h, step, fit):
    """One sample's value of `column` at worn depth h, reduced as src/coupling/homogenise_curves.cpp does: fit = True
    (mu_body, area_fraction) and h > 0: the least-squares line over the rows with h within step / 2, at h, kept
    within those rows' range; otherwise (or with fewer than 3 rows) linear between the last row below h and the
    first at or above it. NaN if the rows do not reach h."""
    def bracket():
        for a, b in zip(rows, rows[1:]):
            if a[2] <= h <= b[2] and b[2] > a[2]:
                w = (h - a[2]) / (b[2] - a[2])
                return (1 - w) * a[column] + w * b[column]
        return rows[0][column] if rows and h <= rows[0][2] else float("nan")
    if not fit or h <= 0.0:
        return bracket()
    window = [(r[2], r[column]) for r in rows if h - 0.5 * step <= r[2] <= h + 0.5 * step]
    if len(window) < 3:
        return bracket()
    mx = sum(x for x, _ in window) / len(window)
    my = sum(y for _, y in window) / len(window)
    sxx = sum((x - mx) ** 2 for x, _ in window)
    if not sxx > 0.0:
        return bracket()
    value = my + sum((x - mx) * (y - my) for x, y in window) / sxx * (h - mx)
    return min(max(value, min(y for _, y in window)), max(y for _, y in window))
