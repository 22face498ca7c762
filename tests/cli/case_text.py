"""Edits of TOML case-file text for the stress sweeps (stdlib only; the cases stay readable files)."""
import re
import sys


def edit(text, section, key, value):
    """Replace `key = ...` inside [section] (the key must exist there)."""
    pattern = re.compile(r"(\[" + re.escape(section) + r"\][^\[]*?^" + re.escape(key) + r"\s*=)[^\n#]*", re.S | re.M)
    new, n = pattern.subn(lambda m: m.group(1) + " " + value + " ", text)
    if n != 1:
        sys.exit(f"stress: cannot set {section}.{key}")
    return new


def drop_section(text, section):
    """Remove [section] and its lines up to the next table header."""
    return re.sub(r"^\[" + re.escape(section) + r"\]\n(?:(?!\[).*\n?)*", "", text, flags=re.M)
