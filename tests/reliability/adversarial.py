#!/usr/bin/env python3
"""Inputs, neighbours and faults that must not corrupt a result: one test per case.

  adversarial.py CHOC WORKDIR CASE

Every case runs choc in a sandbox (WORKDIR/CASE/s/a/b holds the input, the output directory is
WORKDIR/CASE/s/a/b/out) and asserts, besides what the case is about:
- the exit code, and for a failure exactly one line on stderr that matches the case's message
  (never an internal error);
- no file outside the output directory was created, changed or removed (the whole sandbox
  WORKDIR/CASE/s is compared before and after, and the absolute paths a case aims at);
- no file of the output directory with a complete result's name holds a partial or foreign
  result (a refused run leaves the directory as it was; a failed one leaves *.incomplete.*).
The case names follow the table of the reliability work in docs/user-guide/errors.md.
"""
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
INPUTS = os.path.join(HERE, "inputs")


class Failure(Exception):
    pass


def check(cond, msg):
    if not cond:
        raise Failure(msg)


# --- the sandbox -----------------------------------------------------------------------------

class Sandbox:
    def __init__(self, workdir, case):
        self.top = os.path.join(workdir, case)
        shutil.rmtree(self.top, ignore_errors=True)
        self.root = os.path.join(self.top, "s")
        self.dir = os.path.join(self.root, "a", "b")
        self.out = os.path.join(self.dir, "out")
        os.makedirs(self.dir)
        with open(os.path.join(self.root, "a", "keep.txt"), "w") as f:
            f.write("a file of the user's, beside the run\n")

    def path(self, *parts):
        return os.path.join(self.dir, *parts)

    def snapshot(self, skip_out=True):
        """Every file and directory under the sandbox: path -> (kind, size, mtime, digest)."""
        state = {}
        for base, dirs, files in os.walk(self.root):
            if skip_out and os.path.abspath(base).startswith(os.path.abspath(self.out)):
                continue
            for d in dirs:
                p = os.path.join(base, d)
                if skip_out and os.path.abspath(p) == os.path.abspath(self.out):
                    continue
                state[p] = ("dir",)
            for f in files:
                p = os.path.join(base, f)
                st = os.lstat(p)
                with open(p, "rb") as fh:
                    digest = hashlib.sha256(fh.read()).hexdigest()
                state[p] = ("file", st.st_size, st.st_mtime_ns, digest)
        return state

    def out_snapshot(self):
        return {k: v for k, v in self.snapshot(skip_out=False).items()
                if os.path.abspath(k).startswith(os.path.abspath(self.out) + os.sep)}


def unchanged(before, after, what="outside the output directory"):
    added = sorted(set(after) - set(before))
    removed = sorted(set(before) - set(after))
    changed = sorted(p for p in set(before) & set(after) if before[p] != after[p])
    check(not (added or removed or changed),
          "files %s changed: added %s, removed %s, changed %s" % (what, added, removed, changed))


# --- inputs ------------------------------------------------------------------------------------

def deck(src, dst, edit=None):
    """Copies an input, its mesh path made absolute, after edit(root) changed its tree."""
    tree = ET.parse(src)
    root = tree.getroot()
    mesh = find(root, "Mesh/File")
    mesh.set("value", os.path.normpath(os.path.join(os.path.dirname(src), mesh.get("value"))))
    if edit:
        edit(root)
    tree.write(dst)
    return dst


def find(root, path):
    node = root
    for name in path.split("/"):
        nxt = [c for c in node if c.get("name") == name]
        check(nxt, "deck: no '%s' in '%s'" % (name, path))
        node = nxt[0]
    return node


def set_value(root, path, value, type_=None):
    parent, _, key = path.rpartition("/")
    node = find(root, parent) if parent else root
    for c in node:
        if c.get("name") == key:
            c.set("value", str(value))
            return
    ET.SubElement(node, "Parameter", {"name": key, "type": type_ or "string", "value": str(value)})


def rename(root, path, new):
    find(root, path).set("name", new)


def remove_checks(root, analysis):
    a = find(root, "Analyses/" + analysis)
    for c in list(a):
        if c.get("name") == "Checks":
            a.remove(c)


def sdnl111a(box, edit=None):
    return deck(os.path.join(ROOT, "input", "sdnl111a.xml"), box.path("input.xml"), edit)


# --- running -----------------------------------------------------------------------------------

def choc_cmd(choc, *args):
    return [choc] + list(args)


def run(cmd, cwd, env=None, timeout=300, preexec=None):
    e = dict(os.environ)
    e.pop("CHOC_TEST_SIGNAL_AT_STEP", None)
    e.update(env or {})
    p = subprocess.run(cmd, cwd=cwd, env=e, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True, timeout=timeout, preexec_fn=preexec)
    return p.returncode, p.stdout, p.stderr


def expect_error(rc, err, code, pattern):
    check(rc == code, "exit %s, expected %s; stderr: %s" % (rc, code, err))
    check(err.endswith("\n") and err.count("\n") == 1, "stderr is not one line: %r" % err)
    check("internal error" not in err, "an internal error: %s" % err)
    check(re.search(pattern, err), "stderr does not match %r: %s" % (pattern, err))


def refused(box, choc, args, code, pattern, also_check=True, env=None):
    """`choc run` (and `choc check`) refuse; nothing inside or outside the output directory
    changes."""
    before, out_before = box.snapshot(), box.out_snapshot()
    if also_check:
        rc, _, err = run(choc_cmd(choc, "check", box.path("input.xml")), box.dir, env)
        expect_error(rc, err, code, pattern)
    rc, out, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out) + args, box.dir, env)
    expect_error(rc, err, code, pattern)
    unchanged(before, box.snapshot())
    unchanged(out_before, box.out_snapshot(), "in the output directory")
    return out, err


# --- cases: names that would be paths ------------------------------------------------------------

NAME_RULE = r"use 1 to 32 characters among letters, digits"


def case_name_parent_escape(choc, box):
    sdnl111a(box, lambda r: rename(r, "Analyses/plans_z", "../../escape"))
    refused(box, choc, [], 1, r"parameter 'Analyses' = '\.\./\.\./escape': the name contains '/'.*" + NAME_RULE)
    check(not os.path.exists(os.path.join(box.root, "a", "escape.exo")), "wrote outside")


def case_name_absolute(choc, box):
    target = "/tmp/choc-adversarial-%d" % os.getpid()
    sdnl111a(box, lambda r: rename(r, "Analyses/plans_z", target))
    refused(box, choc, [], 1, r"parameter 'Analyses' = '/tmp/choc-adversarial-[0-9]+': the name contains '/'")
    check(not any(p.startswith(target) for p in os.listdir("/tmp")), "wrote under /tmp")


def case_name_nul_character(choc, box):
    sdnl111a(box)
    text = open(box.path("input.xml")).read().replace('name="plans_z"', 'name="plans&#0;z"')
    open(box.path("input.xml"), "w").write(text)
    refused(box, choc, [], 1, r"(input error: .*input\.xml: )(malformed XML|parameter 'Analyses')")


def case_name_too_long(choc, box):
    sdnl111a(box, lambda r: rename(r, "Analyses/plans_z", "z" * 300))
    refused(box, choc, [], 1, r"parameter 'Analyses' = 'z+\.\.\.': the name is 300 characters long")


def case_pair_name_with_slash(choc, box):
    deck(os.path.join(ROOT, "input", "sdnv100.xml"), box.path("input.xml"),
         lambda r: rename(r, "Analyses/a_penalty/Contact/Pairs/wall", "wall/../../x"))
    refused(box, choc, [], 1, r"parameter 'Analyses/a_penalty/Contact/Pairs' = 'wall/\.\./\.\./x': the name contains '/'")


def case_history_column_twice(choc, box):
    sdnl111a(box, lambda r: set_value(r, "Analyses/plans_z/History", "A:DX A:DX"))
    refused(box, choc, [], 1, r"parameter 'Analyses/plans_z/History' = 'A:DX': is given twice")


# --- cases: runs that would never end or fill the disk ---------------------------------------------

def case_tiny_time_step(choc, box):
    sdnl111a(box, lambda r: (set_value(r, "Analyses/plans_z/Time Step", "1e-25"), remove_checks(r, "plans_z")))
    refused(box, choc, [], 1, r"parameter 'Analyses/plans_z/Time Step' = '1e-25': the run would take "
                              r"1\.02e\+22 steps, more than 'Maximum Steps' = 1e\+08.*raise 'Analyses/plans_z/Maximum Steps'")


def case_endless_run(choc, box):
    sdnl111a(box, lambda r: (set_value(r, "Analyses/plans_z/Time Step", "1.02e-15"), remove_checks(r, "plans_z")))
    refused(box, choc, [], 1, r"'Analyses/plans_z/Time Step' = '1\.02e-15': the run would take 1e\+12 steps")


def case_output_too_large(choc, box):
    # 1e7 steps of 1e-10 s, every state in Exodus: under 'Maximum Steps', far over 20 GB.
    def edit(r):
        set_value(r, "Analyses/plans_z/Time Step", "1.02e-10")
        set_value(r, "Analyses/plans_z/Exodus Interval", "1", "int")
        remove_checks(r, "plans_z")
    sdnl111a(box, edit)
    refused(box, choc, [], 1, r"parameter 'Analyses/plans_z/Maximum Output Size' = '20': the history "
                              r"\(1e\+07 rows of [0-9]+ columns\) and the Exodus file \(every 1 steps\) would take about [0-9.]+ GB")


# --- cases: input files that attack the reader ------------------------------------------------------

def case_deep_nesting(choc, box):
    n = 10000
    with open(box.path("input.xml"), "w") as f:
        f.write('<ParameterList name="x">' + '<ParameterList name="a">' * n + "</ParameterList>" * (n + 1))
    refused(box, choc, [], 1, r"input\.xml: nests lists more than 64 levels deep")


def case_huge_input(choc, box):
    sdnl111a(box)
    text = open(box.path("input.xml")).read()
    with open(box.path("input.xml"), "w") as f:
        f.write(text.replace("</ParameterList>\n", "</ParameterList>\n" + "<!--" + "x" * (17 << 20) + "-->\n", 1))
    refused(box, choc, [], 1, r"input\.xml: is 17 MiB, more than the 16 MiB an input may take")


def case_hexadecimal_number(choc, box):
    sdnl111a(box, lambda r: set_value(r, "Analyses/plans_z/Time Step", "0x10"))
    refused(box, choc, [], 1, r"parameter 'Analyses/plans_z/Time Step' = '0x10': is not a number")


def case_byte_order_mark(choc, box):
    sdnl111a(box)
    data = open(box.path("input.xml"), "rb").read()
    open(box.path("input.xml"), "wb").write(b"\xef\xbb\xbf" + data)
    rc, out, err = run(choc_cmd(choc, "check", box.path("input.xml")), box.dir)
    check(rc == 0 and err == "", "a UTF-8 byte order mark: exit %s, stderr %r" % (rc, err))


# --- cases: the output directory and its files ---------------------------------------------------------

def case_result_file_is_a_directory(choc, box):
    sdnl111a(box)
    os.makedirs(os.path.join(box.out, "plans_z.history.csv"))
    refused(box, choc, [], 1, r"cannot remove .*out/plans_z\.history\.csv: Is a directory", also_check=False)


def case_checks_csv_is_a_directory(choc, box):
    sdnl111a(box)
    os.makedirs(os.path.join(box.out, "checks.csv"))
    refused(box, choc, [], 1, r"cannot remove .*out/checks\.csv: Is a directory", also_check=False)


def case_read_only_output_directory(choc, box):
    sdnl111a(box)
    os.makedirs(box.out)
    os.chmod(box.out, 0o555)
    os.chmod(box.top, 0o755)
    for d in (box.root, os.path.join(box.root, "a"), box.dir):
        os.chmod(d, 0o755)
    args = ["run", box.path("input.xml"), "-o", box.out]
    before = box.snapshot(skip_out=False)
    if os.geteuid() == 0:  # root writes anywhere: run as nobody, as a user would be
        cmd = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", choc] + args
        env = {"OMPI_ALLOW_RUN_AS_ROOT": "", "HOME": "/tmp"}
    else:
        cmd, env = [choc] + args, {}
    rc, out, err = run(cmd, "/tmp", env)
    expect_error(rc, err, 1, r"output directory '.*out' is not writable \(Permission denied\)")
    unchanged(before, box.snapshot(skip_out=False), "in the sandbox")


def case_run_help(choc, box):
    rc, out, err = run(choc_cmd(choc, "run", "--help"), box.dir)
    check(rc == 0, "choc run --help: exit %s" % rc)
    for option in ("-o, --output DIR", "--restart FILE.checkpoint", "--help"):
        check(option in out, "choc run --help does not list %s:\n%s" % (option, out))


def case_history_node_set_of_several_nodes(choc, box):
    def edit(r):
        history = find(r, "Analyses/a_penalty/History")
        history.set("value", history.get("value") + " FACEINF:DZ")
    deck(os.path.join(ROOT, "input", "sdnv100.xml"), box.path("input.xml"), edit)
    rc, out, err = run(choc_cmd(choc, "check", box.path("input.xml")), box.dir)
    check(rc == 0, "check: exit %s: %s" % (rc, err))
    check(re.search(r"history: node set 'FACEINF' has [0-9]+ nodes; its columns record its first node, [0-9]+ at \(", out),
          "choc check does not say which node of FACEINF the history records")


# --- cases: restart ------------------------------------------------------------------------------------

def stopped_run(choc, box, step=300):
    sdnl111a(box)
    rc, _, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out), box.dir,
                     {"CHOC_TEST_SIGNAL_AT_STEP": "plans_z:%d" % step})
    expect_error(rc, err, 143, r"interrupted: SIGTERM received: modal transient 'plans_z' stopped at t = ")
    return os.path.join(box.out, "plans_z.checkpoint")


def case_refused_restart_writes_nothing(choc, box):
    checkpoint = stopped_run(choc, box)
    os.remove(os.path.join(box.out, "plans_z.incomplete.exo"))
    refused(box, choc, ["--restart", checkpoint], 1,
            r"plans_z\.exo\.part: cannot continue the results of the checkpointed run: no such file", also_check=False)


def case_restart_leaves_no_stale_incomplete(choc, box):
    checkpoint = stopped_run(choc, box)
    check(os.path.exists(os.path.join(box.out, "plans_z.impacts.incomplete.csv")), "no incomplete impacts to continue")
    before = box.snapshot()
    rc, out, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out, "--restart", checkpoint), box.dir)
    check(rc == 0, "restart: exit %s: %s" % (rc, err))
    stale = [f for f in os.listdir(box.out) if ".incomplete" in f or f.endswith(".part")]
    check(not stale, "stale partial files after a successful restart: %s" % stale)
    unchanged(before, box.snapshot())


def case_restart_given_a_directory(choc, box):
    sdnl111a(box)
    os.makedirs(box.out)
    refused(box, choc, ["--restart", box.out], 1, r"out: option '--restart': is not a file", also_check=False)


# --- cases: resources and signals ---------------------------------------------------------------------

def case_out_of_memory(choc, box):
    mesh = box.path("bars.exo")
    rc, _, err = run(choc_cmd(choc, "mesh", "--dim", "3", "--axis", "z", "--along1", "300", "--along2", "300",
                              "--across1", "8", "--across2", "8", "-o", mesh), box.dir)
    check(rc == 0, "choc mesh: %s" % err)

    def edit(r):
        find(r, "Mesh/File").set("value", mesh)
        model = find(r, "Model")
        model.remove(find(r, "Model/Active Components"))
        set_value(r, "Model/Dirichlet/clamped face of bar 2/Components", "DX DY DZ")
        an = find(r, "Analyses")
        for a in list(an):
            if a.get("name") != "c1_modified":
                an.remove(a)
        set_value(r, "Analyses/c1_modified/End Time", "3e-6")
        remove_checks(r, "c1_modified")
    deck(os.path.join(ROOT, "input", "sdnl111c.xml"), box.path("input.xml"), edit)
    before = box.snapshot()
    limit = 1000 * 1024 * 1024  # the factorisation needs about 1.8 GB

    def preexec():
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    rc, out, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out), box.dir, preexec=preexec)
    expect_error(rc, err, 2, r"^choc: out of memory: .*(allocation of [0-9.]+ [KMG]?i?B|[0-9.]+ [KMG]iB \(an estimate of its factors\))")
    unchanged(before, box.snapshot())
    complete = [f for f in os.listdir(box.out) if f.startswith("c1_modified") and ".incomplete" not in f
                and not f.endswith(".summary.json")]
    check(not complete, "complete-named results of a failed run: %s" % complete)
    stopped_summary(box, "c1_modified", "failed", 2)


def stopped_summary(box, analysis, status, code):
    """A stopped analysis still reports itself: its summary says how it ended."""
    path = os.path.join(box.out, analysis + ".summary.json")
    check(os.path.exists(path), "no %s written by the stopped analysis" % os.path.basename(path))
    summary = json.load(open(path))
    check(summary.get("status") == status and summary.get("exit_code") == code,
          "%s: status %r, exit code %r; expected %r, %r" % (path, summary.get("status"), summary.get("exit_code"),
                                                           status, code))


def long_transient(box):
    return deck(os.path.join(INPUTS, "long_transient.xml"), box.path("input.xml"))


def interrupted_by_timeout(choc, box, seconds):
    """`timeout -s TERM` signals the child, then its process group: two SIGTERMs."""
    shutil.rmtree(box.out, ignore_errors=True)
    rc, out, err = run(["timeout", "--preserve-status", "-s", "TERM", "%.2f" % seconds, choc, "run",
                        box.path("input.xml"), "-o", box.out], box.dir, timeout=120)
    expect_error(rc, err, 143, r"^choc: interrupted: SIGTERM received: ")
    m = re.search(r"modal transient 'long' stopped at t = ([0-9.e+-]+) s.*continue it with --restart (\S+)$", err)
    if m:
        check(os.path.exists(m.group(2)), "the message names a checkpoint that is not there: %s" % m.group(2))
    else:
        check(re.search(r"run stopped before (analysis '[a-z]+'|the first analysis \(during the set-up\))", err),
              "neither a transient stopped with its checkpoint nor a stop before an analysis: %s" % err)
    complete = [f for f in os.listdir(box.out) if f.startswith("long.") and ".incomplete" not in f
                and not f.endswith((".checkpoint", ".summary.json"))] if os.path.isdir(box.out) else []
    check(not complete, "complete-named results of an interrupted run: %s" % complete)
    if m:
        stopped_summary(box, "long", "interrupted", 143)
    return bool(m)


def case_timeout_sigterm(choc, box):
    long_transient(box)
    before = box.snapshot()
    # Two SIGTERMs back to back inside the transient (what `timeout` and `mpirun` send): the
    # same clean stop as one, with its checkpoint.
    p = subprocess.Popen([choc, "run", box.path("input.xml"), "-o", box.out], cwd=box.dir,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    part = os.path.join(box.out, "long.history.csv.part")
    start = time.time()
    while not os.path.exists(part) and p.poll() is None and time.time() - start < 60:
        time.sleep(0.02)
    time.sleep(0.3)
    p.send_signal(signal.SIGTERM)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=60)
    expect_error(p.returncode, err, 143, r"^choc: interrupted: SIGTERM received: modal transient 'long' stopped at t = ")
    check(os.path.exists(os.path.join(box.out, "long.checkpoint")), "no checkpoint after two SIGTERMs")
    stopped = 0
    for i in range(10):  # the set-up, the eigen-solve and the transient: 0.3 s to 2.4 s
        stopped += interrupted_by_timeout(choc, box, 0.3 + 0.23 * i)
    check(stopped >= 5, "only %d of 10 runs were stopped inside the transient" % stopped)
    unchanged(before, box.snapshot())


def case_sigterm_during_setup(choc, box):
    """While the libraries load, MPI starts, the mesh is read and the modes are computed (the
    first few tenths of a second of SDNL111 B): a clean stop with its message, never the
    signal's default action."""
    deck(os.path.join(ROOT, "input", "sdnl111b.xml"), box.path("input.xml"))
    before = box.snapshot()
    stopped = 0
    for delay in (0.02, 0.1, 0.25, 0.5):
        shutil.rmtree(box.out, ignore_errors=True)
        p = subprocess.Popen([choc, "run", box.path("input.xml"), "-o", box.out], cwd=box.dir,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(delay)
        p.send_signal(signal.SIGTERM)
        out, err = p.communicate(timeout=60)
        if p.returncode == 0:
            continue  # it finished first: nothing was stopped
        expect_error(p.returncode, err, 143, r"^choc: interrupted: SIGTERM received: ")
        stopped += 1
    check(stopped >= 3, "only %d of 4 runs were stopped" % stopped)
    unchanged(before, box.snapshot())


# --- cases: two runs, one directory ----------------------------------------------------------------

def case_two_runs_one_directory(choc, box):
    """Two runs of different inputs started together into one directory: exactly one runs, the
    other is refused at once (exit 1, naming the directory and the holder's pid) and writes
    nothing; the survivor's results equal a lone run's bit for bit."""
    # Long enough (about 2 s each) for the two to overlap whatever MPI's start-up takes.
    source = os.path.join(INPUTS, "long_transient.xml")
    deck(source, box.path("input.xml"), lambda r: set_value(r, "Analyses/long/End Time", "8"))
    deck(source, box.path("other.xml"), lambda r: (set_value(r, "Analyses/long/End Time", "8"),
                                                   set_value(r, "Analyses/long/Modal Damping", "0.002")))
    inputs = {"input.xml": box.path("input.xml"), "other.xml": box.path("other.xml")}
    for name, path in inputs.items():
        rc, _, err = run(choc_cmd(choc, "run", path, "-o", box.path("lone-" + name)), box.dir)
        check(rc == 0, "lone run of %s: exit %s: %s" % (name, rc, err))
    compare = os.path.join(ROOT, "tools", "oracles", "compare_results.py")
    for attempt in range(3):
        shutil.rmtree(box.out, ignore_errors=True)
        procs = {name: subprocess.Popen([choc, "run", path, "-o", box.out], cwd=box.dir, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True) for name, path in inputs.items()}
        ends = {name: p.communicate(timeout=120) + (p.returncode,) for name, p in procs.items()}
        codes = sorted(e[2] for e in ends.values())
        check(codes == [0, 1], "exit codes %s, expected one run (0) and one refusal (1); stderr: %s" % (
            codes, [e[1] for e in ends.values()]))
        winner = [n for n, e in ends.items() if e[2] == 0][0]
        loser = [n for n, e in ends.items() if e[2] == 1][0]
        expect_error(1, ends[loser][1], 1, r"^choc: input error: choc run: output directory '.*out' is in use by "
                                           r"another choc run \(pid [0-9]+\); wait for it to end, or give another directory")
        rc, out, err = run([sys.executable, compare, box.path("lone-" + winner), box.out], box.dir)
        check(rc == 0, "the survivor (%s) differs from its lone run:\n%s%s" % (winner, out, err))
        check(not os.path.exists(os.path.join(box.out, ".choc.lock")), "the lock file outlived the run")


# --- cases: a disk that fills up ----------------------------------------------------------------------

def sdnl111c_with_checkpoints(box):
    def edit(r):
        an = find(r, "Analyses")
        for a in list(an):
            if a.get("name") != "c1_modified":
                an.remove(a)
        ck = ET.SubElement(find(r, "Analyses/c1_modified"), "ParameterList", {"name": "Checkpoint"})
        ET.SubElement(ck, "Parameter", {"name": "Interval Steps", "type": "int", "value": "100"})
    return deck(os.path.join(ROOT, "input", "sdnl111c.xml"), box.path("input.xml"), edit)


def parse_history(path):
    """Every row whole: as many fields as the header, each a finite number, times increasing."""
    lines = open(path).read().split("\n")
    check(lines[-1] == "", "%s does not end with a whole row" % path)
    header = lines[0].split(",")
    times = []
    for k, line in enumerate(lines[1:-1], start=2):
        fields = line.split(",")
        check(len(fields) == len(header), "%s:%d: %d fields, the header has %d" % (path, k, len(fields), len(header)))
        values = [float(f) for f in fields]
        check(all(v == v and abs(v) != float("inf") for v in values), "%s:%d: not finite" % (path, k))
        times.append(values[0])
    check(all(b > a for a, b in zip(times, times[1:])), "%s: times do not increase" % path)
    return len(times)


def disk_full(choc, box, trigger, after):
    library = os.environ.get("CHOC_DISK_FULL_LIBRARY", "")
    check(os.path.exists(library), "CHOC_DISK_FULL_LIBRARY is not the fault library: %r" % library)
    sdnl111c_with_checkpoints(box)
    reference = box.path("reference")
    rc, _, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", reference), box.dir)
    check(rc == 0, "reference run: exit %s: %s" % (rc, err))
    before = box.snapshot()
    env = {"LD_PRELOAD": library, "CHOC_DISK_FULL_DIR": os.path.abspath(box.out) + "/",
           "CHOC_DISK_FULL_TRIGGER": trigger, "CHOC_DISK_FULL_AFTER": str(after)}
    rc, out, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out), box.dir, env)
    expect_error(rc, err, 2, r"^choc: output failure: .*(No space left on device|disk full)")
    unchanged(before, box.snapshot())
    files = os.listdir(box.out)
    complete = [f for f in files if f in ("c1_modified.exo", "c1_modified.history.csv", "checks.csv")]
    check(not complete, "complete-named results after a full disk: %s" % complete)
    rows = parse_history(os.path.join(box.out, "c1_modified.history.incomplete.csv"))
    check(0 < rows < 1001, "the incomplete history has %d rows" % rows)
    checkpoint = os.path.join(box.out, "c1_modified.checkpoint")
    check(os.path.exists(checkpoint), "no checkpoint left to continue from")
    rc, _, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out, "--restart", checkpoint), box.dir)
    check(rc == 0, "restart after the disk was freed: exit %s: %s" % (rc, err))
    compare = os.path.join(ROOT, "tools", "oracles", "compare_results.py")
    rc, out, err = run([sys.executable, compare, reference, box.out, "--names", "c1_modified"], box.dir)
    check(rc == 0, "the continued run differs from the uninterrupted one:\n%s%s" % (out, err))


def case_disk_full_during_exodus_write(choc, box):
    disk_full(choc, box, ".exo.part", 2500000)  # about half of the Exodus file


def case_disk_full_during_history_write(choc, box):
    disk_full(choc, box, ".history.csv.part", 150000)  # about half of the history


# --- cases: meshes ---------------------------------------------------------------------------------------

def case_coincident_unshared_nodes(choc, box):
    for f in ("two_boxes.msh",):
        shutil.copy(os.path.join(INPUTS, f), box.path(f))
    shutil.copy(os.path.join(INPUTS, "two_boxes.xml"), box.path("input.xml"))
    rc, out, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out), box.dir)
    check(rc == 0, "exit %s: %s" % (rc, err))
    m = re.search(r"choc: warning: .*mesh 'two_boxes\.msh': 9 node\(s\) lie within [0-9.e+-]+ m of a node of other "
                  r"elements they are not shared with \(first: nodes [0-9]+ and [0-9]+ at \(([-0-9.e+, ]+)\)\).*"
                  r"'Mesh/Merge Coincident Nodes' = true", out)
    check(m, "no warning about the 9 coincident nodes:\n" + out)
    z = float(m.group(1).split(",")[2])
    check(abs(z - 0.01) < 1e-12, "the first pair is not on the cubes' common face: z = %g" % z)
    free = last_value(os.path.join(box.out, "drop.history.csv"), "top:DZ")
    check(abs(free + 1e-4) < 1e-9, "unconnected, the upper cube falls freely: DZ = %g, expected -1e-4" % free)
    # Merged: one body; 9 nodes fewer carry unknowns, and the upper cube rings on the lower one
    # with an amplitude of the order of v L / c = 1 m/s x 0.02 m / 5000 m/s = 4e-6 m.
    text = open(box.path("input.xml")).read().replace(
        '<Parameter name="File" type="string" value="two_boxes.msh"/>',
        '<Parameter name="File" type="string" value="two_boxes.msh"/>\n'
        '    <Parameter name="Merge Coincident Nodes" type="bool" value="true"/>')
    open(box.path("merged.xml"), "w").write(text)
    rc, out2, err = run(choc_cmd(choc, "run", box.path("merged.xml"), "-o", box.path("merged")), box.dir)
    check(rc == 0, "merged: exit %s: %s" % (rc, err))
    unknowns = [int(x) for x in re.findall(r"model: .* ([0-9]+) unknowns on", out + out2)]
    check(unknowns == [135, 108], "unknowns unmerged and merged: %s, expected 135 and 108" % unknowns)
    peak = max(abs(v) for v in column(os.path.join(box.path("merged"), "drop.history.csv"), "top:DZ"))
    check(peak < 1e-5, "merged, the upper cube still moves by %g m (free: 1e-4)" % peak)


def column(path, name):
    rows = [line.rstrip("\n").split(",") for line in open(path)]
    j = rows[0].index(name)
    return [float(r[j]) for r in rows[1:]]


def last_value(path, name):
    return column(path, name)[-1]


CASES = {name[len("case_"):]: fn for name, fn in globals().items() if name.startswith("case_")}


def run_cases(cases, script):
    """The command line of a case script: --list, or CHOC WORKDIR CASE (exit 0 when it passes)."""
    if sys.argv[1:] == ["--list"]:
        print(";".join(sorted(cases)))
        return 0
    if len(sys.argv) != 4 or sys.argv[3] not in cases:
        print("usage: %s CHOC WORKDIR CASE; cases: %s" % (script, " ".join(sorted(cases))))
        return 2
    choc, workdir, case = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
    box = Sandbox(workdir, case)
    try:
        cases[case](choc, box)
    except Failure as e:
        print("FAIL: %s: %s" % (case, e))
        return 1
    print("%s: OK" % case)
    return 0


if __name__ == "__main__":
    sys.exit(run_cases(CASES, "adversarial.py"))
