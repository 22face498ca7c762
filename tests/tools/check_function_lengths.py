#!/usr/bin/env python3
"""House rule: no function in src/cli over 80 lines (the CLI reads cases, runs and writes; physics and long
procedures live in the library). Runs tools/function_lengths.py on a synthetic file with an 81-line function (it
must be reported, so the check can fail) and on src/cli/*.{cpp,h} (none may be over 80)."""
import glob
import os
import subprocess
import sys
import tempfile

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOOL = os.path.join(SOURCE, "tools", "function_lengths.py")


def run(files):
    return subprocess.run([sys.executable, TOOL, *files], capture_output=True, text=True)


with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "long.cpp")
    with open(path, "w") as f:
        f.write("namespace x {\nint long_one(int a) {\n" + "  a += 1;  // { not a brace\n" * 79 + "}\n"
                "int short_one() { return \"}\"[0]; }\n}\n")
    result = run([path])
    if result.returncode != 1 or "long_one" not in result.stdout or "short_one" in result.stdout:
        sys.exit(f"FAIL: the tool does not report an 81-line function alone: {result.stdout}")
files = sorted(glob.glob(os.path.join(SOURCE, "src", "cli", "*.cpp")) + glob.glob(os.path.join(SOURCE, "src", "cli", "*.h")))
result = run(files)
print(result.stdout, end="")
if result.returncode != 0:
    sys.exit("FAIL: functions in src/cli over 80 lines (split them; move procedures into the library)")
print("PASS")
