#!/usr/bin/env python3
"""bench/micro/compare_builds.py's options: each bad one gives one line `compare_builds: error: --OPTION: ...` on
stderr and exit 2 before any run (no traceback); with --run, one short real A/A run (nside 8, 2 repeats, style d)
then still prints its ratio line.

  /usr/bin/python3 tests/tools/check_compare_builds.py --lmp build/lmp_runin --workdir /tmp/compare_builds [--run]"""
import argparse
import os
import re
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SCRIPT = os.path.join(SOURCE, "bench", "micro", "compare_builds.py")


def bad_options(lmp, workdir):
    """(arguments, the message after `compare_builds: error: `)."""
    a_file = os.path.join(workdir, "a_file")
    open(a_file, "w").close()
    both = ["--before", lmp, "--after", lmp]
    return [
        (both + ["--repeats", "0"], r"--repeats: the number of paired runs must be >= 1, got 0"),
        (both + ["--repeats", "-3"], r"--repeats: the number of paired runs must be >= 1, got -3"),
        (both + ["--repeats", "x"], r"argument --repeats: invalid int value: 'x' \(see --help\)"),
        (both + ["--nside", "0"], r"--nside: summits per side of the dense scene must be >= 2, got 0"),
        (both + ["--nside", "1"], r"--nside: summits per side of the dense scene must be >= 2, got 1"),
        (both + ["--out", a_file], r"--out: .*a_file is an existing file, not a directory"),
        (both + ["--styles", "d,z"], r"--styles: unknown style 'z' \(known: "),
        (both + ["--styles", "d,d"], r"--styles: style 'd' given twice"),
        (["--before", os.path.join(workdir, "missing"), "--after", lmp],
         r"--before: .*missing is not an executable file \(give the lmp_runin of a build\)"),
        (["--before", workdir, "--after", lmp], r"--before: .* is not an executable file"),
        (["--before", lmp, "--after", "/bin/true"],
         r"--after: /bin/true is not an lmp_runin \(its -h lists no pair style runin/asperity\)"),
        (["--after", lmp], r"the following arguments are required: --before \(see --help\)"),
    ]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--run", action="store_true", help="also the short A/A run (some seconds)")
    args = ap.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    lmp = os.path.abspath(args.lmp)
    failures = []
    for argv, message in bad_options(lmp, args.workdir):
        r = subprocess.run([sys.executable, SCRIPT] + argv, capture_output=True, text=True, timeout=120)
        lines = r.stderr.splitlines()
        ok = (r.returncode == 2 and len(lines) == 1 and not r.stdout
              and re.match(r"compare_builds: error: " + message, lines[0]))
        print(f"{'ok  ' if ok else 'FAIL'} {' '.join(argv[-2:])}: exit {r.returncode}, {lines[-1] if lines else ''}")
        if not ok:
            failures.append(f"{argv}: exit {r.returncode}, stdout {r.stdout!r}, stderr {r.stderr!r}")
    if args.run:
        failures += aa_run(lmp, os.path.join(args.workdir, "aa"))
    if failures:
        sys.exit("FAIL:\n" + "\n".join(failures))
    print("PASS")


def aa_run(lmp, out):
    r = subprocess.run([sys.executable, SCRIPT, "--before", lmp, "--after", lmp, "--same-binary", "--styles", "d",
                        "--repeats", "2", "--nside", "8", "--out", out], capture_output=True, text=True, timeout=300)
    ok = r.returncode == 0 and re.search(r"^  \(d\) .*: median \d\.\d{4} \(range ", r.stdout, re.M)
    print(f"{'ok  ' if ok else 'FAIL'} A/A run, nside 8, 2 repeats: exit {r.returncode}")
    return [] if ok else [f"A/A run: exit {r.returncode}\n{r.stdout}{r.stderr}"]


if __name__ == "__main__":
    main()
