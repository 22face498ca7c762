#!/usr/bin/env python3
"""bench/micro/compare_builds.py's options: each bad one gives one line `compare_builds: error: --OPTION: ...` on
stderr and exit 2 before any run (no traceback); with --run, one short real A/A run (nside 8, 2 repeats, style d)
then still prints its ratio line.

  /usr/bin/python3 tests/tools/check_compare_builds.py --lmp build/lmp_runin --workdir /tmp/compare_builds [--run]"""
import argparse
import os
import re
import signal
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SCRIPT = os.path.join(SOURCE, "bench", "micro", "compare_builds.py")


def run(command, timeout):
    """The command in a session of its own, all of it stopped at the timeout (its lmp_runin runs too)."""
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          start_new_session=True) as p:
        try:
            out, err = p.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            out, err = p.communicate()
            err += f"\n(stopped after {timeout} s)"
    return subprocess.CompletedProcess(command, p.returncode, out, err)


def bad_options(lmp, workdir):
    """(arguments, the message after `compare_builds: error: `)."""
    a_file = os.path.join(workdir, "a_file")
    open(a_file, "w").close()
    # the scene small and one repeat wherever the option under test allows, so that a script that takes a bad
    # option anyway runs briefly
    both = ["--before", lmp, "--after", lmp]
    small = ["--styles", "d", "--nside", "8", "--repeats", "1"]
    return [
        (both + ["--nside", "8", "--repeats", "0"], r"--repeats: the number of paired runs must be >= 1, got 0"),
        (both + ["--nside", "8", "--repeats", "-3"], r"--repeats: the number of paired runs must be >= 1, got -3"),
        (both + ["--repeats", "x"], r"argument --repeats: invalid int value: 'x' \(see --help\)"),
        (both + ["--repeats", "1", "--nside", "0"], r"--nside: summits per side of the dense scene must be >= 2, got 0"),
        (both + ["--repeats", "1", "--nside", "1"], r"--nside: summits per side of the dense scene must be >= 2, got 1"),
        (both + small + ["--out", a_file], r"--out: .*a_file is an existing file, not a directory"),
        (both + ["--nside", "8", "--repeats", "1", "--styles", "d,z"], r"--styles: unknown style 'z' \(known: "),
        (both + ["--nside", "8", "--repeats", "1", "--styles", "d,d"], r"--styles: style 'd' given twice"),
        (small + ["--before", os.path.join(workdir, "missing"), "--after", lmp],
         r"--before: .*missing is not an executable file \(give the lmp_runin of a build\)"),
        (small + ["--before", workdir, "--after", lmp], r"--before: .* is not an executable file"),
        (small + ["--before", lmp, "--after", "/bin/true"],
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
        r = run([sys.executable, SCRIPT] + argv, 120)
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
    r = run([sys.executable, SCRIPT, "--before", lmp, "--after", lmp, "--same-binary", "--styles", "d",
             "--repeats", "2", "--nside", "8", "--out", out], 300)
    ok = r.returncode == 0 and re.search(r"^  \(d\) .*: median \d\.\d{4} \(range ", r.stdout, re.M)
    print(f"{'ok  ' if ok else 'FAIL'} A/A run, nside 8, 2 repeats: exit {r.returncode}")
    return [] if ok else [f"A/A run: exit {r.returncode}\n{r.stdout}{r.stderr}"]


if __name__ == "__main__":
    main()
