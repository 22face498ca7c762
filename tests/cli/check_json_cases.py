#!/usr/bin/python3
"""A JSON case file gives the same results as its TOML original (stdlib only; ctest label cli).

usage: check_json_cases.py RUNIN SOURCE_DIR WORKDIR

- inputs/feedback_lubricated.json (shipped) vs inputs/feedback_lubricated.toml;
- inputs/pin_on_disk.toml converted to JSON here with tomllib + json;
each run with --no-plot into its own directory; every CSV must be byte-identical.
"""
import json
import os
import shutil
import subprocess
import sys
import tomllib


def run(runin, command, case, out):
    p = subprocess.run([runin, command, case, "--output-dir", out, "--no-plot"], capture_output=True, text=True,
                       timeout=300)
    if p.returncode != 0:
        sys.exit(f"check_json_cases: {command} {case}: exit {p.returncode}: {p.stderr}")


def csvs(directory):
    return {n: open(os.path.join(directory, n), "rb").read() for n in sorted(os.listdir(directory))
            if n.endswith(".csv")}


def main():
    runin, source, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    inputs = os.path.join(source, "inputs")
    converted = os.path.join(work, "pin_on_disk.json")
    with open(os.path.join(inputs, "pin_on_disk.toml"), "rb") as f, open(converted, "w") as g:
        json.dump(tomllib.load(f), g, indent=2)
    pairs = [("feedback", os.path.join(inputs, "feedback_lubricated.toml"), os.path.join(inputs, "feedback_lubricated.json")),
             ("pin-on-disk", os.path.join(inputs, "pin_on_disk.toml"), converted)]
    failures = []
    for command, toml_case, json_case in pairs:
        a, b = os.path.join(work, command + "_toml"), os.path.join(work, command + "_json")
        run(runin, command, toml_case, a)
        run(runin, command, json_case, b)
        from_toml, from_json = csvs(a), csvs(b)
        if not from_toml or from_toml.keys() != from_json.keys():
            failures.append(f"{command}: CSV files differ: {sorted(from_toml)} vs {sorted(from_json)}")
        for name in from_toml:
            if from_toml[name] != from_json.get(name):
                failures.append(f"{command}: {name} differs between {toml_case} and {json_case}")
        print(f"{command}: {os.path.basename(json_case)} == {os.path.basename(toml_case)}: {sorted(from_toml)}")
    for f in failures:
        print("check_json_cases:", f, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
