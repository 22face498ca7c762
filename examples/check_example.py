#!/usr/bin/env python3
"""Runs a RunIn example and compares its key numbers with the reference output (standard library only).

  check_example.py NAME --np N [--lmp CMD] [--mpiexec MPIEXEC] [--runin RUNIN] [--workdir DIR]
      Runs examples/NAME (its check.json says how) on N MPI ranks in DIR/examples/NAME (a copy of the
      example folder; DIR/potentials points at the source tree's potentials/, so the decks' relative
      paths ../../potentials/... resolve), then compares the key columns of its thermo tables (and key-number
      files) with the reference log of the same rank count, log.<date>.<stem>.g++.<N> (for a rank count
      without a reference of its own, e.g. 2, the 1-rank reference with the same tolerance: results must not
      depend on the rank count), and runs the example's closed-form checks. Relative paths (--lmp build/lmp_runin,
      --runin, --workdir, --outputs) are taken from the caller's directory.
  check_example.py NAME --np N --outputs DIR
      The same checks on outputs that already exist in DIR (log.<stem>, key-number files): nothing is run.
  check_example.py NAME --np N --update-reference [...]
      Runs the example and, if it completes cleanly and passes its closed-form checks, stores its outputs as
      the new reference files log.<today>.<stem>.g++.<N> (replacing the old ones of that N).
  check_example.py --diff FILE_A FILE_B
      Worst difference per column between two logs (or key-number files), e.g. the 1- and 4-rank references,
      in the unit the tolerance uses (below).

--lmp is a command string: 'lmp_runin', or a stock LAMMPS with the plugin auto-loaded, e.g.
  --lmp 'LAMMPS_PLUGIN_PATH=/path/to/build lmp'   (leading NAME=VALUE words, optionally after 'env',
  go into the environment of every rank; the rest is split like a shell would).

Comparison: for each key column, |run - reference| / scale <= rtol at every row of the table, where scale is
the largest |value| of that column in the reference table (so a column that crosses zero, e.g. Rsk, is judged
relative to its size, not to a value near 0). rtol comes from check.json, one number or one per output (the
README of each example gives the measured 1-vs-4-rank difference it sits above). The run fails on: a non-zero exit, an ERROR line, a log
that did not finish ('Total wall time') or did not run on N ranks, a non-finite value anywhere in a thermo
table or key file, a missing or extra table, a missing key column, a different number of rows or different
Step values, a key number outside the tolerance, or a failed closed-form check.
"""
import argparse
import glob
import json
import math
import os
import shlex
import shutil
import subprocess
import sys
import time

EXAMPLES = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.dirname(EXAMPLES)
REFERENCE_PATTERNS = {"log": "log.*.{stem}.g++.{np}", "keys": "key_numbers.*.{stem}.g++.{np}"}
REFERENCE_NAMES = {"log": "log.{date}.{stem}.g++.{np}", "keys": "key_numbers.{date}.{stem}.g++.{np}"}


class CheckFailed(Exception):
    pass


def fail(message):
    raise CheckFailed(message)


# --- reading outputs ------------------------------------------------------------------------------
def thermo_blocks(text, name):
    """Each run's thermo table of a LAMMPS log as {'header': [...], 'rows': [[float...]...]}.

    A table starts at a line whose first word is 'Step' and ends at 'Loop time'; lines inside it with as many
    words as the header that all parse as numbers are rows (WARNING lines in between are skipped). A table
    that never reaches 'Loop time' (a crash) is an error."""
    blocks, header, rows = [], None, []
    for line in text.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            if header is not None:
                fail(f"{name}: a thermo table without 'Loop time' before the next one")
            header, rows = words, []
        elif header is not None and line.startswith("Loop time"):
            blocks.append({"header": header, "rows": rows})
            header = None
        elif header is not None and len(words) == len(header):
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                pass
    if header is not None:
        fail(f"{name}: the last thermo table did not finish (no 'Loop time' line)")
    return blocks


def read_log(path, np=None):
    """Thermo tables of a LAMMPS log, after the log's own sanity checks."""
    name = os.path.basename(path)
    if not os.path.exists(path):
        fail(f"{name}: missing")
    text = open(path, errors="replace").read()
    errors = [line for line in text.splitlines() if line.lstrip().startswith("ERROR")]
    if errors:
        fail(f"{name}: {errors[0].strip()}")
    if "Total wall time" not in text:
        fail(f"{name}: the run did not finish (no 'Total wall time' line)")
    procs = [int(line.split(" on ")[1].split()[0]) for line in text.splitlines() if line.startswith("Loop time of")]
    if np is not None and any(p != np for p in procs):
        fail(f"{name}: runs on {sorted(set(procs))} procs, expected {np}")
    blocks = thermo_blocks(text, name)
    if not blocks:
        fail(f"{name}: no thermo table")
    for k, block in enumerate(blocks):
        if not block["rows"]:
            fail(f"{name}: thermo table {k} has no rows")
        for row in block["rows"]:
            for column, value in zip(block["header"], row):
                if not math.isfinite(value):
                    fail(f"{name}: {column} = {value} at Step {row[0]:.0f} (thermo table {k})")
    return blocks


def read_keys(path):
    """A key-number file ('name value' lines, # comments) as one table with one row."""
    name = os.path.basename(path)
    if not os.path.exists(path):
        fail(f"{name}: missing")
    header, row = [], []
    for number, line in enumerate(open(path), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        words = line.split()
        if len(words) != 2:
            fail(f"{name} line {number}: expected 'name value', got {line!r}")
        try:
            value = float(words[1])
        except ValueError:
            fail(f"{name} line {number}: {words[1]!r} is not a number")
        if not math.isfinite(value):
            fail(f"{name}: {words[0]} = {value}")
        if words[0] in header:
            fail(f"{name}: {words[0]} appears twice")
        header.append(words[0])
        row.append(value)
    if not header:
        fail(f"{name}: no key numbers")
    return [{"header": header, "rows": [row]}]


def read_output(path, kind, np=None):
    return read_log(path, np) if kind == "log" else read_keys(path)


def kind_of(path):
    return "keys" if os.path.basename(path).startswith("key_numbers") else "log"


# --- comparing ---------------------------------------------------------------------------------------
def column(block, name, label):
    if name not in block["header"]:
        fail(f"{label}: no column {name!r} (columns: {' '.join(block['header'])})")
    k = block["header"].index(name)
    return [row[k] for row in block["rows"]]


def worst_difference(run, reference):
    """max over rows of |run - reference| / max |reference| of the column (0 if both are all zero)."""
    scale = max(abs(v) for v in reference)
    if scale == 0.0:
        return 0.0 if all(v == 0.0 for v in run) else math.inf
    return max(abs(a - b) for a, b in zip(run, reference)) / scale


def compare_tables(run_blocks, ref_blocks, wanted, rtol, label):
    """wanted: {block index (str): [columns] or "all"}. Returns [(label, column, worst)]."""
    if len(run_blocks) != len(ref_blocks):
        fail(f"{label}: {len(run_blocks)} thermo tables, reference has {len(ref_blocks)}")
    results = []
    for index, columns in wanted.items():
        k = int(index)
        run, ref = run_blocks[k], ref_blocks[k]
        where = f"{label} table {k}"
        if len(run["rows"]) != len(ref["rows"]):
            fail(f"{where}: {len(run['rows'])} rows, reference has {len(ref['rows'])}")
        if "Step" in ref["header"] and column(run, "Step", where) != column(ref, "Step", where):
            fail(f"{where}: Step values differ from the reference")
        for name in (ref["header"] if columns == "all" else columns):
            worst = worst_difference(column(run, name, where), column(ref, name, f"{where} (reference)"))
            results.append((where, name, worst))
            if not worst <= rtol:
                rows = [(r[0], a, b) for r, a, b in zip(ref["rows"], column(run, name, where), column(ref, name, where))]
                step, a, b = max(rows, key=lambda t: abs(t[1] - t[2]))
                fail(f"{where}: {name} = {a!r} at Step {step:.0f}, reference {b!r}: difference {worst:.3e} of the "
                     f"column's largest |value| > rtol {rtol:.1e}")
    return results


def value_at(tables, reference):
    """'stem:table:row:column' -> number."""
    stem, table, row, name = reference.split(":", 3)
    if stem not in tables:
        fail(f"check refers to unknown output {stem!r}")
    blocks = tables[stem]
    try:
        block = blocks[int(table)]
        values = column(block, name, f"{stem} table {table}")
        return values[int(row)]
    except IndexError:
        fail(f"check refers to {reference}: no such table or row ({len(blocks)} tables)")


def closed_form_checks(tables, checks):
    """The example's physics checks (check.json 'checks'), each printed with its value."""
    for check in checks:
        what = check["what"]
        if "same_table" in check:
            (stem_a, k_a), (stem_b, k_b) = (ref.split(":") for ref in check["same_table"])
            a, b = tables[stem_a][int(k_a)], tables[stem_b][int(k_b)]
            if a["header"] != b["header"] or len(a["rows"]) != len(b["rows"]):
                fail(f"{what}: tables differ in columns or rows ({len(a['rows'])} vs {len(b['rows'])})")
            worst = 0.0
            for name in a["header"]:
                worst = max(worst, worst_difference(column(b, name, what), column(a, name, what)))
            if not worst <= check["rtol"]:
                fail(f"{what}: worst difference {worst:.3e} > {check['rtol']:.1e}")
            print(f"  ok  {what}: {len(a['rows'])} rows x {len(a['header'])} columns, worst difference {worst:.3e} "
                  f"(limit {check['rtol']:.0e})")
            continue
        value = value_at(tables, check["value"])
        if "equals" in check:
            target = check["equals"]
            target = value_at(tables, target) if isinstance(target, str) else float(target)
            error = abs(value - target) / abs(target)
            ok = error <= check["rtol"]
            text = f"{value:.6g} vs {target:.6g}: {error:.2e} relative (limit {check['rtol']:.0e})"
        else:
            low, high = check.get("min", -math.inf), check.get("max", math.inf)
            ok = low <= value <= high
            text = f"{value:.6g} in [{low:g}, {high:g}]"
        if not ok:
            fail(f"{what}: {text}")
        print(f"  ok  {what}: {text}")


# --- running -----------------------------------------------------------------------------------------
def split_command(command):
    """'[env] [NAME=VALUE...] program args' -> (environment additions, argv)."""
    words = shlex.split(command)
    env = {}
    if words and words[0] == "env":
        words = words[1:]
    while words and "=" in words[0] and words[0].split("=", 1)[0].isidentifier():
        name, value = words.pop(0).split("=", 1)
        env[name] = value
    if not words:
        fail(f"no program in command {command!r}")
    return env, words


def resolve_program(words):
    """A program given by a relative path (build/lmp_runin) is the caller's: the run happens in another
    directory, so make it absolute against the caller's cwd. A bare name (lmp, mpiexec) stays a PATH lookup."""
    if words and os.sep in words[0] and not os.path.isabs(words[0]):
        words = [os.path.abspath(words[0])] + words[1:]
    return words


def mpi_env(extra):
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    env.update(extra)
    return env


def outputs_of(spec):
    """{stem: (kind, file name in the run directory)} of every step."""
    outputs = {}
    for step in spec["steps"]:
        if "lammps" in step:
            stem = step.get("stem", step["lammps"][3:] if step["lammps"].startswith("in.") else step["lammps"])
            outputs[stem] = ("log", f"log.{stem}")
        for stem in step.get("logs", []):
            outputs[stem] = ("log", f"log.{stem}")
        for stem, file_name in step.get("keys", {}).items():
            outputs[stem] = ("keys", file_name)
    return outputs


def mirror(name, spec, workdir):
    """DIR/examples/NAME with the example's inputs (no references) and DIR/potentials -> source potentials/."""
    example = os.path.join(EXAMPLES, name)
    run_dir = os.path.join(workdir, "examples", name)
    shutil.rmtree(run_dir, ignore_errors=True)
    os.makedirs(run_dir)
    for entry in os.listdir(example):
        path = os.path.join(example, entry)
        if os.path.isfile(path) and not entry.startswith(("log.", "key_numbers.")) and entry != "README.md":
            shutil.copy2(path, run_dir)
    for relative in spec.get("copy", []):
        target = os.path.normpath(os.path.join(run_dir, relative))
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy2(os.path.normpath(os.path.join(example, relative)), target)
    potentials = os.path.join(workdir, "potentials")
    if os.path.islink(potentials) or os.path.isfile(potentials):
        os.remove(potentials)
    if not os.path.exists(potentials):
        os.symlink(os.path.join(SOURCE_DIR, "potentials"), potentials)
    return run_dir


def run_steps(spec, args, run_dir):
    lmp_env, lmp = split_command(args.lmp)
    lmp = resolve_program(lmp)
    env = mpi_env(lmp_env)
    launcher = resolve_program([args.mpiexec]) + ["-np", str(args.np)] if args.np > 1 else []
    for step in spec["steps"]:
        started = time.monotonic()
        if "lammps" in step:
            stem = step.get("stem", step["lammps"][3:])
            command = launcher + lmp + ["-in", step["lammps"], "-log", f"log.{stem}", "-screen", "none"]
            for variable, value in step.get("vars", {}).items():
                command += ["-var", variable, str(value)]
        else:
            if not args.runin and step.get("needs_runin"):
                fail("this example needs the runin CLI: pass --runin")
            runin = resolve_program([args.runin])[0] if args.runin else "runin"
            env = dict(env, LMP=shlex.join(lmp), MPIEXEC=resolve_program([args.mpiexec])[0], NP=str(args.np), RUNIN=runin,
                       PYTHON=sys.executable)
            command = ["bash", step["script"]]
        try:
            result = subprocess.run(command, cwd=run_dir, env=env, capture_output=True, text=True,
                                    timeout=spec.get("timeout", 600))
        except subprocess.TimeoutExpired:
            fail(f"{' '.join(command)} did not finish within {spec.get('timeout', 600)} s")
        except OSError as error:
            fail(f"cannot run {command[0]}: {error}")
        print(f"  ran {' '.join(command)}  ({time.monotonic() - started:.1f} s, exit {result.returncode})")
        if result.returncode != 0:
            tail = "\n".join((result.stdout + result.stderr).splitlines()[-20:])
            logs = [f for f in os.listdir(run_dir) if f.startswith("log.")]
            for log in logs:
                errors = [line for line in open(os.path.join(run_dir, log), errors="replace") if "ERROR" in line]
                tail += "".join(f"\n{log}: {line.rstrip()}" for line in errors[:3])
            fail(f"{command[0]} exited with {result.returncode}:\n{tail}")


def reference_file(name, stem, kind, np):
    pattern = REFERENCE_PATTERNS[kind].format(stem=stem, np=np)
    found = sorted(glob.glob(os.path.join(EXAMPLES, name, pattern)))
    if len(found) != 1:
        fail(f"examples/{name}: want exactly one reference {pattern}, found {[os.path.basename(f) for f in found]}")
    return found[0]


def check(args):
    spec_path = os.path.join(EXAMPLES, args.name, "check.json")
    if not os.path.exists(spec_path):
        fail(f"no example {args.name!r} (no {spec_path})")
    spec = json.load(open(spec_path))
    if args.np < 1:
        fail(f"--np {args.np}: the number of MPI ranks must be >= 1")
    ranks = spec.get("ranks", [1, 4])
    # Results on any rank count must agree: one without a reference log of its own is compared with the
    # 1-rank reference, to the same rtol (which sits above the measured 1-vs-4-rank difference).
    reference_np = args.np if args.np in ranks else 1
    if args.update_reference and reference_np != args.np:
        fail(f"--update-reference: references are stored for {ranks} ranks only, not {args.np}")
    outputs = outputs_of(spec)
    if args.outputs:
        run_dir = os.path.abspath(args.outputs)
    else:
        workdir = os.path.abspath(args.workdir or os.path.join(os.getcwd(), f"example_{args.name}_np{args.np}"))
        run_dir = mirror(args.name, spec, workdir)
        print(f"examples/{args.name} on {args.np} rank(s) in {run_dir}")
        run_steps(spec, args, run_dir)
    tables = {stem: read_output(os.path.join(run_dir, file_name), kind, args.np if kind == "log" else None)
              for stem, (kind, file_name) in outputs.items()}
    closed_form_checks(tables, spec.get("checks", []))
    if args.update_reference:
        date = time.strftime("%d%b%Y")
        for stem, (kind, file_name) in outputs.items():
            pattern = REFERENCE_PATTERNS[kind].format(stem=stem, np=args.np)
            for old in glob.glob(os.path.join(EXAMPLES, args.name, pattern)):
                os.remove(old)
            target = os.path.join(EXAMPLES, args.name, REFERENCE_NAMES[kind].format(date=date, stem=stem, np=args.np))
            shutil.copyfile(os.path.join(run_dir, file_name), target)
            print(f"  reference written: {os.path.relpath(target, SOURCE_DIR)}")
        return
    for stem, wanted in spec["compare"].items():
        rtol = float(spec["rtol"][stem] if isinstance(spec["rtol"], dict) else spec["rtol"])
        kind, _ = outputs[stem]
        ref_path = reference_file(args.name, stem, kind, reference_np)
        reference = read_output(ref_path, kind, reference_np if kind == "log" else None)
        results = compare_tables(tables[stem], reference, wanted, rtol, stem)
        worst = max(results, key=lambda r: r[2])
        print(f"  ok  {stem}: {len(results)} key columns agree with {os.path.basename(ref_path)}; worst "
              f"{worst[2]:.2e} ({worst[1]}, {worst[0]}; rtol {rtol:.0e})")
        last = tables[stem][-1]
        keys = wanted.get(str(len(tables[stem]) - 1), wanted.get("-1", []))
        if keys and keys != "all":
            print("      last row: " + ", ".join(f"{k} {last['rows'][-1][last['header'].index(k)]:.8g}" for k in keys))
    print(f"PASS examples/{args.name} np{args.np}")


def diff(args):
    """Worst difference per column of two outputs (same tables, same rows)."""
    a = read_output(args.diff[0], kind_of(args.diff[0]))
    b = read_output(args.diff[1], kind_of(args.diff[1]))
    if len(a) != len(b):
        fail(f"{len(a)} vs {len(b)} tables")
    overall = 0.0
    for k, (ta, tb) in enumerate(zip(a, b)):
        if len(ta["rows"]) != len(tb["rows"]):
            fail(f"table {k}: {len(ta['rows'])} vs {len(tb['rows'])} rows")
        print(f"table {k} ({len(ta['rows'])} rows):")
        for name in ta["header"]:
            if name in tb["header"]:
                worst = worst_difference(column(tb, name, "b"), column(ta, name, "a"))
                overall = max(overall, worst)
                print(f"  {name:16s} {worst:.3e}")
    print(f"worst over all columns: {overall:.3e}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("name", nargs="?", help="example folder name (examples/NAME)")
    parser.add_argument("--np", type=int, default=1, help="MPI ranks (1 runs without mpiexec)")
    parser.add_argument("--lmp", default=os.path.join(SOURCE_DIR, "build", "lmp_runin"),
                        help="LAMMPS command string, may start with NAME=VALUE environment settings")
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--runin", help="the runin CLI (multiscale_pipeline)")
    parser.add_argument("--workdir", help="directory to run in (default ./example_NAME_npN)")
    parser.add_argument("--outputs", help="check the outputs already in this directory; run nothing")
    parser.add_argument("--update-reference", action="store_true", help="store this run as the reference")
    parser.add_argument("--diff", nargs=2, metavar=("FILE_A", "FILE_B"))
    args = parser.parse_args()
    try:
        if args.diff:
            diff(args)
        elif args.name:
            check(args)
        else:
            parser.error("give an example NAME or --diff FILE_A FILE_B")
    except CheckFailed as error:
        print(f"FAIL examples/{args.name or ''}: {error}")
        sys.exit(1)


if __name__ == "__main__":
    main()
