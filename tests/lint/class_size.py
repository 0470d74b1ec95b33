#!/usr/bin/env python3
"""Fails when a class of the given sources has too many member functions or data members.

Usage: class_size.py MAX_FUNCTIONS MAX_DATA FILE... [--report] [--known NAME:FUNCTIONS:DATA ...]
A class is a 'class' or 'struct' body; its member functions are the functions declared or
defined at its top level (constructors and operators included, each name once per
declaration), its data members the other declarations there (static constants included). A
class whose members are all data (a plain settings aggregate: no member function) is held to
the function limit only. A class's definitions out of its body ('X::f(') count once, where
they are declared. With --report every class is listed, largest first. --known names a class
over the limits that is allowed at most its present counts (work still to do: it must not grow).
"""
import re
import sys

sys.path.insert(0, __import__("os").path.dirname(__file__))
from function_length import blank_literals  # noqa: E402


def classes(path):
    text = blank_literals(open(path, encoding="utf-8").read())
    text = "\n".join(l for l in text.split("\n") if not l.lstrip().startswith("#"))
    out = []
    for m in re.finditer(r"\b(class|struct)\s+([A-Za-z_]\w*)[^;{()]*\{", text):
        name, start = m.group(2), m.end()
        if re.match(r"\s*enum", text[m.start() - 5:m.start()]):
            continue
        depth, i, stmt, functions, data = 1, start, "", 0, 0
        while i < len(text) and depth:
            c = text[i]
            if c == "{":
                if depth == 1:
                    if re.search(r"\)\s*(const|override|noexcept|final|mutable|\s)*(->[^{]*)?$", stmt.strip()) or \
                       re.search(r"\)\s*:.*$", stmt.strip(), re.S):
                        functions += 1
                        stmt = "<fn>"
                    elif re.match(r"\s*(class|struct|union|enum)\b", stmt):
                        stmt = "<nested>"
                depth += 1
            elif c == "}":
                depth -= 1
                if depth == 1 and stmt in ("<fn>",):
                    stmt = ""
            elif depth == 1:
                if c == ";":
                    s = " ".join(stmt.split())
                    s = re.sub(r"^(public|private|protected)\s*:\s*", "", s)
                    if s.startswith("<nested>") or s.startswith("<fn>") or not s or s.startswith("using ") \
                       or s.startswith("friend ") or s.startswith("typedef ") or s.startswith("static_assert"):
                        pass
                    elif re.search(r"\w\s*\([^)]*\)\s*(const|override|noexcept|final|=\s*(0|default|delete)|\s)*$", s) \
                            and not re.search(r"=\s*[^=]*\(", s.split("(")[0] + "("):
                        functions += 1
                    else:
                        data += max(1, s.count(",") + 1 if "(" not in s and "{" not in s and "<" not in s else 1)
                    stmt = ""
                else:
                    stmt += c
                    if c == ":" and re.search(r"(public|private|protected)\s*:$", stmt):
                        stmt = ""
            i += 1
        out.append((name, functions, data))
    return out


def main(argv):
    maxf, maxd = int(argv[1]), int(argv[2])
    known, files, args = {}, [], argv[3:]
    while args:
        a = args.pop(0)
        if a == "--known":
            name, f, d = args.pop(0).split(":")
            known[name] = (int(f), int(d))
        elif a != "--report":
            files.append(a)
    rows = []
    for f in files:
        for name, fn, data in classes(f):
            rows.append((fn, data, name, f))
    bad = 0
    for fn, data, name, f in sorted(rows, reverse=True):
        limf, limd = known.get(name, (maxf, maxd))
        limf, limd = max(limf, maxf), max(limd, maxd)
        over = fn > limf or (data > limd and fn > 0)
        if over or "--report" in argv:
            print(f"{f}: {name}: {fn} member functions, {data} data members" + ("  <- over" if over else "")
                  + ("  (known)" if name in known and not over else ""))
        bad += over
    print(f"{len(rows)} classes in {len(files)} files, {bad} over the limits ({maxf} functions, {maxd} data members)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
