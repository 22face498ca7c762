"""Checks shared by the tests/cli/check_*_csv.py scripts (stdlib only)."""
import os
import sys

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


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
