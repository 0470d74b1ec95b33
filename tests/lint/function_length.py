#!/usr/bin/env python3
"""Fails when a function defined in the given source files is longer than the limit.

Usage: function_length.py LIMIT FILE... [--run-limit N]
Every function definition counts: at namespace scope and inside class bodies (member functions
defined where they are declared). The sources are read with comments, strings and character
literals blanked, braces matched: a brace that ends its line opens a scope whose kind comes from
the text before it (a function when that text is a signature: balanced parentheses, not a
control statement, no '=' outside them; a class, a namespace, or anything else, whose insides
are not functions); a brace closed on its own line is part of the text (a one-line body, a
braced initialiser). A function's length counts the lines from the first line of its signature
to its closing brace. With --run-limit, the bodies of '::run(' definitions must be at most N
lines as well (the analyses' run() as named steps).
"""
import re
import sys

CONTROL = ("if", "for", "while", "switch", "catch", "do", "else", "try", "return")
SCOPES = ("namespace", "class", "struct", "union", "enum", "extern")


def blank_literals(text):
    """Comments, strings and character literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == '"' and text[max(0, i - 1)] == "R" and text.startswith('"(', i):
            j = text.find(')"', i)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def balanced(s):
    depth = 0
    for ch in s:
        depth += ch == "("
        depth -= ch == ")"
        if depth < 0:
            return False
    return depth == 0


def is_signature(header):
    h = " ".join(header.split())
    if "(" not in h or not balanced(h):
        return False
    first = re.match(r"[A-Za-z_]+", h)
    if first and first.group(0) in CONTROL + SCOPES:
        return False
    outside = re.sub(r"\([^()]*\)", "", h)
    while re.search(r"\([^()]*\)", outside):
        outside = re.sub(r"\([^()]*\)", "", outside)
    outside = outside.replace("==", "").replace("<=", "").replace(">=", "").replace("!=", "")
    return "=" not in outside.replace("operator=", "") and "[" not in h.split("(")[0]


def scope_kind(header):
    h = " ".join(header.split())
    h = re.sub(r"^template\s*<[^{]*?>\s*", "", h)
    first = re.match(r"[A-Za-z_]+", h)
    if first and first.group(0) in SCOPES:
        return "scope"
    return "function" if is_signature(header) else "other"


def functions(path):
    original = open(path, encoding="utf-8").read()
    text = blank_literals(original)
    lines = text.split("\n")
    found = []
    header, header_line = "", None
    stack = []  # kinds of the open end-of-line scopes
    skip_depth = 0  # braces inside a function or an 'other' scope

    def reset():
        nonlocal header, header_line
        header, header_line = "", None

    for ln, line in enumerate(lines, start=1):
        if line.lstrip().startswith("#"):
            continue
        i = 0
        while i < len(line):
            c = line[i]
            if skip_depth:
                if c == "{":
                    skip_depth += 1
                elif c == "}":
                    skip_depth -= 1
                    if skip_depth == 0:
                        kind, start, brace = stack.pop()
                        if kind == "function":
                            found.append((start, ln, brace))
                        reset()
                i += 1
                continue
            if c == "{":
                rest = line[i + 1:]
                end_of_line = rest.strip() == ""
                if not end_of_line:  # closed on this line? then it is text of the header
                    depth, j = 1, i + 1
                    while j < len(line) and depth:
                        depth += line[j] == "{"
                        depth -= line[j] == "}"
                        j += 1
                    if depth == 0:
                        if scope_kind(header) == "function":
                            found.append((header_line or ln, ln, ln))
                            reset()
                        else:
                            header += line[i:j]
                        i = j
                        continue
                kind = scope_kind(header)
                start = header_line or ln
                if kind == "scope":
                    stack.append((kind, start, ln))
                else:
                    stack.append((kind, start, ln))
                    skip_depth = 1
                reset()
            elif c == "}":
                if stack and stack[-1][0] == "scope":
                    stack.pop()
                reset()
            elif c == ";":
                reset()
            else:
                if not c.isspace() and header_line is None:
                    header_line = ln
                header += c
                if c == ":" and header.strip() in ("public:", "private:", "protected:"):
                    reset()
            i += 1
        header += "\n"
    signatures = original.split("\n")
    return [(signatures[s - 1].strip(), s, e - s + 1, e - b - 1) for s, e, b in found]


def main(argv):
    limit = int(argv[1])
    run_limit = None
    files = []
    args = argv[2:]
    while args:
        a = args.pop(0)
        if a == "--run-limit":
            run_limit = int(args.pop(0))
        else:
            files.append(a)
    bad = 0
    count = 0
    for f in files:
        for sig, start, length, body in functions(f):
            count += 1
            if length > limit:
                print(f"{f}:{start}: {length} lines (limit {limit}): {sig}")
                bad += 1
            if run_limit is not None and "::run(" in sig and body > run_limit:
                print(f"{f}:{start}: run() body has {body} lines (limit {run_limit}): {sig}")
                bad += 1
    print(f"{count} functions in {len(files)} files, {bad} over the limits")
    if count == 0:
        print("no function found: the pattern no longer matches the sources")
        return 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
