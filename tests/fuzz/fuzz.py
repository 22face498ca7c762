#!/usr/bin/env python3
"""RunIn's own fuzz harness: seeded mutations of every shipped deck, case file and law file, and of the CLI's
options, each run with a time limit and classified as

  OK           exit 0 and nothing non-finite printed or written
  CLEAN_ERROR  a one-line error naming what is wrong: LAMMPS's ERROR line, or the CLI's 'runin: error: ...'
               (exit 2 for bad input, 1 for a failed run) / CLI11's usage error (exit 2)
  CRASH        killed by a signal, abort, 'terminate called', segfault, uncaught exception text
  HANG         the time limit was reached
  SILENT_NAN   nan or inf in thermo output or in a written file (before any error)
  UNCLEAR      an error, but a raw library message ([json.exception, basic_filebuf, filesystem error,
               bad_alloc, stoi ...) or none naming the input

Any class but OK and CLEAN_ERROR fails the run (exit 1). doc/fuzz.md has the operators and how to repeat a case.

  fuzz.py --lmp BUILD/lmp_runin --runin BUILD/runin [--set quick|full] [--seed N] [--only decks,cases,laws,cli]
          [--jobs 2] [--report report.csv] [--case ID] [--keep DIR]
"""
import argparse
import concurrent.futures
import csv
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
INPUTS = os.path.join(SOURCE, "inputs")

# What each shipped deck needs to run in about a second (its own variables) and the variables worth fuzzing.
DECKS = {
    "in.runin_wall": {
        "short": {"nload": "200", "nslide": "200", "thermo_every": "50"},
        "fuzz": ["R", "sigma", "nside", "spacing", "load", "speed", "nload", "nslide", "k", "tau_s", "plough",
                 "restick", "seed", "thermo_every"],
        "scaled": ["load", "speed"],
    },
    "in.rough_slider": {
        "short": {"nsettle": "200", "nslide": "400", "thermo_every": "100",
                  "coeffs": os.path.join(SOURCE, "potentials", "CuAl.runin")},
        "fuzz": ["R", "spacing", "sigma", "nside", "nsettle", "nslide", "speed", "load", "vsettle", "seed",
                 "thermo_every"],
        "scaled": ["load", "speed"],
    },
}
SUBCOMMAND = {"pin": "pin-on-disk", "journal": "journal-bearing", "piston": "piston-ring", "feedback": "feedback"}
# Lines of a deck that belong to RunIn's styles: token mutations there exercise our parsers (elsewhere they
# would mostly test LAMMPS's own input language, e.g. turn a label loop into an endless one).
RUNIN_LINE = re.compile(r"^\s*(pair_style|pair_coeff|fix\s+\S+\s+\S+\s+runin|compute\s+\S+\s+\S+\s+runin|timestep)")
NUMBER = re.compile(r"(?<![\w.$])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
NON_FINITE = re.compile(r"(?<![\w.])[-+]?(?:nan|inf|infinity)(?![\w.])", re.IGNORECASE)
CRASH_TEXT = re.compile(r"terminate called|Segmentation fault|Aborted|core dumped|mpirun noticed|signal \d+|"
                        r"what\(\):|double free|stack smashing")
RAW_TEXT = re.compile(r"\[json\.exception|basic_filebuf|filesystem error|bad_alloc|\bstoi\b|\bstod\b|"
                      r"std::|vector::_M|out_of_range|invalid_argument")
EXTREME = ["0", "-1", "1e308", "1e999", "-1e999", "nan", "inf", "-inf", "4294967298", "1e19", "1e-308"]


class Case:
    def __init__(self, case_id, kind, source, mutation, files, command):
        self.id, self.kind, self.source, self.mutation = case_id, kind, source, mutation
        self.files = files        # {name: text} written into the case's directory
        self.command = command    # argv; '{dir}' is the case's directory


# --- mutation operators --------------------------------------------------------------------------------------
def numbers_in(text, lines=None):
    spans = []
    for n, line in enumerate(text.splitlines(keepends=True)):
        if lines is not None and n not in lines:
            continue
        start = sum(len(l) for l in text.splitlines(keepends=True)[:n])
        spans += [(start + m.start(), start + m.end()) for m in NUMBER.finditer(line) if not line.lstrip().startswith("#")]
    return spans


def replace_number(rng, text, lines=None, values=EXTREME, wrong_types=()):
    spans = numbers_in(text, lines)
    if not spans:
        return text, "no number to replace"
    start, end = rng.choice(spans)
    old = text[start:end]
    choices = list(values) + [f"{float(old) * s:g}" for s in (10, 1000, -1)] + list(wrong_types)
    new = rng.choice(choices)
    return text[:start] + new + text[end:], f"number {old!r} at byte {start} -> {new!r}"


def delete_token(rng, text, lines=None):
    all_lines = text.splitlines(keepends=True)
    candidates = [n for n, l in enumerate(all_lines) if l.split() and (lines is None or n in lines)]
    if not candidates:
        return text, "nothing to delete"
    n = rng.choice(candidates)
    words = all_lines[n].split()
    k = rng.randrange(len(words))
    removed = words.pop(k)
    all_lines[n] = " ".join(words) + "\n"
    return "".join(all_lines), f"line {n + 1}: token {removed!r} deleted"


def swap_tokens(rng, text, lines=None):
    all_lines = text.splitlines(keepends=True)
    candidates = [n for n, l in enumerate(all_lines) if len(l.split()) > 2 and (lines is None or n in lines)]
    if not candidates:
        return text, "nothing to swap"
    n = rng.choice(candidates)
    words = all_lines[n].split()
    a, b = rng.sample(range(len(words)), 2)
    words[a], words[b] = words[b], words[a]
    all_lines[n] = " ".join(words) + "\n"
    return "".join(all_lines), f"line {n + 1}: tokens {a + 1} and {b + 1} swapped"


def truncate(rng, text):
    cut = rng.randrange(len(text))
    return text[:cut], f"truncated at byte {cut} of {len(text)}"


def garbage(rng, text):
    at = rng.randrange(len(text))
    junk = "".join(chr(rng.choice([0x00, 0x07, 0x1b, 0x7f, 0xff, 0x3000, 0xfffd, 0x22, 0x5b, 0x7b]))
                   for _ in range(rng.randint(1, 12)))
    return text[:at] + junk + text[at:], f"{len(junk)} garbage characters at byte {at}"


def deep_nesting(rng, text, json_file):
    spans = numbers_in(text)
    if not spans:
        return text, "no value to nest"
    start, end = rng.choice(spans)
    depth = rng.choice([100, 10000, 100000])
    if json_file:
        nested = "[" * depth + text[start:end] + "]" * depth
    else:
        nested = "[" * depth + text[start:end] + "]" * depth
    return text[:start] + nested + text[end:], f"value at byte {start} nested {depth} levels"


# --- case generators -------------------------------------------------------------------------------------------
def deck_cases(rng, count, lmp):
    cases = []
    for k in range(count):
        name = rng.choice(sorted(DECKS))
        spec = DECKS[name]
        text = open(os.path.join(INPUTS, name)).read()
        variables = dict(spec["short"])
        ours = {n for n, line in enumerate(text.splitlines()) if RUNIN_LINE.match(line)}
        op = rng.choice(["var", "var", "var", "scale", "number", "delete", "swap", "timestep"])
        if op == "var":
            var = rng.choice(spec["fuzz"])
            value = rng.choice(EXTREME + ["abc", "1e-30", "2.5"])
            variables[var] = value
            mutation = f"-var {var} {value}"
        elif op == "scale":
            var = rng.choice(spec["scaled"])
            factor = rng.choice([10, 100, 1000])
            base = float(re.search(rf"variable\s+{var}\s+index\s+(\S+)", text).group(1))
            variables[var] = f"{base * factor:g}"
            mutation = f"-var {var} {base * factor:g} ({factor} x)"
        elif op == "timestep":
            factor = rng.choice([10, 100, 1000])
            text = re.sub(r"(?m)^(timestep\s+)(\S+)", lambda m: m.group(1) + f"{float(m.group(2)) * factor:g}", text)
            mutation = f"timestep x {factor}"
        elif op == "number":
            text, mutation = replace_number(rng, text, ours, wrong_types=("abc", "v_undefined"))
        elif op == "delete":
            text, mutation = delete_token(rng, text, ours)
        else:
            text, mutation = swap_tokens(rng, text, ours)
        command = [lmp, "-in", "{dir}/" + name, "-log", "none", "-echo", "none"]
        for var, value in variables.items():
            command += ["-var", var, value]
        cases.append(Case(f"deck-{k}", "lammps", name, mutation, {name: text}, command))
    return cases


def shipped_cases():
    """The machine-element case files (the homogenise case runs the LAMMPS cell: its own op in cli_cases; a
    state_law_*.json is a law the cases read, not a case)."""
    return sorted(n for n in os.listdir(INPUTS) if n.endswith((".toml", ".json"))
                  and not n.startswith(("homogenise_", "state_law_")))


def needs_law(text):
    return re.search(r'model\s*=\s*"law_file"|"model"\s*:\s*"law_file"', text) is not None


def case_command(runin, name, text, law_path="{dir}/law.json"):
    command = [runin, SUBCOMMAND[name.split("_")[0]], "{dir}/" + name, "--output-dir", "{dir}/out", "--no-plot"]
    if needs_law(text):
        command += ["--law", law_path]
    return command


def case_file_cases(rng, count, runin, law_text):
    cases = []
    names = shipped_cases()
    for k in range(count):
        name = rng.choice(names)
        text = open(os.path.join(INPUTS, name)).read()
        is_json = name.endswith(".json")
        op = rng.choice(["number", "number", "number", "type", "delete", "swap", "truncate", "garbage", "nest"])
        if op == "number":
            text, mutation = replace_number(rng, text, values=EXTREME + ["1e400"] if is_json else EXTREME)
        elif op == "type":
            types = ('"abc"', "[1, 2]", "{}" if is_json else "{ a = 1 }", "true", "null" if is_json else '""')
            text, mutation = replace_number(rng, text, values=(), wrong_types=types)
        elif op == "delete":
            text, mutation = delete_token(rng, text)
        elif op == "swap":
            text, mutation = swap_tokens(rng, text)
        elif op == "truncate":
            text, mutation = truncate(rng, text)
        elif op == "garbage":
            text, mutation = garbage(rng, text)
        else:
            text, mutation = deep_nesting(rng, text, is_json)
        files = {name: text, "law.json": law_text}
        cases.append(Case(f"case-{k}", "cli", name, mutation, files, case_command(runin, name, text)))
    return cases


def law_cases(rng, count, runin, law_text):
    cases = []
    users = [n for n in shipped_cases() if needs_law(open(os.path.join(INPUTS, n)).read())]
    for k in range(count):
        text = law_text
        op = rng.choice(["number", "number", "type", "delete", "truncate", "garbage", "nest", "root"])
        if op == "number":
            text, mutation = replace_number(rng, text, values=EXTREME + ["1e400"])
        elif op == "type":
            text, mutation = replace_number(rng, text, values=(), wrong_types=('"abc"', "[1]", "{}", "null", "true"))
        elif op == "delete":
            text, mutation = delete_token(rng, text)
        elif op == "truncate":
            text, mutation = truncate(rng, text)
        elif op == "garbage":
            text, mutation = garbage(rng, text)
        elif op == "nest":
            text, mutation = deep_nesting(rng, text, True)
        else:
            text = rng.choice(["null", "[]", "1", '"law"', "{}"])
            mutation = f"root replaced by {text}"
        name = rng.choice(users)
        case_text = open(os.path.join(INPUTS, name)).read()
        files = {name: case_text, "law.json": text}
        cases.append(Case(f"law-{k}", "cli", f"law.json ({name})", mutation, files,
                          case_command(runin, name, case_text)))
    return cases


def cli_cases(rng, count, runin):
    cases = []
    names = shipped_cases()
    for k in range(count):
        name = rng.choice(names)
        text = open(os.path.join(INPUTS, name)).read()
        command = case_command(runin, name, text)
        op = rng.choice(["empty-dir", "missing-case", "dir-case", "drop-option", "unknown-option", "bad-sub",
                         "fit-law", "dump-to-vtk", "sweep", "homogenise"])
        files = {name: text}
        if needs_law(text):
            files["law.json"] = None  # filled with the real law by the caller
        if op == "empty-dir":
            command[command.index("--output-dir") + 1] = ""
        elif op == "missing-case":
            command[2] = "{dir}/does_not_exist.toml"
        elif op == "dir-case":
            command[2] = "{dir}"
        elif op == "drop-option":
            drop = rng.randrange(2, len(command))
            command = command[:drop] + command[drop + 1:]
        elif op == "unknown-option":
            command.insert(rng.randrange(2, len(command) + 1), rng.choice(["--bogus", "-x", "--output-dir", "--law"]))
        elif op == "bad-sub":
            command[1] = rng.choice(["pin_on_disk", "", "feedbak", "--help-me"])
        elif op == "sweep":
            # runin sweep over a real key, a wrong key, or a bad span / point count (subprocess runs per value)
            element = command[1] if command[1] != "feedback" else rng.choice(["journal-bearing", "feedback"])
            key = rng.choice(["friction.A", "friction.B", "drive.damping_ratio", "ring.land_damping_ratio", "pin.mass",
                              "bearing.halves", "friction", "no.such.key", ""])
            span = rng.choice(["10", "10", "1", "nan", "1e300", "-2", "abc"])
            points = rng.choice(["3", "3", "4", "1", "11", "x"])
            command = [runin, "sweep", element, command[2], "--output-dir", "{dir}/out", "--no-plot", "--key", key,
                       "--span", span, "--points", points] + (command[command.index("--law"):] if "--law" in command else [])
            op += f" ({element} --key {key!r} --span {span} --points {points})"
        elif op == "homogenise":
            # runin homogenise on its shipped case, mutated or not, with a bad option; the deck is always missing
            # or a directory, so no case reaches LAMMPS (the case is validated first: its errors come before the deck's)
            name = "homogenise_steel.toml"
            text = open(os.path.join(INPUTS, name)).read()
            mutate = rng.choice(["none", "number", "type", "delete"])
            if mutate == "number":
                text, mutation = replace_number(rng, text, values=EXTREME)
            elif mutate == "type":
                text, mutation = replace_number(rng, text, values=(), wrong_types=('"abc"', "[1, 2]", "{ a = 1 }", "true"))
            elif mutate == "delete":
                text, mutation = delete_token(rng, text)
            else:
                mutation = "case as shipped"
            files = {name: text}
            option, value = rng.choice([("--np", "0"), ("--np", "-1"), ("--np", "abc"), ("--np", "1e9"),
                                        ("--output", ""), ("--cache-dir", ""), ("--lmp", "{dir}/no_lmp"),
                                        ("--bogus", "1"), ("--np", "2")])
            command = [runin, "homogenise", "{dir}/" + name, "--cache-dir", "{dir}/cache", "--output",
                       "{dir}/out/law.json", "--deck", rng.choice(["{dir}/no_deck.in", "{dir}"]), option, value]
            op += f" ({mutation}; {option} {value!r})"
        elif op == "fit-law":
            column = rng.choice(["v_slide", "c_fric[3]", "nope", ""])
            source = rng.choice(["{dir}/ave.txt", "{dir}", "{dir}/missing.txt"])
            files = {"ave.txt": rng.choice([open(os.path.join(SOURCE, "tests/data/fric_ave_time.txt")).read(),
                                            open(os.path.join(SOURCE, "tests/data/fric_ave_time_malformed.txt")).read(),
                                            "", "# x\n1 2 nan\n"])}
            command = [runin, "fit-law", "--input", source, "--distance-column", "v_slide", "--mu-column", column,
                       "--output", "{dir}/out/law.json", "--distance-unit", rng.choice(["m", "um", "parsec"])]
        else:
            atoms = rng.choice(["2", "0", "-3", "1000000000000", "50", "abc"])
            dump = ("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n" + atoms + "\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n"
                    "ITEM: ATOMS id type x y z\n1 1 0.1 0.1 0.1\n2 1 0.5 0.5 0.5\n")
            files = {"a.dump": dump}
            command = [runin, "dump-to-vtk", "{dir}/a.dump", "--output-dir", "{dir}/out"]
            op += f" (atom count {atoms})"
        cases.append(Case(f"cli-{k}", "cli", name if "fit" not in op and "dump" not in op else op.split()[0],
                          op, files, command))
    return cases


def controls(lmp, runin, law_text):
    """Every shipped input unmutated: must be OK (guards the classifier against false alarms)."""
    cases = []
    for name, spec in DECKS.items():
        command = [lmp, "-in", "{dir}/" + name, "-log", "none", "-echo", "none"]
        for var, value in spec["short"].items():
            command += ["-var", var, value]
        cases.append(Case(f"control-{name}", "lammps", name, "none", {name: open(os.path.join(INPUTS, name)).read()},
                          command))
    for name in shipped_cases():
        text = open(os.path.join(INPUTS, name)).read()
        cases.append(Case(f"control-{name}", "cli", name, "none", {name: text, "law.json": law_text},
                          case_command(runin, name, text)))
    return cases


# --- running and classifying -------------------------------------------------------------------------------
def non_finite_lines(directory, printed):
    """Lines with a non-finite number in printed text (LAMMPS's thermo output; not ERROR/WARNING lines) and in
    the text files a run wrote (VTK files hold binary data: the writer itself refuses non-finite fields)."""
    bad = [l for l in printed.splitlines()
           if not l.startswith(("ERROR", "WARNING", "Last command", "Last input line", "runin: error"))
           and NON_FINITE.search(l)]
    for root, _, names in os.walk(directory):
        for name in names:
            if name.endswith((".csv", ".dat", ".pvd", ".dump")) and "out" in root + name:
                with open(os.path.join(root, name), errors="replace") as f:
                    bad += [l for l in f if NON_FINITE.search(l)][:1]
    return bad


def classify(case, returncode, stdout, stderr, directory):
    text = stdout + stderr
    if returncode is None:
        return "HANG", "time limit"
    if returncode < 0 or returncode >= 128 or CRASH_TEXT.search(text):
        first = (CRASH_TEXT.search(text).group(0) if CRASH_TEXT.search(text) else f"signal/status {returncode}")
        return "CRASH", first
    # the CLI echoes user text (titles) on stdout: only its files are judged there
    printed_bad = non_finite_lines(directory, stdout if case.kind == "lammps" else "")
    if returncode == 0:
        return ("SILENT_NAN", printed_bad[0].strip()[:200]) if printed_bad else ("OK", "")
    if case.kind == "lammps":
        errors = [l for l in text.splitlines() if l.startswith("ERROR")]
        if not errors:
            return "UNCLEAR", (text.strip().splitlines() or ["no output"])[-1][:200]
        if printed_bad:
            return "SILENT_NAN", "before the ERROR: " + printed_bad[0].strip()[:160]
        if RAW_TEXT.search(errors[0]):
            return "UNCLEAR", errors[0][:200]
        return "CLEAN_ERROR", errors[0][:200]
    lines = [l for l in stderr.strip().splitlines() if l.strip()]
    first = lines[0] if lines else ""
    if printed_bad:
        return "SILENT_NAN", printed_bad[0].strip()[:200]
    if returncode not in (1, 2) or not lines or RAW_TEXT.search(first):
        return "UNCLEAR", first[:200] or f"exit {returncode} without a message"
    # exit 2: bad input, one 'runin: error:' line (case reader, law reader and CLI11's option errors all name
    # the file, key or option); exit 1: the input parsed but the run failed (a diverging solver, a full disk)
    if len(lines) != 1 or not first.startswith("runin: error: "):
        return "UNCLEAR", first[:200]
    return "CLEAN_ERROR", first[:200]


def run_case(case, limit, keep):
    directory = tempfile.mkdtemp(prefix=f"runin-fuzz-{case.id}-")
    for name, text in case.files.items():
        with open(os.path.join(directory, name), "w", encoding="utf-8", errors="surrogatepass") as out:
            out.write(text)
    command = [c.replace("{dir}", directory) for c in case.command]
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    try:
        result = subprocess.run(command, cwd=directory, capture_output=True, timeout=limit, env=env)
        outcome = classify(case, result.returncode, result.stdout.decode(errors="replace"),
                           result.stderr.decode(errors="replace"), directory)
        code = result.returncode
    except subprocess.TimeoutExpired:
        outcome, code = classify(case, None, "", "", directory), None
    seconds = time.time() - start
    if keep and outcome[0] not in ("OK", "CLEAN_ERROR"):
        shutil.copytree(directory, os.path.join(keep, case.id), dirs_exist_ok=True)
    shutil.rmtree(directory, ignore_errors=True)
    return case, outcome, code, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--runin", required=True)
    parser.add_argument("--set", choices=["quick", "full"], default="quick")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--only", default="decks,cases,laws,cli")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--limit", type=float, default=30.0, help="seconds per case before it is a HANG")
    parser.add_argument("--report", help="CSV: id, kind, input, mutation, class, exit, seconds, first message")
    parser.add_argument("--case", help="run only this case id (as listed in a report)")
    parser.add_argument("--keep", help="copy the directory of every failing case here")
    args = parser.parse_args()

    lmp, runin = os.path.abspath(args.lmp), os.path.abspath(args.runin)
    scratch = tempfile.mkdtemp(prefix="runin-fuzz-law-")
    subprocess.run([runin, "fit-law", "--input", os.path.join(SOURCE, "tests/data/fric_ave_time.txt"),
                    "--distance-column", "v_slide", "--mu-column", "c_fric[3]", "--output",
                    os.path.join(scratch, "law.json")], check=True, capture_output=True)
    law_text = open(os.path.join(scratch, "law.json")).read()
    shutil.rmtree(scratch)

    sizes = {"quick": {"decks": 12, "cases": 40, "laws": 12, "cli": 16},
             "full": {"decks": 120, "cases": 280, "laws": 60, "cli": 60}}[args.set]
    rng = random.Random(args.seed)
    wanted = set(args.only.split(","))
    cases = controls(lmp, runin, law_text)
    if "decks" in wanted:
        cases += deck_cases(random.Random(rng.random()), sizes["decks"], lmp)
    if "cases" in wanted:
        cases += case_file_cases(random.Random(rng.random()), sizes["cases"], runin, law_text)
    if "laws" in wanted:
        cases += law_cases(random.Random(rng.random()), sizes["laws"], runin, law_text)
    if "cli" in wanted:
        cli = cli_cases(random.Random(rng.random()), sizes["cli"], runin)
        for case in cli:
            if "law.json" in case.files:
                case.files["law.json"] = law_text
        cases += cli
    if args.case:
        cases = [c for c in cases if c.id == args.case]
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)

    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_case, c, args.limit, args.keep) for c in cases]
        for n, future in enumerate(concurrent.futures.as_completed(futures), 1):
            case, (label, message), code, seconds = future.result()
            results.append((case, label, message, code, seconds))
            if label not in ("OK", "CLEAN_ERROR") or n % 50 == 0 or n == len(cases):
                print(f"[{n}/{len(cases)}] {case.id} {label} ({case.source}: {case.mutation}) {message}", flush=True)

    results.sort(key=lambda r: r[0].id)
    if args.report:
        with open(args.report, "w", newline="") as out:
            writer = csv.writer(out)
            writer.writerow(["id", "kind", "input", "mutation", "class", "exit", "seconds", "message"])
            for case, label, message, code, seconds in results:
                writer.writerow([case.id, case.kind, case.source, case.mutation[:200], label, code,
                                 f"{seconds:.2f}", message])
    classes = ["OK", "CLEAN_ERROR", "CRASH", "HANG", "SILENT_NAN", "UNCLEAR"]
    by_input = {}
    for case, label, *_ in results:
        by_input.setdefault(case.source.split(" ")[0], dict.fromkeys(classes, 0))[label] += 1
    print(f"\n{'input':32s}" + "".join(f"{c:>12s}" for c in classes))
    for source in sorted(by_input):
        print(f"{source:32s}" + "".join(f"{by_input[source][c]:12d}" for c in classes))
    totals = {c: sum(1 for r in results if r[1] == c) for c in classes}
    print(f"{'all (' + str(len(results)) + ' cases, seed ' + str(args.seed) + ')':32s}" +
          "".join(f"{totals[c]:12d}" for c in classes))
    controls_bad = [r for r in results if r[0].id.startswith("control-") and r[1] != "OK"]
    for case, label, message, *_ in controls_bad:
        print(f"control {case.id} is {label}: {message}")
    bad = sum(totals[c] for c in classes[2:]) + len(controls_bad)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
