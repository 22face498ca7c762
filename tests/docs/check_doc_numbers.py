#!/usr/bin/env python3
"""Every number a README or doc page quotes, checked against the run that produces it (tests/doc_numbers.toml).

  check_doc_numbers.py GROUP --manifest tests/doc_numbers.toml [--lmp LMP] [--runin RUNIN] [--mpiexec MPIEXEC]
                       [--workdir DIR]
  check_doc_numbers.py --hygiene --manifest tests/doc_numbers.toml
  check_doc_numbers.py --list --manifest tests/doc_numbers.toml   (name|needs|labels of each group, one a line)

A group has one source: `log` or `keys` (a reference file under examples/, a glob that must match one file), or
`command` (run in DIR; {lmp} {runin} {mpiexec} {python} {source} {work} are substituted; its output is the
source text, and `log` names a LAMMPS log it writes in DIR, if any, whose text is added to it). Each of its numbers names the doc file, a
regex `quote` whose one group is the number as the doc prints it (it must match exactly once, unless
`occurrence` picks one of several), and `value`, a Python expression on the source:
  log(table, row, column)   a thermo value of the log (tables and rows count from 0, -1 is the last)
  log_table(table)          the rows of a thermo table, as {column: value} dicts
  text(regex[, group[, occurrence]])   a number the source text prints (default: the last match)
  texts(regex[, group])     every such number, as a list
  key(name)                 a value of a key-number file ('name value' lines)
  csv(path, column[, row])  a value of a CSV the command wrote (path relative to DIR)
  column(path, name)        every value of a CSV column, as a list
  rank_diff(glob_a, glob_b) the worst difference over all columns of two reference files (check_example.py --diff)
  plus math's functions.
The doc's number must equal the value to the digits it prints (|doc - value| <= half a unit of its last digit);
`atol` / `rtol` widen that where the doc rounds further on purpose (say why in `why`).
--hygiene: no README or doc page may point outside the repository, no file refers to the issue tracker
(`forbidden` patterns, each with its files and `except` globs), the repository root holds no generated files
(`root_data` globs), tracked or not, and the doc index (`index.file`) links every page (`index.pages`).
"""
import argparse
import csv as csvmod
import glob
import math
import os
import re
import subprocess
import sys
import tomllib

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


class Failed(Exception):
    pass


def thermo_tables(text):
    """LAMMPS thermo tables as lists of {column: value} rows ('Step' header ... 'Loop time')."""
    tables, header, rows = [], None, []
    for line in text.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header, rows = words, []
        elif header is not None and line.startswith("Loop time"):
            tables.append(rows)
            header = None
        elif header is not None and len(words) == len(header):
            try:
                rows.append(dict(zip(header, (float(w) for w in words))))
            except ValueError:
                pass
    return tables


def one_file(pattern):
    found = sorted(glob.glob(os.path.join(SOURCE_DIR, pattern)))
    if len(found) != 1:
        raise Failed(f"source {pattern}: want exactly one file, found {[os.path.relpath(f, SOURCE_DIR) for f in found]}")
    return found[0]


class Source:
    """What a group's numbers are read from: a reference file, or a command's output and files."""

    def __init__(self, group, args):
        self.work = os.path.abspath(args.workdir or os.path.join(os.getcwd(), f"doc_numbers_{group['name']}"))
        self.text, self.log_text, self.keys = "", None, None
        if "command" in group:
            os.makedirs(self.work, exist_ok=True)

            def program(path, default):  # a relative path is the caller's (the command runs in DIR)
                return os.path.abspath(path) if path and os.sep in path else (path or default)

            names = {"lmp": program(args.lmp, "lmp_runin"), "runin": program(args.runin, "runin"),
                     "mpiexec": program(args.mpiexec, "mpiexec"),
                     "python": sys.executable, "source": SOURCE_DIR, "work": self.work}
            command = [word.format(**names) for word in group["command"]]
            env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                       OMPI_MCA_rmaps_base_oversubscribe="1", OMP_NUM_THREADS="1")
            result = subprocess.run(command, cwd=self.work, env=env, capture_output=True, text=True,
                                    timeout=group.get("timeout", 300))
            if result.returncode != 0:
                raise Failed(f"{' '.join(command)} exited with {result.returncode}:\n{(result.stdout + result.stderr)[-2000:]}")
            self.text = result.stdout + result.stderr
            if "log" in group:
                self.log_text = open(os.path.join(self.work, group["log"]), errors="replace").read()
                self.text += self.log_text
        elif "log" in group:
            self.log_text = open(one_file(group["log"]), errors="replace").read()
            self.text = self.log_text
        elif "keys" in group:
            path = one_file(group["keys"])
            self.text = open(path).read()
            self.keys = {}
            for line in self.text.splitlines():
                words = line.split("#", 1)[0].split()
                if len(words) == 2:
                    self.keys[words[0]] = float(words[1])
        self.tables = thermo_tables(self.log_text) if self.log_text is not None else None

    def namespace(self):
        def log(table, row, column):
            if self.tables is None:
                raise Failed("log(): this group's source has no LAMMPS log")
            try:
                return self.tables[table][row][column]
            except (IndexError, KeyError):
                raise Failed(f"log({table}, {row}, {column!r}): no such value ({len(self.tables)} tables)") from None

        def text(regex, group=1, occurrence=-1):
            found = list(re.finditer(regex, self.text, re.M))
            if not found:
                raise Failed(f"text({regex!r}): the source prints no such line")
            return float(found[occurrence].group(group).replace(",", ""))

        def log_table(table):
            if self.tables is None or not -len(self.tables) <= table < len(self.tables):
                raise Failed(f"log_table({table}): no such thermo table")
            return self.tables[table]

        def texts(regex, group=1):
            return [float(m.group(group).replace(",", "")) for m in re.finditer(regex, self.text, re.M)]

        def key(name):
            if self.keys is None or name not in self.keys:
                raise Failed(f"key({name!r}): not in the source's key numbers")
            return self.keys[name]

        def csv(path, column, row=-1):
            rows = list(csvmod.DictReader(open(os.path.join(self.work, path))))
            return float(rows[row][column])

        def column(path, name):
            return [float(r[name]) for r in csvmod.DictReader(open(os.path.join(self.work, path)))]

        def rank_diff(file_a, file_b):
            """examples/check_example.py --diff: the worst difference over all columns of two reference files."""
            sys.path.insert(0, os.path.join(SOURCE_DIR, "examples"))
            import check_example
            a, b = (check_example.read_output(one_file(f), check_example.kind_of(f)) for f in (file_a, file_b))
            worst = 0.0
            for ta, tb in zip(a, b):
                for name in ta["header"]:
                    if name in tb["header"]:
                        worst = max(worst, check_example.worst_difference(
                            check_example.column(tb, name, "b"), check_example.column(ta, name, "a")))
            return worst

        names = {name: getattr(math, name) for name in dir(math) if not name.startswith("_")}
        names.update(log=log, log_table=log_table, text=text, texts=texts, key=key, csv=csv, column=column, rank_diff=rank_diff, abs=abs, min=min, max=max, range=range, sum=sum, len=len, zip=zip)
        return names


def printed_half_unit(number):
    """Half a unit of the last digit of a printed number: '851' -> 0.5, '0.0201' -> 5e-5, '1.57e-07' -> 5e-10."""
    mantissa, _, exponent = number.lower().partition("e")
    decimals = len(mantissa.split(".", 1)[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def check_group(group, args):
    source = Source(group, args)
    names = source.namespace()
    problems, checked = [], 0
    docs = {}
    for number in group["number"]:
        doc = number["doc"]
        if doc not in docs:
            docs[doc] = open(os.path.join(SOURCE_DIR, doc)).read()
        found = list(re.finditer(number["quote"], docs[doc]))
        where = f"{doc}: /{number['quote']}/"
        if "occurrence" in number:
            if len(found) <= number["occurrence"]:
                problems.append(f"{where}: quoted {len(found)} times, want occurrence {number['occurrence']}")
                continue
            match = found[number["occurrence"]]
        elif len(found) != 1:
            problems.append(f"{where}: the doc quotes it {len(found)} times, want exactly once")
            continue
        else:
            match = found[0]
        printed = match.group(1).replace(",", "")
        try:
            quoted = float(printed)
        except ValueError:
            problems.append(f"{where}: {printed!r} is not a number")
            continue
        try:
            value = float(eval(number["value"], dict(names, __builtins__={})))  # noqa: S307 (the project's manifest)
        except Failed as error:
            problems.append(f"{where}: {error}")
            continue
        except Exception as error:  # a bad expression in the manifest
            problems.append(f"{where}: value {number['value']!r}: {type(error).__name__}: {error}")
            continue
        # a bare "0" says zero, not "below 0.5"
        half_unit = 0.0 if re.fullmatch(r"[-+]?0", printed) else printed_half_unit(printed)
        allowed = half_unit * (1 + 1e-9) + number.get("atol", 0.0) + number.get("rtol", 0.0) * abs(value)
        line = f"{doc}: {match.group(0)!r} -> {printed} vs {number['value']} = {value:.6g} (allowed {allowed:.2g})"
        if not abs(quoted - value) <= allowed:
            problems.append("MISMATCH " + line)
        else:
            print("  ok  " + line)
            checked += 1
    if problems:
        raise Failed(f"{len(problems)} of {len(group['number'])} numbers do not match their run:\n  " + "\n  ".join(problems))
    print(f"PASS docs.numbers.{group['name']}: {checked} quoted numbers equal what the run gives")


def hygiene(manifest):
    problems = []
    rules = manifest["hygiene"]
    for rule in rules["forbidden"]:
        excepted = {os.path.join(SOURCE_DIR, e) for e in rule.get("except", [])}
        for pattern in rule["files"]:
            for path in sorted(glob.glob(os.path.join(SOURCE_DIR, pattern))):
                if path in excepted or not os.path.isfile(path):
                    continue
                for number, line in enumerate(open(path, errors="replace"), 1):
                    if re.search(rule["pattern"], line):
                        problems.append(f"{os.path.relpath(path, SOURCE_DIR)}:{number}: {rule['why']}: {line.strip()[:120]}")
    for pattern in rules["root_data"]:
        for path in sorted(glob.glob(os.path.join(SOURCE_DIR, pattern))):
            if os.path.isfile(path):
                problems.append(f"{os.path.relpath(path, SOURCE_DIR)}: a generated file at the repository root "
                                "(whatever wrote it should write into its output directory)")
    index = rules.get("index")
    if index:
        text = open(os.path.join(SOURCE_DIR, index["file"])).read()
        for pattern in index["pages"]:
            for path in sorted(glob.glob(os.path.join(SOURCE_DIR, pattern))):
                name = os.path.basename(path)
                if os.path.relpath(path, SOURCE_DIR) != index["file"] and f"]({name})" not in text:
                    problems.append(f"{index['file']}: no link to {os.path.relpath(path, SOURCE_DIR)}")
    if problems:
        raise Failed("\n  ".join([f"{len(problems)} problem(s):"] + problems))
    print("PASS docs.hygiene: no doc points outside the repository, no issue-tracker references, no generated "
          "files at the root, the doc index links every page")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0], epilog=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("group", nargs="?")
    parser.add_argument("--manifest", default=os.path.join(SOURCE_DIR, "tests", "doc_numbers.toml"))
    parser.add_argument("--lmp")
    parser.add_argument("--runin")
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--workdir")
    parser.add_argument("--hygiene", action="store_true")
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    manifest = tomllib.load(open(args.manifest, "rb"))
    try:
        if args.list:
            for group in manifest["group"]:   # name|what its command needs|labels|timeout [s], for tests/docs/CMakeLists.txt
                command = " ".join(group.get("command", []))
                needs = [tool for tool in ("lmp", "runin") if "{" + tool + "}" in command]
                print("|".join([group["name"], ",".join(needs) or "-", group.get("labels", "docs"),
                                str(group.get("timeout", 300))]))
        elif args.hygiene:
            hygiene(manifest)
        else:
            groups = [g for g in manifest["group"] if g["name"] == args.group]
            if not groups:
                raise Failed(f"no group {args.group!r} in {args.manifest}")
            check_group(groups[0], args)
    except Failed as error:
        print(f"FAIL {args.group or 'docs.hygiene'}: {error}")
        sys.exit(1)


if __name__ == "__main__":
    main()
