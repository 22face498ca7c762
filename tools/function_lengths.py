#!/usr/bin/env python3
"""Lengths of the C++ functions in FILES (signature line to closing brace, by brace matching on the text with
comments, strings and preprocessor lines blanked; lambdas count in their enclosing function).

  function_lengths.py [--max N] [--all] FILES...

Prints each function over N lines (default 80; --all: every function) as `lines  path:line  name`, then a
summary line; exit status 1 when any function is over N. House rule: no function in src/cli over 80 lines
(ctest tools.cli_function_lengths)."""
import argparse
import re
KEYWORDS = ("if", "for", "while", "switch", "catch", "do", "else", "try", "return")
def strip(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i); j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:]); end = text.find(')' + m.group(1) + '"', i) + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end])); i = end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + c); i = j + 1
        elif c == "#" and (i == 0 or text[i-1] == "\n"):
            j = text.find("\n", i)
            while j > 0 and text[j-1] == "\\": j = text.find("\n", j + 1)
            j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        else:
            out.append(c); i += 1
    return "".join(out)
def functions(path):
    text = strip(open(path).read())
    stack, header_start, rows = [], 0, []
    for i, c in enumerate(text):
        if c == "{":
            header = text[header_start:i]
            kind = "block"
            inside_function = any(k == "function" for k, _ in stack)
            h = " ".join(header.split())
            if not inside_function:
                if re.match(r"^(namespace|extern)\b", h) or h == "" and not stack or h.startswith("namespace"):
                    kind = "namespace"
                elif re.search(r"\b(struct|class|union|enum)\b", h) and "(" not in h.split("{")[0].split(":")[0]:
                    kind = "class"
                elif ")" in h and not re.match(r"^(%s)\b" % "|".join(KEYWORDS), h) and not h.rstrip().endswith("="):
                    kind = "function"
            line = text.count("\n", 0, header_start + (len(header) - len(header.lstrip()))) + 1
            stack.append((kind, (line, h)))
            header_start = i + 1
        elif c == "}":
            if not stack: continue
            kind, (line, h) = stack.pop()
            if kind == "function":
                end = text.count("\n", 0, i) + 1
                name = re.sub(r"\(.*", "", h).split()[-1] if "(" in h else h
                rows.append((end - line + 1, path, line, name))
            header_start = i + 1
        elif c == ";":
            header_start = i + 1
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--max", type=int, default=80)
    ap.add_argument("--all", action="store_true")
    ap.add_argument("files", nargs="+")
    a = ap.parse_args()
    rows = sorted((r for p in a.files for r in functions(p)), reverse=True)
    for n, path, line, name in rows:
        if n > a.max or a.all:
            print(f"{n:5d}  {path}:{line}  {name}")
    over = sum(1 for r in rows if r[0] > a.max)
    print(f"# {over} of {len(rows)} functions over {a.max} lines")
    return 1 if over else 0


if __name__ == "__main__":
    raise SystemExit(main())
