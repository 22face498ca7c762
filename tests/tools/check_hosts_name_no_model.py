#!/usr/bin/env python3
"""House rule: the contact hosts (plugins/) and the CLI (src/cli) never name a concrete sub-model; they ask the
registry's capabilities and queries (SubModelInfo, FlattensSummits, HasFilm, interface_friction_models, ...;
doc/architecture.md, "One contact model, and how to add a law").
Reads the registered classes and their names from src/tribo/contact_model.h and reports, in plugins/**/*.{h,cpp} and
src/cli/*.{h,cpp}, any use of a sub-model class, any comparison with (or lookup of) a registered name as a literal,
any list of two registered names as literals and a registered name as the last field of a table row. A synthetic host file that does each must be reported, so the check
can fail. Allowed, with the reason: ALLOWED below."""
import glob
import os
import re
import sys
import tempfile

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REGISTRY = os.path.join(SOURCE, "src", "tribo", "contact_model.h")
# (file suffix, line substring): a keyword of the host that shares a model's name
ALLOWED = [
    # pair_style / fix runin/wall keyword 'archard plain|thesis': the Archard form, a host setting (ContactSettings)
    ("plugins/common/pair_style.h", 'keyword == "archard"'),    # both pairs' pair_style keywords
    ("plugins/common/runin_wall_core.h", 'keyword == "archard"'),
    # friction.out_of_range = "archard" of a state-law case: wear proportional to p outside the law's grid
    ("src/cli/case_file.cpp", 'policy == "archard"'),
    ("src/cli/case_file.cpp", '"friction.out_of_range"'),
    ("src/cli/lubricated_bearing.cpp", '"friction.out_of_range"'),
]


def registered():
    text = open(REGISTRY).read()
    classes = dict(re.findall(r'class (\w+Model) \{\s*public:\s*static constexpr const char \*name = "([^"]+)"', text))
    if len(classes) < 5:
        sys.exit(f"FAIL: found only {len(classes)} sub-model classes in {REGISTRY}")
    return classes


def findings(path, classes):
    out = []
    names = "|".join(re.escape(n) for n in classes.values())
    literal = re.compile(r'(==|!=)\s*"(%s)"|"(%s)"\s*(==|!=)|find_sub_model\([^;]*"(%s)"|"(%s)",\s*"(%s)"|'
                         r',\s*"(%s)"\s*\}' % (names, names, names, names, names, names))
    used_class = re.compile(r"\b(%s)\b" % "|".join(classes))
    rel = os.path.relpath(path, SOURCE)
    for number, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
        if any(rel.endswith(suffix) and snippet in line for suffix, snippet in ALLOWED):
            continue
        if used_class.search(line) or literal.search(line):
            out.append(f"{rel}:{number}: {line.strip()}")
    return out


classes = registered()
with tempfile.TemporaryDirectory() as tmp:
    probe = os.path.join(tmp, "host.cpp")
    with open(probe, "w") as f:
        f.write('bool a(const std::string &name) { return name == "junction"; }\n'
                "const char *b = tribo::JunctionFilmFrictionModel::name;\n"
                "bool c() { return choice == tribo::find_sub_model(kind, \"elastic/plastic\"); }\n"
                'const char *d = "junction: a message";\n'
                'auto e = reader.choice("contact.friction", {"strength", "brizmer"});\n'
                '{"group", 2, {"tau_s", "plough"}, "strength"},\n')
    found = findings(probe, classes)
    if len(found) != 5 or "a message" in " ".join(found):
        sys.exit("FAIL: the check does not report exactly the five namings of the probe:\n" + "\n".join(found))
files = sorted(path for folder in ("plugins/**", "src/cli") for ext in ("h", "cpp")
               for path in glob.glob(os.path.join(SOURCE, folder, "*." + ext), recursive=True))
bad = [hit for path in files for hit in findings(path, classes)]
if bad:
    sys.exit("FAIL: a host or the CLI names a concrete sub-model (ask the registry instead):\n" + "\n".join(bad))
print(f"{len(files)} host and CLI files, {len(classes)} registered sub-models: none names one")
