#!/usr/bin/env python3
"""The user guide lists every file an analysis writes: each '<name>.<suffix>' that
`choc run --help` prints (from the one list in src/output/OutputDirectory.cpp) must have a row
'`<analysis>.<suffix>`' in docs/user-guide/running.md.

  check_output_files_listed.py CHOC RUNNING_MD
"""
import re
import subprocess
import sys


def main():
    choc, page = sys.argv[1:3]
    help_text = subprocess.run([choc, "run", "--help"], capture_output=True, text=True, check=True).stdout
    suffixes = re.findall(r"^  <name>(\.\S+)", help_text, re.M)
    if len(suffixes) < 5:
        sys.exit("choc run --help lists %d output files: %r" % (len(suffixes), suffixes))
    text = open(page).read()
    missing = [s for s in suffixes if "`<analysis>%s`" % s not in text]
    if missing:
        sys.exit("%s has no row for: %s (choc run --help lists them)" % (page, ", ".join(missing)))
    print("every output file is listed: " + " ".join(suffixes))


if __name__ == "__main__":
    main()
