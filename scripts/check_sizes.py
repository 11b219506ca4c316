#!/usr/bin/env python3
"""Lists source files over MAX_FILE lines and functions over MAX_FUNC lines (issue 12's limits).

A function is a definition that starts at column 0 (clang-format puts top-level definitions there)
and ends at the next '}' at column 0; member functions defined inside a class are counted with the
class. Usage: scripts/check_sizes.py [--max-file N] [--max-func N] [DIR...] (default lib apps tests
bench). Exit 1 when anything is over.
"""
import argparse
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
START = re.compile(r"^(?!namespace|struct|class|enum|union|template|#|//|extern|using|static_assert)"
                   r"[A-Za-z_].*\)\s*(const\s*)?(noexcept\s*)?(->\s*[^{]+)?\{\s*$")


def functions(lines):
    i = 0
    while i < len(lines):
        line = lines[i]
        head = line
        j = i
        # a signature may span lines: join until '{' at the end of a line
        while not head.rstrip().endswith("{") and j + 1 < len(lines) and j - i < 6 and \
                not head.rstrip().endswith(";") and line[:1].isalpha():
            j += 1
            head += " " + lines[j].strip()
        if line[:1].isalpha() and START.match(head.replace("\n", " ")):
            k = j + 1
            while k < len(lines) and not lines[k].startswith("}"):
                k += 1
            name = re.sub(r"\(.*", "", head).split()[-1] if "(" in head else head
            yield name, i + 1, k - i + 1
            i = k + 1
        else:
            i += 1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--max-file", type=int, default=500)
    ap.add_argument("--max-func", type=int, default=120)
    ap.add_argument("dirs", nargs="*", default=["lib", "apps", "tests", "bench"])
    a = ap.parse_args()
    over = 0
    for d in a.dirs:
        for p in sorted((ROOT / d).rglob("*")):
            if p.suffix not in (".cpp", ".hpp") or "fuzz/corpus" in str(p):
                continue
            lines = p.read_text(errors="replace").splitlines()
            rel = p.relative_to(ROOT)
            if len(lines) > a.max_file:
                print(f"{rel}: {len(lines)} lines (max {a.max_file})")
                over += 1
            for name, at, n in functions(lines):
                if n > a.max_func:
                    print(f"{rel}:{at}: function {name} is {n} lines (max {a.max_func})")
                    over += 1
    print(f"check_sizes: {over} over the limits")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
