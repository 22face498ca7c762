#!/usr/bin/env python3
"""No shipped file holds an absolute path of the machine that made it (a law's provenance, a log, a doc line).

  check_no_machine_paths.py SOURCE_DIR

Every text file under inputs/ potentials/ examples/ tests/data/ must not name /work, /tmp, /root or /home; the
pages under doc/ must not name /work, /root or /home (their commands may use /tmp as a scratch directory, which
exists on every machine). Prints each offending file:line and exits 1. Standard library only.
"""
import os
import re
import sys

ALL = re.compile(r"(?<![\w.~$-])/(work|tmp|root|home)(?=/|\b)")
DOC = re.compile(r"(?<![\w.~$-])/(work|root|home)(?=/|\b)")


def main():
    source = sys.argv[1]
    bad = []
    for top, pattern in (("inputs", ALL), ("potentials", ALL), ("examples", ALL), ("tests/data", ALL),
                         ("doc", DOC)):
        for root, _, files in os.walk(os.path.join(source, top)):
            for name in sorted(files):
                path = os.path.join(root, name)
                try:
                    with open(path, encoding="utf-8") as f:
                        lines = f.read().splitlines()
                except (UnicodeDecodeError, OSError):
                    continue  # binary (PNG, restart file)
                for number, line in enumerate(lines, 1):
                    match = pattern.search(line)
                    if match:
                        bad.append(f"{os.path.relpath(path, source)}:{number}: {match.group(0)} in: {line.strip()[:160]}")
    for line in bad:
        print(line)
    if bad:
        sys.exit(f"check_no_machine_paths: {len(bad)} line(s) name an absolute machine path")
    print("check_no_machine_paths: no absolute machine path in the shipped files")


if __name__ == "__main__":
    main()
