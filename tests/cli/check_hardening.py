#!/usr/bin/env python3
"""Hardening of the runin CLI (the hardening pass's findings), each a case that crashed, hung or gave an unclear error:
hostile case and law files give exit 2 and one line naming the file and key; SIGTERM/SIGINT mid-run and a
dead process's staging directory leave nothing behind.

usage: check_hardening.py RUNIN SOURCE_DIR WORKDIR"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

RUNIN, SOURCE, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
INPUTS = os.path.join(SOURCE, "inputs")
failures = []


def run(*args, timeout=60):
    return subprocess.run([RUNIN, *args], cwd=WORK, capture_output=True, text=True, timeout=timeout)


def expect_refused(label, args, pattern):
    result = run(*args)
    lines = result.stderr.strip().splitlines()
    if result.returncode != 2 or len(lines) != 1 or not re.search(r"^runin: error: .*" + pattern, lines[0]):
        failures.append(f"{label}: exit {result.returncode}, stderr {result.stderr.strip()!r}; want exit 2 and "
                        f"{pattern!r}")
    else:
        print(f"ok: {label}: {lines[0]}")


def write(name, text):
    path = os.path.join(WORK, name)
    with open(path, "w") as out:
        out.write(text)
    return path


def staging_dirs():
    return [n for n in os.listdir(WORK) if ".staging-" in n]


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)

# --- case files ------------------------------------------------------------------------------------------
deep = write("deep.json", '{"model": ' + "[" * 100000 + "]" * 100000 + "}")
expect_refused("JSON nested 100,000 levels", ["feedback", deep, "--output-dir", "o"],
               r"deep.json: key 'model': nested deeper than 32 levels")
lubricated = open(os.path.join(INPUTS, "feedback_lubricated.json")).read()
overflow = write("overflow.json", re.sub(r'"R0": *[-0-9.eE+]+', '"R0": 1e400', lubricated, count=1))
expect_refused("JSON number 1e400", ["feedback", overflow, "--output-dir", "o"],
               r"overflow.json: key 'run.R0': number out of range")
expect_refused("a directory as case file", ["feedback", INPUTS, "--output-dir", "o"], r"is a directory, not a case file")
expect_refused("empty --output-dir", ["feedback", os.path.join(INPUTS, "feedback_dry.toml"), "--output-dir", ""],
               r"--output-dir: must not be empty")
piston = open(os.path.join(INPUTS, "piston_ring.toml")).read()
wrap = write("wrap.toml", re.sub(r"(?m)^ring_cells = .*$", "ring_cells = 4294967298", piston))
expect_refused("integer beyond int (2^32 + 2)", ["piston-ring", wrap, "--output-dir", "o", "--no-plot"],
               r"key 'wear.ring_cells': must be at most 2147483647, got 4294967298")
cells = write("cells.toml", re.sub(r"(?m)^liner_cells = .*$", "liner_cells = 10000000", piston))
expect_refused("liner cells above the cap", ["piston-ring", cells, "--output-dir", "o", "--no-plot"],
               r"key 'wear.liner_cells': must lie in \[2, 100000\]")
frames = "[" + ", ".join("0.0" for _ in range(20000)) + "]"
many = write("frames.toml", re.sub(r"(?m)^vtk_times = .*$", "vtk_times = " + frames, piston))
expect_refused("20,000 VTK frames", ["piston-ring", many, "--output-dir", "o", "--no-plot"],
               r"key 'output.vtk_times': 20000 frames: at most 200 allowed")

soft = write("soft.toml", re.sub(r"(?m)^(ring_cells = .*)$", r"\1\nfoundation_modulus = 1e-300", piston))
expect_refused("a foundation modulus of 1e-300", ["piston-ring", soft, "--output-dir", "o", "--no-plot"],
               r"key 'wear.foundation_modulus': must be at least 1e6 Pa/m, got 1e-300")

# Ring pack: overlapping grooves, non-positive stiffness or dimensions, inconsistent arrays.
def pack_case(name, key, value, text=None):
    text = piston if text is None else text
    if re.search(r"(?m)^" + key + r" = ", text):
        text = re.sub(r"(?m)^" + key + r" = [^#\n]*", f"{key} = {value}", text, count=1)
    else:
        text = text.replace("[ring_pack]", f"[ring_pack]\n{key} = {value}", 1)
    return write(name, text)


for label, name, key, value, pattern in [
        ("overlapping grooves", "overlap.toml", "groove_position", "[0.0, -0.005]",
         r"key 'ring_pack.groove_position': grooves 0 and 1 overlap: centres 0.005 m apart, less than the ring width "
         r"0.01 m"),
        ("a negative land stiffness", "stiffness.toml", "land_stiffness", "[1e7, -1e7]",
         r"key 'ring_pack.land_stiffness': element 1: must be positive, got -1e\+07"),
        ("a zero land width", "land.toml", "land_width", "[0.005, 0.0]",
         r"key 'ring_pack.land_width': element 1: must be positive, got 0$"),
        ("a negative groove diameter", "groove.toml", "groove_diameter", "[0.0815, -0.08]",
         r"key 'ring_pack.groove_diameter': element 1: must be positive, got -0.08"),
        ("a groove wider than the bore", "wide.toml", "groove_diameter", "[0.0815, 0.12]",
         r"key 'ring_pack.groove_diameter': element 1: must be below ring.bore \(0.1\), got 0.12"),
        ("one tension for two rings", "tension.toml", "elastic_pressure", "[0.2e6]",
         r"key 'ring_pack.elastic_pressure': has 1 values, ring_pack.groove_diameter has 2"),
        ("a zero ring tension", "tension0.toml", "elastic_pressure", "[0.2e6, 0.0]",
         r"key 'ring_pack.elastic_pressure': element 1: must be positive, got 0"),
        ("an unknown ring model", "model.toml", "model", '"three"',
         r"key 'ring_pack.model': 'three' is not one of pack, single")]:
    expect_refused(label, ["piston-ring", pack_case(name, key, value), "--output-dir", "o", "--no-plot"], pattern)
both = write("both.toml", piston.replace("[ring]", "[ring]\nland_stiffness = 1e7", 1))
expect_refused("ring.land_stiffness in a ring-pack case", ["piston-ring", both, "--output-dir", "o", "--no-plot"],
               r"key 'ring.land_stiffness': is set per ring in \[ring_pack\] when the case has one")
zero_width = write("width0.toml", re.sub(r"(?m)^width = [^#\n]*", "width = 0.0 ", piston, count=1))
expect_refused("a zero ring width", ["piston-ring", zero_width, "--output-dir", "o", "--no-plot"],
               r"key 'ring.width': must be positive, got 0")
contact = write("contact.toml", re.sub(r'(?m)^contact = [^#\n]*', 'contact = "hertz" ', piston, count=1))
expect_refused("an unknown face contact", ["piston-ring", contact, "--output-dir", "o", "--no-plot"],
               r"key 'wear.contact': 'hertz' is not one of half_plane, winkler")
single = re.sub(r"(?ms)^\[ring_pack\].*?(?=^\[)", "", piston).replace("[ring]", "[ring]\nelastic_pressure = 0.2e6", 1)
single = single.replace("[wear]", "[wear]\ncrown_height = 2e-6", 1)
nogeometry = write("nogeometry.toml", single)
expect_refused("one ring without land geometry or stiffness", ["piston-ring", nogeometry, "--output-dir", "o", "--no-plot"],
               r"key 'ring.groove_diameter': missing: the land stiffness is computed from ring.groove_diameter and "
               r"ring.land_width \(or give ring.land_stiffness\)")
thin = write("thin.toml", single.replace("[ring]", "[ring]\ngroove_diameter = 0.0815\nland_width = -0.005", 1))
expect_refused("one ring with a negative land width", ["piston-ring", thin, "--output-dir", "o", "--no-plot"],
               r"key 'ring.land_width': must be positive, got -0.005")
journal = open(os.path.join(INPUTS, "journal_bearing.toml")).read()
frames_jb = write("frames_jb.toml", re.sub(r"(?m)^frame_times = .*$", "frame_times = " + frames, journal))
expect_refused("20,000 journal-bearing frames", ["journal-bearing", frames_jb, "--output-dir", "o", "--no-plot"],
               r"key 'run.frame_times': 20000 frames: at most 200 allowed")
dump = write("huge.dump", "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1000000000000\nITEM: BOX BOUNDS pp pp pp\n"
             "0 1\n0 1\n0 1\nITEM: ATOMS id type x y z\n1 1 0.1 0.1 0.1\n")
expect_refused("dump with 1e12 atoms", ["dump-to-vtk", dump, "--output-dir", "o"],
               r"huge.dump:4: atom count 1000000000000 above the limit of 100000000")

# --- law files -------------------------------------------------------------------------------------------
case = os.path.join(INPUTS, "pin_on_disk_micro.toml")
law_text = run("fit-law", "--input", os.path.join(SOURCE, "tests/data/fric_ave_time.txt"), "--distance-column",
               "v_slide", "--mu-column", "c_fric[3]", "--output", "law.json")
law = json.load(open(os.path.join(WORK, "law.json")))
for label, document, pattern in [
        ("law file with a null root", None, r"the law must be a JSON object"),
        ("law value of the wrong type", {**law, "units": {**law["units"], "distance_in_m": "1"}},
         r"key 'units.distance_in_m': expected a number, got string"),
        ("law table with a null", {**law, "table": {**law["table"], "mu": law["table"]["mu"][:2] + [None]}},
         r"key 'table.mu': element 2: expected a finite number"),
        ("law version as a string", {**law, "version": "1"}, r"key 'version': expected the integer 1, got \"1\""),
        ("law number beyond a double", "OVERFLOW", r"key 'units.distance_in_m': number out of range")]:
    text = json.dumps(document) if document != "OVERFLOW" else \
        json.dumps({**law, "units": {**law["units"], "distance_in_m": 12345.0}}).replace("12345.0", "1e400")
    path = write("bad_law.json", text)
    expect_refused(label, ["pin-on-disk", case, "--law", path, "--output-dir", "o", "--no-plot"], pattern)

# --- signals and stale staging ---------------------------------------------------------------------------
# 1e5 liner cells: a run of several seconds, long enough to be killed mid-way
long_case = write("long.toml", re.sub(r"(?m)^liner_cells = .*$", "liner_cells = 100000", piston))
for sig in (signal.SIGTERM, signal.SIGINT):
    process = subprocess.Popen([RUNIN, "piston-ring", long_case, "--output-dir", "killed", "--no-plot"], cwd=WORK,
                               stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    deadline = time.time() + 20
    while not staging_dirs() and time.time() < deadline and process.poll() is None:
        time.sleep(0.05)
    time.sleep(0.3)
    if process.poll() is not None:
        failures.append(f"{sig.name}: the run ended before it could be killed (exit {process.returncode})")
        continue
    process.send_signal(sig)
    status = process.wait(timeout=30)
    printed = process.stdout.read()
    if "note: large wear pass" not in printed or "MB of memory and disk" not in printed:
        failures.append(f"{sig.name}: no time and memory estimate before the 1e5-cell run: {printed!r}")
    left = staging_dirs()
    if status != -sig or left or os.path.exists(os.path.join(WORK, "killed")):
        failures.append(f"{sig.name}: exit {status}, staging left {left}, output dir "
                        f"{os.path.exists(os.path.join(WORK, 'killed'))}")
    else:
        print(f"ok: {sig.name} mid-run: killed by the signal, no staging directory or output left")

dead_pid = subprocess.Popen(["true"])
dead_pid.wait()
stale = os.path.join(WORK, f".fb.staging-{dead_pid.pid}-0")
alive = os.path.join(WORK, f".fb.staging-{os.getpid()}-0")
for path in (stale, alive):
    os.makedirs(path)
    write(os.path.relpath(os.path.join(path, "partial.csv"), WORK), "t,R\n0,1\n")
result = run("feedback", os.path.join(INPUTS, "feedback_dry.toml"), "--output-dir", "fb", "--no-plot")
if result.returncode != 0 or os.path.exists(stale) or not os.path.exists(alive):
    failures.append(f"stale staging: exit {result.returncode}, dead process's kept {os.path.exists(stale)}, live "
                    f"process's removed {not os.path.exists(alive)}")
else:
    print("ok: a dead process's staging directory is removed by the next run; a live one's is kept")
shutil.rmtree(alive, ignore_errors=True)

if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ok: all hardening cases")
