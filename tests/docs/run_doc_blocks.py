#!/usr/bin/python3
"""Runs the ```sh blocks of documentation pages, as a reader would from the repository root.

usage: run_doc_blocks.py CHOC PAGE.md... [--root DIR] [--timeout S] [--keep | --discard]

Each page's ```sh blocks run in order, in one fresh `bash -euo pipefail` per page, from the
repository root, with `build/choc` replaced by CHOC. Every `/tmp` path of the commands is
rewritten into a private directory of the page's run (which is also its HOME and TMPDIR), so
that pages run in parallel do not collide and nothing is left in /tmp; the directory is
removed after a success and kept after a failure (always kept with --keep, always removed
with --discard).

Fails (exit 1) naming the page, the failing block's line and first line, the command and its
output. Blocks marked ```text or ```console are not run.
"""
import argparse
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

MARK = "@@choc-doc-block"
FAILED = "@@choc-doc-failed"
# `build/choc` as a command word (not inside another path).
CHOC_RE = re.compile(r"(?<![\w./-])build/choc(?![\w./-])")
# `/tmp` as the start of a path (not /var/tmp, not /tmpfoo).
TMP_RE = re.compile(r"(?<![\w./-])/tmp(?=/|\s|$|[\"';)])")


def sh_blocks(path):
    """[(line of the opening fence, [lines])] of the ```sh blocks of a markdown file."""
    blocks, current, start = [], None, 0
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            stripped = line.rstrip("\n")
            if current is None:
                if stripped.rstrip() == "```sh":
                    current, start = [], number
            elif stripped.startswith("```"):
                blocks.append((start, current))
                current = None
            else:
                current.append(stripped)
    if current is not None:
        raise SystemExit(f"{path}:{start}: the ```sh block is never closed")
    return blocks


def rewrite(line, choc, private_tmp):
    # /tmp first: CHOC itself may lie under /tmp (a checkout there) and must stay as it is.
    line = TMP_RE.sub(lambda m: private_tmp, line)
    return CHOC_RE.sub(lambda m: shlex.quote(choc), line)


def script_for(blocks, choc, private_tmp):
    """One bash script: a marker line before each block, the failing command on an error."""
    out = [f"trap 'printf \"%s %s\\n\" {FAILED} \"$BASH_COMMAND\" >&2' ERR"]
    for index, (_, lines) in enumerate(blocks):
        out.append(f"printf '\\n%s %d\\n' {MARK} {index}")
        out.extend(rewrite(line, choc, private_tmp) for line in lines)
    return "\n".join(out) + "\n"


def split_output(text, count):
    """The output of each block (the text after its marker), and the failing command."""
    outputs, current, failed = [""] * count, None, ""
    for line in text.splitlines(keepends=True):
        if line.startswith(MARK + " "):
            if current is not None and re.search(r"(^|\n)\n$", outputs[current]):
                outputs[current] = outputs[current][:-1]  # the marker's leading line break
            current = int(line.split()[1])
            continue
        if line.startswith(FAILED + " "):
            failed = line[len(FAILED) + 1:].rstrip("\n")
            continue
        if current is not None:
            outputs[current] += line
        elif line.strip():
            outputs[0] += line
    return outputs, current, failed


def run_bash(script, root, env, timeout):
    """(exit code or None on a timeout, output) of the script in its own process group."""
    proc = subprocess.Popen(["bash", "-euo", "pipefail", "-c", script], cwd=root, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            errors="replace", start_new_session=True)
    try:
        text, _ = proc.communicate(timeout=timeout)
        return proc.returncode, text
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)  # bash and every command it started
        text, _ = proc.communicate()
        return None, text


def run_page(page, choc, root, keep, discard, timeout):
    blocks = sh_blocks(page)
    name = os.path.relpath(page, root)
    if not blocks:
        print(f"{name}: no ```sh block")
        return True
    private = tempfile.mkdtemp(prefix="choc-doc-")
    private_tmp = os.path.join(private, "tmp")
    home = os.path.join(private, "home")
    os.makedirs(private_tmp)
    os.makedirs(home)
    env = dict(os.environ, HOME=home, TMPDIR=private_tmp)
    script = script_for(blocks, choc, private_tmp)
    started = time.monotonic()
    code, text = run_bash(script, root, env, timeout)
    seconds = time.monotonic() - started
    outputs, last, failed = split_output(text, len(blocks))
    ok = code == 0
    if code is None:
        why = f"did not finish within {timeout:g} s (killed)"
    else:
        why = f"exited {code}" + (f" at the command: {failed}" if failed else "")
    report(name, blocks, outputs, ok, last, why, seconds)
    if (ok and not keep) or discard:
        shutil.rmtree(private, ignore_errors=True)
    else:
        print(f"{name}: the page's /tmp was {private_tmp} (kept)")
    return ok


def report(name, blocks, outputs, ok, last, why, seconds):
    for index, (line, lines) in enumerate(blocks):
        if not ok and last is not None and index > last:
            break
        print(f"--- {name}:{line}: {lines[0] if lines else ''}")
        sys.stdout.write(outputs[index])
    if ok:
        print(f"{name}: {len(blocks)} ```sh block(s) passed in {seconds:.1f} s")
        return
    index = last if last is not None else 0
    line, lines = blocks[index]
    first = lines[0] if lines else ""
    print(f"FAILED: {name}: the ```sh block at line {line} ('{first}') {why}; its output:")
    sys.stdout.write(outputs[index] or "(no output)\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("choc", help="the choc executable, in place of build/choc")
    parser.add_argument("pages", nargs="+", help="markdown files")
    parser.add_argument("--root", default=os.path.normpath(
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")),
                        help="the repository root, where the commands run (default: this "
                             "script's ../..)")
    parser.add_argument("--keep", action="store_true", help="keep each page's private /tmp")
    parser.add_argument("--timeout", type=float, default=240,
                        help="seconds a page's commands may take (default 240)")
    parser.add_argument("--discard", action="store_true",
                        help="remove each page's private /tmp even after a failure")
    args = parser.parse_args()
    choc = os.path.abspath(args.choc)
    if not os.access(choc, os.X_OK):
        raise SystemExit(f"run_doc_blocks.py: '{choc}' is not an executable")
    results = [run_page(os.path.abspath(p), choc, args.root, args.keep, args.discard, args.timeout) for p in args.pages]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
