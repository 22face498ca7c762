#!/usr/bin/python3
"""Where the files a case names are read from (stdlib only; ctest label cli).

usage: check_case_paths.py RUNIN SOURCE_DIR WORKDIR

A relative path in a case file: beside the case file, else in the current directory, else in the RunIn source
tree; the last two print "runin: note: ... read PATH (current directory | RunIn source tree)" on stdout.
1. A copy of tests/data/state_law/pod_flat.toml in WORKDIR/cases/ (its law "synthetic_law.json" not beside it),
   run from WORKDIR/here, which holds the law: read from the current directory, with the note.
2. A copy of inputs/pin_on_disk.toml in WORKDIR/cases/ (materials "potentials/CuAl.runin"), run from WORKDIR:
   the source tree's file, with the note naming it (it was read silently before).
3. The law beside the case file wins over the current directory's, without a note.
4. Found nowhere: exit 2, one line naming the key and the three paths tried.
"""
import os
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402


def run(runin, case, out, cwd, expect):
    p = subprocess.run([runin, "pin-on-disk", case, "--output-dir", out, "--no-plot"], capture_output=True,
                       text=True, cwd=cwd, timeout=120)
    if p.returncode != expect:
        fail(f"{case} from {cwd}: exit {p.returncode}, expected {expect}: {p.stderr}")
    return p


def main():
    runin, source, work = os.path.abspath(sys.argv[1]), sys.argv[2], os.path.abspath(sys.argv[3])
    shutil.rmtree(work, ignore_errors=True)
    cases, here = os.path.join(work, "cases"), os.path.join(work, "here")
    os.makedirs(cases)
    os.makedirs(here)
    law = os.path.join(source, "tests", "data", "state_law", "synthetic_law.json")
    flat = os.path.join(cases, "pod_flat.toml")
    shutil.copy(os.path.join(source, "tests", "data", "state_law", "pod_flat.toml"), flat)
    shutil.copy(law, os.path.join(here, "synthetic_law.json"))

    # 1. the current directory
    p = run(runin, flat, os.path.join(work, "out1"), here, 0)
    want = f"key 'friction.law': 'synthetic_law.json' is not beside the case file; read " \
           f"{os.path.join(here, 'synthetic_law.json')} (current directory)"
    if want not in p.stdout:
        fail(f"1: no note naming the current directory's law:\n{p.stdout}")

    # 2. the source tree, not silently
    pod = os.path.join(cases, "pin_on_disk.toml")
    shutil.copy(os.path.join(source, "inputs", "pin_on_disk.toml"), pod)
    p = run(runin, pod, os.path.join(work, "out2"), work, 0)
    tree = os.path.normpath(os.path.join(source, "potentials", "CuAl.runin"))
    if f"key 'contact.materials': 'potentials/CuAl.runin' is not beside the case file; read {tree} " \
       "(RunIn source tree)" not in p.stdout:
        fail(f"2: the source tree's CuAl.runin was read without a note naming it:\n{p.stdout}")

    # 3. beside the case file: no note
    shutil.copy(law, os.path.join(cases, "synthetic_law.json"))
    p = run(runin, flat, os.path.join(work, "out3"), here, 0)
    if "runin: note:" in p.stdout:
        fail(f"3: a note although the law is beside the case file:\n{p.stdout}")
    os.remove(os.path.join(cases, "synthetic_law.json"))

    # 4. nowhere
    p = run(runin, flat, os.path.join(work, "out4"), work, 2)
    lines = p.stderr.strip().splitlines()
    tried = [os.path.join(cases, "synthetic_law.json"), os.path.join(work, "synthetic_law.json"),
             os.path.normpath(os.path.join(source, "synthetic_law.json"))]
    if len(lines) != 1 or "key 'friction.law': no such file 'synthetic_law.json' (tried " + ", ".join(tried) + ")" \
            not in lines[0]:
        fail(f"4: not one line naming the key and the paths tried: {p.stderr}")
    print("case paths: current directory and source tree named in a note; beside the case file silent; "
          "missing: " + lines[0])


if __name__ == "__main__":
    main()
