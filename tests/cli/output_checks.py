"""Checks shared by the tests/cli/check_*_csv.py scripts (stdlib only)."""
import csv
import math
import os
import sys

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def read_csv(path, header=None):
    """Rows of a numeric CSV as lists of floats (an empty cell, "not reached" in a sweep summary, reads as
    nan); exits if `header` is given and the file's differs."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        got = next(reader)
        if header is not None and got != header:
            sys.exit(f"{path}: header {got} != {header}")
        return [[float(x) if x != "" else math.nan for x in row] for row in reader]


def time_series_problems(rows, t_end, min_rows=100):
    """A run's time series (time in the first column): enough rows, 0..t_end, never backwards, finite."""
    problems = []
    t = [r[0] for r in rows]
    if len(rows) < min_rows:
        problems.append(f"only {len(rows)} rows")
    if t[0] != 0.0 or not close(t[-1], t_end, 1e-12):
        problems.append(f"time runs {t[0]}..{t[-1]}, expected 0..{t_end}")
    if any(b < a for a, b in zip(t, t[1:])):
        problems.append("time decreases")
    if not all(math.isfinite(x) for r in rows for x in r):
        problems.append("non-finite values")
    return problems


def png_problems(directory, names):
    """A problem per named file that is missing or not a PNG."""
    problems = []
    for name in names:
        path = os.path.join(directory, name)
        if not os.path.exists(path):
            problems.append(f"{name} missing")
            continue
        with open(path, "rb") as f:
            if f.read(8) != PNG_SIGNATURE:
                problems.append(f"{name} is not a PNG")
    return problems


def leftover_problems(directory):
    """Hidden staging or temporary files mean a run did not commit its output cleanly."""
    leftovers = [n for n in os.listdir(directory) if n.startswith(".")]
    return [f"temporary files left: {leftovers}"] if leftovers else []


def finish(tool, problems, summary):
    """Print the problems (one line each) and the summary; exit 1 if there were problems."""
    for p in problems:
        print(f"{tool}:", p, file=sys.stderr)
    print(summary)
    sys.exit(1 if problems else 0)
