#!/usr/bin/env python3
"""Fails when a file-system call in src/ can throw without being caught and named.

Usage: filesystem_calls.py SRC_DIR
The std::filesystem operations that throw std::filesystem::filesystem_error on failure (an
exit 4, 'internal error', that names nothing) must be called with a std::error_code argument
(its name contains 'ec' or is 'ignored'); path manipulation (std::filesystem::path, its
members) does not touch the disk and is allowed. choc's own wrappers (src/core/Files.hpp)
turn a failure into an input or output error naming the file.
"""
import os
import re
import sys

THROWING = {
    "exists", "is_directory", "is_regular_file", "is_symlink", "file_size", "remove", "remove_all",
    "rename", "create_directory", "create_directories", "copy", "copy_file", "last_write_time",
    "resize_file", "status", "symlink_status", "canonical", "weakly_canonical", "absolute",
    "current_path", "space", "equivalent", "permissions", "read_symlink", "temp_directory_path",
    "directory_iterator", "recursive_directory_iterator", "hard_link_count", "is_empty",
}
CALL = re.compile(r"\b(?:std::filesystem|fs)::(\w+)\s*\(")


def arguments(text, start):
    depth, i = 0, start
    while i < len(text):
        if text[i] == "(":
            depth += 1
        elif text[i] == ")":
            depth -= 1
            if depth == 0:
                return text[start + 1:i]
        i += 1
    return text[start + 1:]


def main():
    src = sys.argv[1]
    bad = []
    for base, _, files in os.walk(src):
        for f in files:
            if not f.endswith((".cpp", ".hpp")):
                continue
            path = os.path.join(base, f)
            text = open(path, encoding="utf-8").read()
            for m in CALL.finditer(text):
                if m.group(1) not in THROWING:
                    continue
                args = arguments(text, m.end() - 1)
                last = args.split(",")[-1].strip() if args.strip() else ""
                if not re.search(r"(\bec\w*|\w*Ec|\bignored)$", last):
                    line = text.count("\n", 0, m.start()) + 1
                    bad.append("%s:%d: std::filesystem::%s(%s) can throw: pass a std::error_code, or use "
                               "src/core/Files.hpp" % (path, line, m.group(1), args.strip()))
    for b in bad:
        print(b)
    print("filesystem_calls: %d call(s) that can throw" % len(bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
