"""The tools' one way to run choc and read what it wrote (benchmarks, studies, reports).

choc's log is for people and may change; tools read the files choc declares instead:
  - <output dir>/<analysis>.summary.json, one per analysis, written when the analysis ends
    (completed or failed): status, cost, steps, iterations, check rows, energy, impacts
    (read_summary, summary_value, exact_errors);
  - <output dir>/<analysis>.history.csv (read_history);
and they edit decks (Teuchos XML parameter lists) through an XML parser, by parameter path
(set_param(deck, "Analyses/c1/Time Step", 1e-6)): a path that does not exist is an error
naming it, never a silent no-op (create=True for keys that may be absent).

    import os, sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
    import chocrun

    deck = chocrun.load_deck(chocrun.input_path("sdnl111c.xml"))   # mesh path made absolute
    chocrun.keep_analyses(deck, ["c1_modified"])
    chocrun.set_param(deck, "Analyses/c1_modified/Time Step", 5e-7)
    run = chocrun.run(choc, chocrun.write_deck(deck, "work/c1.xml"), "work/c1", ranks=2)
    s = chocrun.read_summary(run.out_dir, "c1_modified")
    steps = chocrun.summary_value(s, "steps")
    h = chocrun.read_history(run.out_dir, "c1_modified")      # h["time"], h["N1:DZ"]

Python 3 standard library; numpy for the histories.
"""
import copy
import datetime
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

LIB = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.dirname(LIB)
TOP = os.path.dirname(TOOLS)
# --bind-to none: Open MPI pins rank r to core r for np <= 2; on a machine shared with other
# jobs a pinned rank waits for its core while the other core idles.
# mpi_yield_when_idle: a waiting rank yields its core rather than spinning; two 2-rank runs at
# once on 2 cores otherwise wait a scheduler slice per message (measured 93 s against 4.3 s).
MPIRUN = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none", "--mca", "mpi_yield_when_idle", "1"]
# choc's exit codes (docs/user-guide/errors.md).
EXIT_OK, EXIT_INPUT, EXIT_NUMERICAL, EXIT_CHECK_FAILED = 0, 1, 2, 3


class ChocError(RuntimeError):
    """A choc run that ended with an exit code the caller did not accept."""


class SummaryError(RuntimeError):
    """A summary that is missing, unreadable, or lacks a figure a tool needs."""


class DeckError(KeyError):
    """A deck edit or read whose parameter path does not exist (or is of the wrong kind)."""

    def __str__(self):
        return self.args[0] if self.args else ""


# ------------------------------------------------------------------ test scripts
def save_figure(fig, path, dpi=110):
    """A study's or test's figure: laid out, written to path, its path printed."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    print(f"figure: {path}")


def finish(failures, ok):
    """Ends a test script: its failures (exit 1) or the line `ok` (exit 0)."""
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print(ok)


def ranks_agree(h1, h2, columns, tolerance=1e-8, label="2 ranks against 1"):
    """Compares two histories' columns (the 1-rank and the 2-rank run) to `tolerance` of each
    column's peak in h1, printing each; returns the failures' descriptions."""
    import numpy as np
    failures = []
    for col in columns:
        peak = float(np.max(np.abs(h1[col])))
        diff = float(np.max(np.abs(np.asarray(h2[col]) - np.asarray(h1[col])))) / peak
        print(f"{label}, {col}: {diff:.1e} of the peak (at most {tolerance:g})")
        if not diff <= tolerance:
            failures.append(f"{label}: {col} differs by {diff:.1e} of its peak")
    return failures


# ------------------------------------------------------------------ paths
def tool_dir(role):
    """tools/<role> (build, oracles, bench, study, report, docs, lib)."""
    d = os.path.join(TOOLS, role)
    if not os.path.isdir(d):
        raise FileNotFoundError(f"chocrun: no tools/{role} directory")
    return d


def add_tool_path(*roles):
    """Makes the modules of tools/<role> importable (e.g. add_tool_path("oracles"))."""
    for role in roles:
        d = tool_dir(role)
        if d not in sys.path:
            sys.path.insert(0, d)


def input_path(name):
    return os.path.join(TOP, "input", name)


def choc_path(build):
    """The choc executable of a build directory (an error naming it when absent)."""
    choc = os.path.join(os.path.abspath(build), "choc")
    if not os.access(choc, os.X_OK):
        raise FileNotFoundError(f"chocrun: no choc executable at {choc} (make build, or --build DIR)")
    return choc


def make_scale_mesh(choc, across=None, along=None, out=None, quiet=True):
    """tools/build/make-scale-mesh.sh: the scale scene's bars (defaults: 9 x 500 into
    meshes/scale_3d.exo, kept when up to date). Returns the mesh path."""
    cmd = [os.path.join(TOOLS, "build", "make-scale-mesh.sh"), choc]
    if across is not None:
        cmd += [str(across), str(along)] + ([out] if out else [])
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL if quiet else None)
    return out or os.path.join(TOP, "meshes", "scale_3d.exo")


# ------------------------------------------------------------------ running choc
class Run:
    """One finished choc run: the command, exit code, captured output and the output directory."""

    def __init__(self, cmd, returncode, stdout, stderr, out_dir, wall, cpu, maxrss_mib, load):
        self.cmd, self.returncode, self.stdout, self.stderr = cmd, returncode, stdout, stderr
        self.out_dir, self.wall, self.cpu, self.maxrss_mib, self.load = out_dir, wall, cpu, maxrss_mib, load

    def summary(self, analysis):
        return read_summary(self.out_dir, analysis)

    def summaries(self, analyses=None):
        return read_summaries(self.out_dir, analyses)

    def history(self, analysis):
        return read_history(self.out_dir, analysis)

    def tail(self, n=2000):
        """The end of what the run printed (for error messages shown to people, not parsed)."""
        return (self.stdout[-n:] + self.stderr[-n:]).rstrip()


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def run(choc, deck, out_dir, ranks=1, args=(), ok=(EXIT_OK,), command="run", cwd=None, env=None,
        timeout=None, log=None):
    """Runs `choc <command> DECK -o OUT_DIR [args]`, serially (ranks = 1) or under mpirun, capturing
    stdout and stderr. Returns a Run (exit code, output, output directory, the process's wall
    time, CPU time and peak resident memory from wait4: under mpirun, the CPU of all ranks and
    the largest process's memory). An exit code outside `ok`
    raises ChocError with the end of the output (ok=None accepts any). `log`: a file to which
    stdout and stderr are also written. command="check" runs `choc check DECK` (no -o)."""
    cmd = [choc, command, deck] + (["-o", out_dir] if command == "run" else []) + list(args)
    if ranks > 1:
        cmd = MPIRUN + ["-np", str(ranks)] + cmd
    load = load_average()
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        t0 = time.monotonic()
        proc = subprocess.Popen(cmd, stdout=out, stderr=err, text=True, cwd=cwd,
                                env=None if env is None else dict(os.environ, **env))
        # wait4: the child's own CPU time and peak resident memory (with mpirun, the ranks it
        # reaped are counted in: CPU summed, memory the largest process).
        while True:
            pid, status, ru = os.wait4(proc.pid, os.WNOHANG if timeout else 0)
            if pid:
                break
            if time.monotonic() - t0 > timeout:
                proc.kill()
                os.wait4(proc.pid, 0)
                proc.returncode = -9
                raise subprocess.TimeoutExpired(cmd, timeout)
            time.sleep(0.02)
        wall = time.monotonic() - t0
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        stdout, stderr = out.read(), err.read()
    r = Run(cmd, proc.returncode, stdout, stderr, out_dir, wall, ru.ru_utime + ru.ru_stime,
            ru.ru_maxrss / 1024.0, load)
    if log:
        with open(log, "w") as f:
            f.write(stdout + stderr)
    if ok is not None and proc.returncode not in ok:
        raise ChocError(f"{' '.join(cmd)}: exit {proc.returncode} (accepted: {', '.join(map(str, ok))})"
                        f"\n{r.tail()}")
    return r


def mesh(choc, out, *options):
    """`choc mesh OPTIONS -o OUT` (the generator); returns OUT."""
    subprocess.run([choc, "mesh", *map(str, options), "-o", out], check=True, stdout=subprocess.DEVNULL)
    return out


def gmsh(geo, out, dim, *options):
    """gmsh -DIM OPTIONS GEO -o OUT (format msh41); options as in gmsh ("-setnumber", "n", 5).
    GEO is a name in meshes/ or a path. Returns OUT."""
    if not os.path.isabs(geo) and not os.path.exists(geo):
        geo = os.path.join(TOP, "meshes", geo)
    subprocess.run(["gmsh", f"-{dim}", *map(str, options), "-format", "msh41", geo, "-o", out],
                   check=True, stdout=subprocess.DEVNULL)
    return out


def count_gmsh_elements(msh, dim):
    """The elements of dimension dim in a gmsh 4.1 file."""
    with open(msh) as f:
        lines = f.read().split("\n")
    i = lines.index("$Elements") + 1
    blocks = int(lines[i].split()[0])
    i += 1
    total = 0
    for _ in range(blocks):
        d, _, _, n = (int(x) for x in lines[i].split())
        total += n if d == dim else 0
        i += 1 + n
    return total


# ------------------------------------------------------------------ summaries
def summary_path(out_dir, analysis):
    return os.path.join(out_dir, f"{analysis}.summary.json")


def read_summary(out_dir, analysis):
    """<out_dir>/<analysis>.summary.json as a dict (nested objects). A missing file is an error
    that says what the directory holds (a choc built before the summaries writes none)."""
    path = summary_path(out_dir, analysis)
    if not os.path.exists(path):
        have = sorted(f for f in os.listdir(out_dir) if f.endswith(".summary.json")) \
            if os.path.isdir(out_dir) else None
        raise SummaryError(
            f"chocrun: no summary {path}: "
            + ("the output directory does not exist" if have is None else
               f"the directory holds {', '.join(have)}" if have else
               "the directory holds no summary at all (choc built before <analysis>.summary.json? "
               "rebuild choc)"))
    try:
        with open(path) as f:
            return json.load(f)
    except ValueError as e:
        raise SummaryError(f"chocrun: {path} is not JSON: {e}") from None


def read_summaries(out_dir, analyses=None):
    """{analysis: summary} for the named analyses (each one required), or every summary of the
    directory when analyses is None."""
    if analyses is None:
        analyses = sorted(f[:-len(".summary.json")] for f in os.listdir(out_dir) if f.endswith(".summary.json"))
    return {a: read_summary(out_dir, a) for a in analyses}


_REQUIRED = object()


def summary_value(summary, key, default=_REQUIRED):
    """The figure at "a/b/c" (nested objects) of a summary. A missing key is an error naming the
    key, the analysis and the keys present at that level, unless a default is given."""
    node = summary
    parts = key.split("/")
    for i, p in enumerate(parts):
        if isinstance(node, dict) and p in node:
            node = node[p]
            continue
        if default is not _REQUIRED:
            return default
        level = "/".join(parts[:i]) or "(top level)"
        have = ", ".join(node) if isinstance(node, dict) else type(node).__name__
        raise SummaryError(f"chocrun: the summary of '{summary.get('analysis', '?')}' has no '{key}' "
                           f"(at {level}: {have})")
    return node


def require_completed(summary, accept=("completed",)):
    """Raises SummaryError unless the analysis's status is one of `accept` ('completed',
    'check failed', 'failed', 'interrupted')."""
    status = summary_value(summary, "status")
    if status not in accept:
        raise SummaryError(f"chocrun: analysis '{summary.get('analysis', '?')}' {status}"
                           + (f": {summary['reason']}" if "reason" in summary else ""))
    return summary


def check_rows(summary):
    """The analysis's check rows (checks/rows/1, 2, ...) as a list of dicts, in order."""
    rows = summary_value(summary, "checks/rows", {})
    return [rows[k] for k in sorted(rows, key=int)]


def exact_errors(summary):
    """The whole-history errors against an exact solution that choc reported as check rows:
    {column: {"max": fraction of the peak, "max_time": t, "rms": fraction of the peak}} (a key is
    absent when its row is: a row exists when the check's tolerance is > 0, see
    report_exact_errors)."""
    out = {}
    for row in check_rows(summary):
        q = row.get("quantity", "")
        for suffix, key in ((" max error/peak", "max"), (" RMS error/peak", "rms")):
            if q.endswith(suffix):
                e = out.setdefault(q[:-len(suffix)], {})
                e[key] = row["computed"]
                if key == "max":
                    e["max_time"] = row.get("time")
    return out


def exact_error(summary, column, which="max"):
    """One whole-history error (a fraction of the peak) of `column`; SummaryError when choc did
    not report it."""
    e = exact_errors(summary)
    if column not in e or which not in e[column]:
        raise SummaryError(f"chocrun: the summary of '{summary.get('analysis', '?')}' has no row "
                           f"'{column} {'max' if which == 'max' else 'RMS'} error/peak' (rows for: "
                           f"{', '.join(sorted(e)) or 'none'}; see report_exact_errors)")
    return e[column][which]


def substeps(summary):
    """The (sub-)steps an analysis took: substeps_taken (the explicit and the modal transients),
    else steps x substeps_per_step (an explicit summary written before substeps_taken), else steps."""
    if "substeps_taken" in summary:
        return int(summary["substeps_taken"])
    return int(summary_value(summary, "steps")) * int(summary.get("substeps_per_step", 1))


def peak_mib_per_rank(summary):
    return [b / 2 ** 20 for b in summary_value(summary, "memory/peak_bytes_per_rank")]


def bytes_per_unknown(summary):
    """The peak resident memory of all ranks together per unknown."""
    return sum(summary_value(summary, "memory/peak_bytes_per_rank")) / summary_value(summary, "unknowns")


# ------------------------------------------------------------------ histories
class History(dict):
    """A history CSV as {column: numpy array}, in the file's column order; a missing column is
    an error naming the file and the columns it has."""

    def __init__(self, path, columns):
        super().__init__(columns)
        self.path = path

    def __missing__(self, key):
        raise KeyError(f"{self.path} has no column '{key}' (columns: {', '.join(self)})")


def history_path(out_dir, analysis):
    return os.path.join(out_dir, f"{analysis}.history.csv")


def read_element_fields(exo, names, step=-1):
    """Element variables of an Exodus file at one output step (the last by default), every block's
    elements one after the other: {name: numpy array}. Names end at their first NUL."""
    import netCDF4
    import numpy as np
    with netCDF4.Dataset(exo) as d:
        raw = d.variables["name_elem_var"]
        raw.set_auto_mask(False)
        stored = [row.tobytes().split(b"\0")[0].decode().strip() for row in raw[:]]
        blocks = len(d.dimensions["num_el_blk"])
        out = {}
        for name in names:
            if name not in stored:
                raise KeyError(f"{exo} has no element variable '{name}' (it has {', '.join(stored)})")
            k = stored.index(name) + 1
            parts = [np.asarray(d.variables[f"vals_elem_var{k}eb{b}"][step])
                     for b in range(1, blocks + 1) if f"vals_elem_var{k}eb{b}" in d.variables]
            out[name] = np.concatenate(parts)
        return out


def read_history(path_or_dir, analysis=None):
    """<out_dir>/<analysis>.history.csv (or a CSV path) as a History; its first column is 'time'."""
    import numpy as np
    path = history_path(path_or_dir, analysis) if analysis is not None else path_or_dir
    with open(path) as f:
        header = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    if not header or header[0] != "time":
        raise ValueError(f"{path}: not a choc history (first column '{header[0] if header else ''}')")
    if data.size == 0:
        data = np.zeros((0, len(header)))
    return History(path, {name: data[:, k] for k, name in enumerate(header)})


def history_difference(a, b, columns=None):
    """{column: max |b - a| / max |a|} of two histories of the same times (every common column
    but time when columns is None)."""
    import numpy as np
    if len(a["time"]) != len(b["time"]):
        raise ValueError(f"{a.path} and {b.path}: {len(a['time'])} and {len(b['time'])} rows")
    columns = columns or [c for c in a if c != "time" and c in b]
    out = {}
    for c in columns:
        peak = float(np.max(np.abs(a[c]))) if len(a[c]) else 0.0
        out[c] = float(np.max(np.abs(b[c] - a[c]))) / (peak if peak > 0 else 1.0)
    return out


# ------------------------------------------------------------------ decks
def load_deck(path, absolute_mesh=True):
    """A deck as an ElementTree (comments kept). With absolute_mesh, a relative 'Mesh/File' is
    made absolute (it is relative to the deck's directory, and edited decks are written
    elsewhere)."""
    tree = ET.parse(path, parser=ET.XMLParser(target=ET.TreeBuilder(insert_comments=True)))
    if absolute_mesh:
        mesh = find(tree, "Mesh/File", None)
        if mesh is not None and not os.path.isabs(mesh.get("value", "")):
            mesh.set("value", os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(path)),
                                                            mesh.get("value"))))
    return tree


def parse_deck(text):
    return ET.ElementTree(ET.fromstring(text, parser=ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))))


def deck_text(tree):
    t = copy.deepcopy(tree)
    ET.indent(t, space="  ")
    return ET.tostring(t.getroot(), encoding="unicode") + "\n"


def write_deck(tree, path):
    """Writes the deck to path (directories made); returns path."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        f.write(deck_text(tree))
    return path


def _root(tree):
    return tree.getroot() if isinstance(tree, ET.ElementTree) else tree


def _children(node, tag=None):
    return [c for c in node if isinstance(c.tag, str) and (tag is None or c.tag == tag)]


def _child(node, name, tag=None):
    for c in _children(node, tag):
        if c.get("name") == name and c.tag in ("Parameter", "ParameterList"):
            return c
    return None


_MISSING = object()


def find(tree, path, default=_MISSING):
    """The element (Parameter or ParameterList) at "A/B/name" below the deck's top list. A path
    that does not exist raises DeckError naming it and what exists where it stops, unless a
    default is given."""
    node = _root(tree)
    parts = path.split("/")
    for i, p in enumerate(parts):
        nxt = _child(node, p) if node.tag == "ParameterList" else None
        if nxt is None:
            if default is not _MISSING:
                return default
            where = "/".join(parts[:i]) or "the top list"
            have = ", ".join(f"'{c.get('name')}'" for c in _children(node)) or "nothing"
            raise DeckError(f"deck: no '{path}' ('{p}' not in {where}, which holds {have})")
        node = nxt
    return node


def has(tree, path):
    return find(tree, path, None) is not None


def _typed(elem):
    kind, text = elem.get("type", "string"), elem.get("value", "")
    if kind == "bool":
        return text.strip().lower() in ("true", "1", "yes")
    if kind == "int":
        return int(text)
    if kind == "double":
        return float(text)
    return text


def get_param(tree, path, default=_MISSING):
    """The typed value (double -> float, int -> int, bool -> bool) of the parameter at path."""
    e = find(tree, path, None if default is not _MISSING else _MISSING)
    if e is None:
        return default
    if e.tag != "Parameter":
        raise DeckError(f"deck: '{path}' is a sublist, not a parameter")
    return _typed(e)


def _format(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _infer_type(value):
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "double"
    return "string"


def _parent(tree, path, create):
    parts = path.split("/")
    node = _root(tree)
    for i, p in enumerate(parts[:-1]):
        nxt = _child(node, p, "ParameterList")
        if nxt is None:
            if not create:
                find(tree, "/".join(parts[:i + 1]))  # raises, naming what exists
                raise DeckError(f"deck: '{'/'.join(parts[:i + 1])}' is a parameter, not a sublist")
            nxt = ET.SubElement(node, "ParameterList", name=p)
        node = nxt
    return node, parts[-1]


def set_param(tree, path, value, type=None, create=False):
    """Sets the parameter at path to value (a float is written to round trip). The parameter must
    exist unless create=True, which adds it (and missing sublists), typed `type` or from the
    value (bool, int, double, string). Returns the element."""
    parent, name = _parent(tree, path, create)
    e = _child(parent, name)
    if e is None:
        if not create:
            find(tree, path)  # raises DeckError naming the path
        e = ET.SubElement(parent, "Parameter", name=name, type=type or _infer_type(value))
    elif e.tag != "Parameter":
        raise DeckError(f"deck: '{path}' is a sublist, not a parameter")
    elif type:
        e.set("type", type)
    e.set("value", _format(value))
    return e


def set_params(tree, values, create=False):
    """set_param for each {path: value}."""
    for path, value in values.items():
        set_param(tree, path, value, create=create)


def remove_param(tree, path, missing_ok=False):
    """Removes the parameter at path (DeckError when absent, unless missing_ok)."""
    e = find(tree, path, None if missing_ok else _MISSING)
    if e is None:
        return False
    if e.tag != "Parameter":
        raise DeckError(f"deck: '{path}' is a sublist, not a parameter (remove_sublist)")
    parent, _ = _parent(tree, path, False)
    parent.remove(e)
    return True


def sublist(tree, path, create=False):
    """The sublist element at path (created with its parents when create=True)."""
    if create:
        parent, name = _parent(tree, path + "/x", True)
        return parent
    e = find(tree, path)
    if e.tag != "ParameterList":
        raise DeckError(f"deck: '{path}' is a parameter, not a sublist")
    return e


def sublists(tree, path):
    """The names of the sublists of the list at path ("" for the top list)."""
    node = _root(tree) if not path else sublist(tree, path)
    return [c.get("name") for c in _children(node, "ParameterList")]


def remove_sublist(tree, path):
    """Removes the sublist at path (DeckError when absent)."""
    e = sublist(tree, path)
    parent, _ = _parent(tree, path, False)
    parent.remove(e)


def hold_on_wall(tree, analysis, side_set, component, scheme, dt, end):
    """An impact deck turned into a short run with its contact replaced by a Dirichlet condition
    holding side_set's `component` (the bar stuck on the wall: no contact iterations), by `scheme`
    at `dt` up to `end`, without Exodus output; an implicit scheme drops the explicit keys."""
    remove_sublist(tree, f"{analysis}/Contact")
    set_params(tree, {"Model/Dirichlet/wall/Node Set": side_set, "Model/Dirichlet/wall/Components": component,
                      f"{analysis}/Scheme": scheme, f"{analysis}/Time Step": dt, f"{analysis}/End Time": end,
                      f"{analysis}/Exodus Interval": 0}, create=True)
    if scheme != "central differences":
        for p in ("Stability Check", "Critical Step Interval"):
            remove_param(tree, f"{analysis}/{p}", missing_ok=True)
    return tree


def rename_sublist(tree, path, new_name):
    """Renames the sublist at path (DeckError when absent or when new_name is taken)."""
    e = sublist(tree, path)
    parent, _ = _parent(tree, path, False)
    if _child(parent, new_name) is not None:
        raise DeckError(f"deck: cannot rename '{path}' to '{new_name}': the name is taken")
    e.set("name", new_name)


def copy_sublist(src_tree, src_path, dst_tree, dst_parent_path, replace=False):
    """Copies the sublist at src_path into the list at dst_parent_path (same name). An existing
    sublist of that name is an error unless replace=True."""
    e = copy.deepcopy(sublist(src_tree, src_path))
    parent = sublist(dst_tree, dst_parent_path)
    old = _child(parent, e.get("name"))
    if old is not None:
        if not replace:
            raise DeckError(f"deck: '{dst_parent_path}/{e.get('name')}' exists already")
        parent.remove(old)
    parent.append(e)
    return e


def analyses(tree):
    """The names of the deck's analyses, in order."""
    return sublists(tree, "Analyses")


def only_analysis(tree):
    """The name of the deck's one analysis (DeckError when it has several)."""
    names = analyses(tree)
    if len(names) != 1:
        raise DeckError(f"deck: {len(names)} analyses ({', '.join(names)}), one expected")
    return names[0]


def keep_analyses(tree, names):
    """Removes every analysis but `names` (each must exist)."""
    have = analyses(tree)
    for n in names:
        if n not in have:
            find(tree, f"Analyses/{n}")  # raises naming it
    for n in have:
        if n not in names:
            remove_sublist(tree, f"Analyses/{n}")


def checks_of_type(tree, analysis, check_type):
    """The paths of the analysis's check rows of a 'Type' (e.g. 'Bar Impact Exact Solution')."""
    base = f"Analyses/{analysis}/Checks"
    if not has(tree, base):
        return []
    return [f"{base}/{n}" for n in sublists(tree, base) if get_param(tree, f"{base}/{n}/Type", "") == check_type]


EXACT_CHECK = "Bar Impact Exact Solution"
REPORT_ONLY = 1e9


def report_exact_errors(tree, analysis):
    """Makes every 'Bar Impact Exact Solution' check of the analysis report its max and RMS
    whole-history errors as rows (a report-only tolerance, so they never fail). Returns the
    checks' paths (empty when the analysis has none)."""
    paths = checks_of_type(tree, analysis, EXACT_CHECK)
    for p in paths:
        set_param(tree, f"{p}/Max Error Tolerance", REPORT_ONLY, "double", create=True)
        set_param(tree, f"{p}/RMS Error Tolerance", REPORT_ONLY, "double", create=True)
    return paths


# ------------------------------------------------------------------ benchmark records
def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def gmsh_mesh(geo, out, order=1, **numbers):
    """meshes/<geo> meshed in 3D by gmsh into out (msh 4.1) with its numbers set (-setnumber
    name value), of element order `order`; returns out."""
    cmd = ["gmsh", "-3", "-order", str(order), "-format", "msh41"]
    for name, value in numbers.items():
        cmd += ["-setnumber", name, str(value)]
    subprocess.run(cmd + [os.path.join(TOP, "meshes", geo), "-o", out], check=True, stdout=subprocess.DEVNULL)
    return out


def rotation_matrix(angle, axis):
    """The rotation by `angle` (radians) about `axis` (Rodrigues), a 3 x 3 numpy array."""
    import numpy as np
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx


def turned_mesh(src_msh, out_msh, R):
    """The gmsh 4.1 mesh src_msh written to out_msh with every node at R x (numbering and groups
    unchanged; the frame-invariance tests); returns out_msh."""
    import numpy as np
    lines = open(src_msh).read().split("\n")
    i = lines.index("$Nodes") + 1
    blocks = int(lines[i].split()[0])
    i += 1
    for _ in range(blocks):
        _, _, parametric, n = map(int, lines[i].split())
        if parametric:
            raise ValueError(f"{src_msh}: parametric nodes are not handled")
        i += 1 + n
        for k in range(i, i + n):
            x = R @ np.array([float(v) for v in lines[k].split()])
            lines[k] = " ".join(repr(float(v)) for v in x)
        i += n
    with open(out_msh, "w") as f:
        f.write("\n".join(lines))
    return out_msh


def taylor_bar_3d_deck(work, n=2, full=0, R=None, end=None, points=("EDGE", "REAR", "CENTRE"),
                       deck="taylor_bar_3d.xml", speed=227):
    """input/`deck` (a bar flying at `speed` along -y) on meshes/taylor_bar_3d.geo with n elements
    across the radius (the mesh written into `work`), Exodus off: the quarter, or with `full` the
    whole bar (no symmetry planes, the `points`' three components recorded); with R (a rotation
    matrix) the bar, its wall and its velocity turned as a rigid whole (the frame-invariance tests);
    `end` the end time. Returns the deck tree."""
    msh = gmsh_mesh("taylor_bar_3d.geo", os.path.join(work, f"bar3d_n{n}_full{full}.msh"), n=n, full=full)
    d = load_deck(input_path(deck))
    set_param(d, "Analyses/impact/Exodus Interval", 0)
    if full:
        remove_sublist(d, "Model/Dirichlet")
        set_param(d, "Analyses/impact/History", " ".join(f"{p}:{c}" for p in points for c in ("DX", "DY", "DZ")))
    if end:
        set_param(d, "Analyses/impact/End Time", end)
    if R is not None:
        msh = turned_mesh(msh, os.path.join(work, f"bar3d_n{n}_turned.msh"), R)
        vec = lambda x: " ".join(repr(float(v)) for v in x)  # noqa: E731
        set_param(d, "Analyses/impact/Contact/Pairs/wall/Obstacle/Normal", vec(R @ [0, 1, 0]))
        ic = "Analyses/impact/Initial Conditions/flight"
        set_param(d, ic + "/Field", "Rigid Velocity")
        remove_param(d, ic + "/Components")
        remove_param(d, ic + "/Value")
        set_param(d, ic + "/Translation", vec(R @ [0, -speed, 0]), create=True)
    set_param(d, "Mesh/File", msh)
    return d


def taylor_bar_outcome(label, h, strain, temperature, failures, R0=3.2e-3, L0=32.4e-3, created=1e-6):
    """A Taylor bar run's figures from its history h (EDGE:DX, REAR:DY, CENTRE:DY) and the element
    fields at its end: the impact-face diameter and the length [mm] (the rear face's centre minus
    the impact face's), the largest equivalent plastic strain and temperature, printed with the
    plastic work and the energy balance; appends to `failures` when energy is created (the balance
    above `created` E0) or the plastic work ends below 97 % of E0. Returns the figures (a dict)."""
    import numpy as np
    e0 = h["energy:total"][1]
    v = {"diameter": 2 * (R0 + h["EDGE:DX"][-1]) * 1e3, "length": (L0 + h["REAR:DY"][-1] - h["CENTRE:DY"][-1]) * 1e3,
         "strain": float(np.max(strain)), "temperature": float(np.max(temperature))}
    bal = np.asarray(h["energy:balance"])
    print(f"{label}: " + ", ".join(f"{k} {x:.4f}" for k, x in v.items()) +
          f"; plastic work {h['energy:dissipated'][-1] / e0:.4f} E0, balance in [{bal.min() / e0:.2e}, "
          f"{bal.max() / e0:.2e}] E0")
    if not bal.max() <= created * e0:
        failures.append(f"{label}: energy created, balance up to {bal.max() / e0:.2e} E0")
    if not h["energy:dissipated"][-1] >= 0.97 * e0:
        failures.append(f"{label}: plastic work {h['energy:dissipated'][-1]:.4g} J below 97 % of E0")
    return v


def renumbered_mesh(src_msh, out_msh):
    """The gmsh 4.1 mesh src_msh written to out_msh with node tag t renamed N + 1 - t, in the
    nodes and the elements (the numbering-invariance tests); returns out_msh."""
    lines = open(src_msh).read().split("\n")
    i = lines.index("$Nodes") + 1
    blocks, total = (int(v) for v in lines[i].split()[:2])
    flip = lambda t: str(total + 1 - int(t))  # noqa: E731
    i += 1
    for _ in range(blocks):
        n = int(lines[i].split()[3])
        for k in range(i + 1, i + 1 + n):
            lines[k] = flip(lines[k])
        i += 1 + 2 * n
    i = lines.index("$Elements") + 2
    while lines[i] != "$EndElements":
        n = int(lines[i].split()[3])
        for k in range(i + 1, i + 1 + n):
            tags = lines[k].split()
            lines[k] = " ".join([tags[0]] + [flip(t) for t in tags[1:]])
        i += 1 + n
    with open(out_msh, "w") as f:
        f.write("\n".join(lines))
    return out_msh


def step_record(choc, path, out, analysis, ranks=1, env=None):
    """Runs a transient deck (`env`: variables added to its environment) and returns its per-step
    figures: unknowns, step_s (the slowest rank's analysis time per step), solve_s, factorizations,
    krylov, newton_per_step, peak_rss_mib (the largest process), kib_per_unknown, choc_commit."""
    r = run(choc, path, out, ranks=ranks, env=env)
    s = require_completed(read_summary(out, analysis))
    v = lambda key, default=_REQUIRED: summary_value(s, key, default)  # noqa: E731
    steps = max(1, v("steps"))
    return {"unknowns": v("unknowns"), "step_s": v("timers/analysis/max") / steps,
            "solve_s": v("timers/linear_solve/max", 0.0), "factorizations": v("factorizations", 0),
            "krylov": v("krylov_iterations", 0), "newton_per_step": v("newton", {"iterations": 0})["iterations"] / steps,
            "peak_rss_mib": r.maxrss_mib, "kib_per_unknown": 1024.0 * r.maxrss_mib / max(1, v("unknowns")),
            "choc_commit": v("choc/commit")}


def rank_sweep(choc, path, out_prefix, analysis, ranks, repeat, record=None):
    """Runs the deck at path `repeat` times on each rank count in turn (into <out_prefix>_np<n>)
    and yields (n, out_dir, record): the median_record of its step_records (or of
    record(choc, path, out, analysis, n), a dict with "step_s", when given), with "ranks" and
    "speedup" (the first rank count's time per step over this one's)."""
    record = record or step_record
    first = None
    for n in ranks:
        out = f"{out_prefix}_np{n}"
        rec = median_record([record(choc, path, out, analysis, n) for _ in range(repeat)])
        first = first or rec["step_s"]
        rec.update({"ranks": n, "speedup": first / rec["step_s"]})
        yield n, out, rec


def median_record(records):
    """The median of each figure over repeated runs' records (dicts of the same keys): numbers
    by statistics.median, lists element by element, other values from the first record."""
    out = {}
    for k in records[0]:
        vals = [r.get(k) for r in records]
        if all(isinstance(v, bool) for v in vals) or not all(isinstance(v, (int, float, list)) for v in vals):
            out[k] = vals[0]
        elif all(isinstance(v, list) for v in vals):
            out[k] = [statistics.median(x) for x in zip(*vals)]
        else:
            m = statistics.median(vals)
            out[k] = int(m) if all(isinstance(v, int) for v in vals) and m == int(m) else m
    out["repeat"] = len(records)
    return out


def machine():
    """The machine: processors available, CPU model, memory, load average now."""
    model = platform.processor() or "?"
    mem = None
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    mem = round(int(line.split()[1]) / 2 ** 20, 1)
    except OSError:
        pass
    nproc = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return {"nproc": nproc, "cpu_model": model, "memory_gib": mem, "load_average": load_average(),
            "os": platform.platform()}


def commit():
    """The source tree's commit (and whether it has uncommitted changes)."""
    def git(*args):
        p = subprocess.run(["git", "-C", TOP, *args], capture_output=True, text=True)
        return p.stdout.strip() if p.returncode == 0 else None
    head = git("rev-parse", "--short=12", "HEAD")
    dirty = git("status", "--porcelain", "--untracked-files=no")
    return {"commit": head, "dirty": bool(dirty) if dirty is not None else None}


def bench_json_path(name):
    return os.path.join(TOP, "results", "bench", f"{name}.json")


def write_bench_json(name, title, runs, tables, parameters=None, path=None, notes=(), choc_commit=None):
    """Writes a benchmark's figures to results/bench/<name>.json (or path), which
    tools/docs/performance_pages.py turns into docs/performance/generated/<name>.md:
      runs:   one dict of figures per run (medians over the repeats, 'repeat' their number);
      tables: [{"title", "columns": [[key, header, format], ...], "where": {key: value}, "note"}]:
              a table of the runs matching 'where' (format: a Python format spec, "list:SPEC"
              for lists, "" for str()).
    Returns the path."""
    path = path or bench_json_path(name)
    doc = {"bench": name, "title": title,
           "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
           "machine": machine(), "source": commit(), "choc_commit": choc_commit,
           "command": " ".join([os.path.relpath(sys.argv[0], TOP)] + sys.argv[1:]),
           "parameters": parameters or {}, "runs": runs, "tables": tables, "notes": list(notes)}
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        json.dump(doc, f, indent=1, default=_json_default)
        f.write("\n")
    print(f"{name}: figures in {path}")
    return path


def _json_default(x):
    try:
        import numpy as np
        if isinstance(x, np.generic):
            return x.item()
        if isinstance(x, np.ndarray):
            return x.tolist()
    except ImportError:
        pass
    raise TypeError(f"not JSON: {type(x).__name__}")


def fmt(value, spec=""):
    """A table cell: value formatted by spec ("list:SPEC" formats each element), '' for None
    and NaN."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if spec.startswith("list:"):
        return ", ".join(fmt(v, spec[5:]) for v in value)
    if not spec:
        return str(value)
    try:
        return format(value, spec)
    except (ValueError, TypeError):
        return str(value)


def markdown_table(runs, columns, where=None):
    """The markdown lines of a table of runs (write_bench_json's table form)."""
    rows = [r for r in runs if all(r.get(k) == v for k, v in (where or {}).items())]
    lines = ["| " + " | ".join(c[1] for c in columns) + " |", "|" + "---|" * len(columns)]
    for r in rows:
        lines.append("| " + " | ".join(fmt(r.get(c[0]), c[2] if len(c) > 2 else "") for c in columns) + " |")
    return lines


def print_tables(runs, tables):
    for t in tables:
        print(f"\n{t['title']}")
        print("\n".join(markdown_table(runs, t["columns"], t.get("where"))))
        if t.get("note"):
            print(t["note"])


def bench_arguments(doc, results_dir, repeat=3):
    """The arguments every benchmark takes: --build, --repeat, --out (results/<results_dir>),
    --json; the caller adds its own and parses."""
    import argparse
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--repeat", type=int, default=repeat)
    ap.add_argument("--out", default=os.path.join(TOP, "results", results_dir))
    ap.add_argument("--json", default=None, help="the figures' file (default results/bench/<bench>.json)")
    return ap


def report_bench(name, title, rows, tables, args):
    """Prints the benchmark's tables and writes its figures (write_bench_json)."""
    print_tables(rows, tables)
    write_bench_json(name, title, rows, tables, vars(args), args.json,
                     choc_commit=rows[0]["choc_commit"] if rows else None)


def write_text(path, text):
    """Writes text to path (a deck written as text); returns path."""
    with open(path, "w") as f:
        f.write(text)
    return path


def spin_deck(mesh, block, omega, centre, scheme, dt, end, strain="finite", law="neo-Hookean", E=2e11, nu=0.3,
              rho=7800.0, history="", exodus=0, extra=""):
    """The deck (text) of one free elastic block of the mesh spun rigidly: Initial Conditions
    'Rigid Velocity' with Angular Velocity omega about centre (3-vectors), lumped mass, one
    transient 'spin' by `scheme`; the block's Strain and the material's Model as given. Used by
    the tumbling body's test and the finite-strain benchmark."""
    vec = lambda x: " ".join(repr(float(v)) for v in x)  # noqa: E731
    return f"""<ParameterList name="spin_{block}">
  <ParameterList name="Mesh"><Parameter name="File" type="string" value="{mesh}"/></ParameterList>
  <ParameterList name="Model">
    <ParameterList name="Materials"><ParameterList name="material">
      <Parameter name="Young's Modulus" type="double" value="{E}"/>
      <Parameter name="Poisson's Ratio" type="double" value="{nu}"/>
      <Parameter name="Density" type="double" value="{rho}"/>
      <Parameter name="Model" type="string" value="{law}"/>
    </ParameterList></ParameterList>
    <ParameterList name="Blocks"><ParameterList name="{block}">
      <Parameter name="Material" type="string" value="material"/>
      <Parameter name="Strain" type="string" value="{strain}"/>
      <Parameter name="Mass" type="string" value="lumped"/>
    </ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Analyses"><ParameterList name="spin">
    <Parameter name="Type" type="string" value="Transient"/>
    <Parameter name="Scheme" type="string" value="{scheme}"/>
    <Parameter name="Time Step" type="double" value="{dt}"/>
    <Parameter name="End Time" type="double" value="{end}"/>
    <Parameter name="History" type="string" value="{history}"/>
    <Parameter name="Exodus Interval" type="int" value="{exodus}"/>{extra}
    <ParameterList name="Initial Conditions"><ParameterList name="spin">
      <Parameter name="Node Set" type="string" value="{block}"/>
      <Parameter name="Field" type="string" value="Rigid Velocity"/>
      <Parameter name="Angular Velocity" type="string" value="{vec(omega)}"/>
      <Parameter name="Centre" type="string" value="{vec(centre)}"/>
    </ParameterList></ParameterList>
  </ParameterList></ParameterList>
</ParameterList>
"""


def saint_venant_run(choc, work, ratio, along=100, courant=0.96, ranks=1, striker_modulus=None, name=None):
    """input/saint_venant.xml (BENCHMARKS section 15) run for the mass ratio rho A L / M = ratio
    with `along` HEX8 along the 1 m bar (choc mesh; 100 is the committed mesh) at the step
    courant x dz / c, until a tenth of a transit after the exact separation (a whole number of
    steps). striker_modulus: the striker meshed elastic (its own Young's modulus, the same mass)
    instead of rigid; the step is then the smaller of the bar's and the striker's transit times.
    Returns (history, impacts (list of dicts), oracle SaintVenant, dz, dt, out_dir)."""
    import csv
    add_tool_path("oracles")
    from saint_venant import SaintVenant
    L, A, rho, E, v0, striker = 1.0, 4e-4, 7800.0, 2e11, 1.0, (0.05, 5)
    c = math.sqrt(E / rho)
    M = rho * A * L / ratio
    sv = SaintVenant(L, A, rho, E, M, v0)
    dz = L / along
    density = M / (0.02 * 0.02 * striker[0])
    step = dz / c if striker_modulus is None else min(dz / c, striker[0] / striker[1] / math.sqrt(striker_modulus / density))
    dt = courant * step
    d = load_deck(os.path.join(TOP, "input", "saint_venant.xml"))
    if along != 100:
        set_param(d, "Mesh/File", mesh(choc, os.path.join(work, f"bar{along}.exo"), "--dim", 3, "--axis", "z", "--gap", 0,
                                       "--length1", striker[0], "--along1", striker[1], "--length2", L, "--along2", along))
    set_params(d, {"Model/Materials/striker/Density": density, "Analyses/strike/Time Step": dt,
                   "Analyses/strike/End Time": math.ceil((sv.duration + 0.1 * sv.T) / dt) * dt})
    if striker_modulus is not None:
        set_params(d, {"Model/Materials/striker/Young's Modulus": striker_modulus, "Model/Blocks/POU1/Rigid": False,
                       "Model/Blocks/POU1/Mass": "lumped"}, create=True)
    out = os.path.join(work, name or f"r{ratio}_n{along}_c{courant}_np{ranks}" + (f"_E{striker_modulus:g}" if striker_modulus else ""))
    run(choc, write_deck(d, out + ".xml"), out, ranks=ranks)
    require_completed(read_summary(out, "strike"))
    with open(os.path.join(out, "strike.impacts.csv")) as f:
        impacts = list(csv.DictReader(f))
    return read_history(out, "strike"), impacts, sv, dz, dt, out


def check_no_energy_created(h, label, failures, peak_bound=1e-3):
    """A run that should create no energy: its history's balance ends at or below 0 (1e-8 of E0
    for round-off) and never exceeds peak_bound E0 (the schemes' transient excess); prints both
    and appends to failures what fails."""
    E0 = h["energy:total"][0]
    final, peak = h["energy:balance"][-1] / E0, max(h["energy:balance"]) / E0
    print(f"  energy balance at the end {final:+.2e} E0, largest {peak:+.2e} E0")
    if not (final <= 1e-8 and peak <= peak_bound):
        failures.append(f"{label}: energy balance {final:+.2e} E0 at the end, {peak:+.2e} at most (0, {peak_bound:g})")


def check_ranks_alike(h1, h2, columns, label, failures, bound=1e-8):
    """Two runs' histories (1 and 2 ranks) alike to bound of each column's peak."""
    for col, rel in history_difference(h1, h2, columns).items():
        if not rel <= bound:
            failures.append(f"{label}{col}: 2 ranks differ by {rel:.2e} of the peak (at most {bound:g})")
