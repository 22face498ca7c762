#!/usr/bin/env python3
"""House rule: tests never copy the registry's list of sub-model names (the "known: ..." of the messages); they
derive it from the registry (registered_names(), or {registry:KIND} in the deck tests' patterns, which
tests/lammps/run_deck.py fills from runin_registry_names), so adding a registry row needs no test edit
(doc/architecture.md, "One contact model, and how to add a law").
Reads the registry's tuples from src/tribo/contact_model.h and reports, in tests/**/{CMakeLists.txt,*.cmake,*.py,*.cpp,
*.h}, a "known: NAME" of a registered name and any run of two or more registered names of one kind joined by ", ".
A synthetic test file that does both must be reported, so the check can fail."""
import glob
import os
import re
import sys
import tempfile

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REGISTRY = os.path.join(SOURCE, "src", "tribo", "contact_model.h")


def registry():
    """{kind: [name, ...]} from the registry's tuples (using <Kind>Models = std::tuple<Class, ...>)."""
    text = open(REGISTRY).read()
    names = dict(re.findall(r'class (\w+Model) \{\s*public:\s*static constexpr const char \*name = "([^"]+)"', text))
    kinds = {}
    for kind, body in re.findall(r"using (\w+)Models = std::tuple<([^>]*)>;", text):
        kinds[kind.lower()] = [names[c] for c in re.findall(r"\w+Model\b", body) if c in names]
    if sum(len(v) for v in kinds.values()) < 5:
        sys.exit(f"FAIL: found only {kinds} in {REGISTRY}")
    return kinds


def patterns(kinds):
    everything = sorted({n for v in kinds.values() for n in v}, key=len, reverse=True)
    out = [re.compile(r"known: (%s)(?![\w/])" % "|".join(re.escape(n) for n in everything))]
    for names in kinds.values():
        if len(names) > 1:
            one = "(%s)" % "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))
            out.append(re.compile(r"(?<![\w/])%s, %s(?![\w/])" % (one, one)))
    return out


def findings(path, checks):
    rel = os.path.relpath(path, SOURCE)
    return [f"{rel}:{number}: {line.strip()}"
            for number, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1)
            if any(check.search(line) for check in checks)]


kinds = registry()
checks = patterns(kinds)
friction, normal = kinds["friction"], kinds["normal"]
with tempfile.TemporaryDirectory() as tmp:
    probe = os.path.join(tmp, "CMakeLists.txt")
    with open(probe, "w") as f:
        f.write(f'  "bad|unknown friction model .known: {friction[0]}, {friction[1]}."\n'
                f'  "bad|unknown normal model .known: {normal[0]}[,)]"\n'
                f'EXPECT_EQ(message, "({friction[-1]}, {friction[0]})");\n'
                f'  "good|unknown friction model .known: {{registry:friction}}."\n'
                f'# {friction[0]} and {friction[1]}; {normal[0]}, {friction[0]} (two kinds)\n')
    found = findings(probe, checks)
    if len(found) != 3 or any("good" in hit or "two kinds" in hit for hit in found):
        sys.exit("FAIL: the check does not report exactly the three lists of the probe:\n" + "\n".join(found))
files = sorted(path for pattern in ("CMakeLists.txt", "*.cmake", "*.py", "*.cpp", "*.h")
               for path in glob.glob(os.path.join(SOURCE, "tests", "**", pattern), recursive=True))
bad = [hit for path in files for hit in findings(path, checks)]
if bad:
    sys.exit("FAIL: a test copies the registry's names (derive them: registered_names(), {registry:KIND}):\n" +
             "\n".join(bad))
print(f"{len(files)} test files, {sum(len(v) for v in kinds.values())} registered sub-models: no test lists them")
