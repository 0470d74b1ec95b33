#!/usr/bin/env python3
"""A wrong answer must never look right (issue 71): one test per case of the adversarial table.

  wrong_answers.py CHOC WORKDIR CASE

Each case is a run that, before, ended with exit 0 and an answer that was not one (an inverted
element, a small-strain block far out of its domain, a key the law ignored, a degenerate
element), a warning the docs promise and the log lacked, or a failed run that reported less than
a completed one. The sandbox and the one-line error checks are adversarial.py's.
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from adversarial import (ROOT, INPUTS, check, choc_cmd, deck, expect_error, find, run, run_cases,  # noqa: E402
                         set_value)

import xml.etree.ElementTree as ET  # noqa: E402


def taylor_3d(box, edit):
    return deck(os.path.join(ROOT, "input", "taylor_bar_3d.xml"), box.path("input.xml"), edit)


def run_choc(choc, box, *args, env=None):
    return run(choc_cmd(choc, "run", box.path("input.xml"), "-o", box.out) + list(args), box.dir, env)


def summary(box, name):
    with open(os.path.join(box.out, name + ".summary.json")) as f:
        return json.load(f)


def exodus_times(path):
    import netCDF4  # Debian's python3-netcdf4 (tools/build/install-deps.sh)
    with netCDF4.Dataset(path) as d:
        return [float(t) for t in d.variables["time_whole"][:]]


def failed_run_reports_fully(box, name, err):
    """The failed run's summary has a completed run's keys, and its .incomplete.exo ends at the
    last accepted state (the time the summary says the run reached)."""
    s = summary(box, name)
    check(s["status"] == "failed" and s["exit_code"] == 2, "summary status %s, exit %s" % (s["status"], s["exit_code"]))
    for key in ("steps", "time_reached", "smallest_step", "energy", "memory", "cpu_seconds_per_rank"):
        check(key in s, "the failed run's summary has no '%s': %s" % (key, sorted(s)))
    check("peak_bytes_per_rank" in s["memory"], "memory keys %s" % sorted(s["memory"]))
    check(s["steps"] > 0 and s["time_reached"] > 0, "steps %s, time reached %s" % (s["steps"], s["time_reached"]))
    exo = os.path.join(box.out, name + ".incomplete.exo")
    check(os.path.exists(exo), "no %s: %s" % (exo, os.listdir(box.out)))
    times = exodus_times(exo)
    check(times and abs(times[-1] - s["time_reached"]) <= 1e-12 * max(1.0, s["time_reached"]) + 1e-15,
          "the incomplete Exodus file ends at t = %s, the run reached %s" % (times[-1:], s["time_reached"]))
    m = re.search(r"t = ([0-9.e+-]+) s", err)
    check(m and abs(float(m.group(1)) - s["time_reached"]) <= 1e-6 * s["time_reached"],
          "the message's time is not the last accepted state's: %s" % err)


# --- inverted elements and small strain out of its domain -----------------------------------------

def case_one_point_taylor_bar_inverted(choc, box):
    """The one-point 3D Taylor bar at 10 x its velocity: elements turn inside out at their corners
    while their mean gradient stays positive. Exit 2 naming the element, its block and the time."""
    def edit(r):
        set_value(r, "Model/Blocks/BAR/Formulation", "one-point")
        set_value(r, "Analyses/impact/Initial Conditions/flight/Value", "-2270", "double")
        set_value(r, "Analyses/impact/End Time", "2e-5", "double")
    taylor_3d(box, edit)
    rc, out, err = run_choc(choc, box)
    expect_error(rc, err, 2, r"element [0-9]+ of block 'BAR': inverted: det F = -?[0-9.e+-]+ at a quadrature point or a "
                             r"one-point element's corner")
    failed_run_reports_fully(box, "impact", err)
    # 2 ranks name the same element at the same time (the lowest-numbered of the worst, whatever
    # rank holds it): the whole line alike
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none", "--mca", "mpi_yield_when_idle", "1",
           "-np", "2", choc, "run", box.path("input.xml"), "-o", box.path("np2")]
    rc2, _, err2 = run(cmd, box.dir)
    line = [l for l in err2.splitlines() if l.startswith("choc: numerical failure")]
    check(rc2 != 0 and line and line[0] == err.strip(), "2 ranks: exit %s, %r against %r" % (rc2, line, err.strip()))


def case_one_point_plane_strain_inverted(choc, box):
    """The same in plane strain: the Taylor bar's section as one-point QUAD4 at 10 x its velocity."""
    def edit(r):
        set_value(r, "Model/Kinematics", "plane strain")
        set_value(r, "Model/Blocks/BAR/Formulation", "one-point")
        flight = [c for c in find(r, "Analyses/impact/Initial Conditions") if c.tag == "ParameterList"][0]
        [c for c in flight if c.get("name") == "Value"][0].set("value", "-2270")  # its name holds a '/'
        set_value(r, "Analyses/impact/End Time", "2e-5", "double")
    deck(os.path.join(ROOT, "input", "taylor_bar_axisymmetric.xml"), box.path("input.xml"), edit)
    rc, out, err = run_choc(choc, box)
    expect_error(rc, err, 2, r"element [0-9]+ of block 'BAR': inverted: det F = -?[0-9.e+-]+ at a quadrature point or a "
                             r"one-point element's corner")
    failed_run_reports_fully(box, "impact", err)


def case_small_strain_sphere_out_of_domain(choc, box):
    """The small-strain plastic sphere at 216 m/s (100 x its yield velocity): strains of order 1 in
    a small-strain block: exit 2 past 50 % (or an inverted element), at the first check (the critical
    step's estimate, every 100 steps here) already past it."""
    def edit(r):
        set_value(r, "Analyses/impact/Initial Conditions/the sphere falls at 10 v_y/Value", "-216.15696775", "double")
    deck(os.path.join(ROOT, "input", "plastic_impact_axisymmetric.xml"), box.path("input.xml"), edit)
    rc, out, err = run_choc(choc, box)
    expect_error(rc, err, 2, r"block 'SPHERE': (a small strain of|a rotation of|inverted)")
    failed_run_reports_fully(box, "impact", err)


def case_small_strain_sphere_in_domain(choc, box):
    """The same sphere at its deck's 2.16 m/s stays in the small-strain domain: no warning."""
    deck(os.path.join(ROOT, "input", "plastic_impact_axisymmetric.xml"), box.path("input.xml"),
         lambda r: set_value(r, "Analyses/impact/End Time", "2e-5", "double"))
    rc, out, err = run_choc(choc, box)
    check(rc == 0, "exit %s: %s" % (rc, err))
    check("past the small-strain" not in out, "a small-strain warning at the deck's speed:\n" + out)


def case_obstacle_penetrated(choc, box):
    """A penalty far too soft (1 N/m per node) lets the sphere through the rigid plane: past half
    its faces' size a failure (exit 2) naming the node and the pair."""
    def edit(r):
        set_value(r, "Analyses/impact/Contact/Method", "Penalty")
        set_value(r, "Analyses/impact/Contact/Penalty Stiffness", "1", "double")
        set_value(r, "Analyses/impact/Initial Conditions/the sphere falls at 10 v_y/Value", "-21.615696775", "double")
    deck(os.path.join(ROOT, "input", "plastic_impact_axisymmetric.xml"), box.path("input.xml"), edit)
    rc, out, err = run_choc(choc, box)
    expect_error(rc, err, 2, r"node [0-9]+ of pair 'plane' is [0-9.e+-]+ m through the rigid obstacle, [0-9.e+-]+ of its "
                             r"faces' size \(limit 0\.5\): raise 'Penalty Stiffness'")
    failed_run_reports_fully(box, "impact", err)


# --- keys the law does not read ------------------------------------------------------------------

def material_deck(box, edit):
    return deck(os.path.join(ROOT, "input", "taylor_bar_3d.xml"), box.path("input.xml"), edit)


def remove_keys(r, path, names):
    """Removes the parameters `names` of the list at `path`."""
    node = find(r, path)
    for c in list(node):
        if c.get("name") in names:
            node.remove(c)


def refused_run(choc, box, pattern):
    rc, _, err = run(choc_cmd(choc, "check", box.path("input.xml")), box.dir)
    expect_error(rc, err, 1, pattern)
    check(not os.path.exists(box.out), "a refused input wrote %s" % box.out)


def case_yield_stress_without_model(choc, box):
    """'Yield Stress' on a material whose 'Model' was forgotten (linear elastic)."""
    def edit(r):
        remove_keys(r, "Model/Materials/copper", ("Model",))
        set_value(r, "Model/Blocks/BAR/Strain", "small")
        set_value(r, "Model/Blocks/BAR/Formulation", "standard")
    material_deck(box, edit)
    refused_run(choc, box, r"parameter 'Model/Materials/copper/Yield Stress' = '4e\+08': is not a parameter of "
                           r"'linear elastic'. did you mean 'Model' = 'J2 plasticity'\?")


def case_hardening_on_neo_hookean(choc, box):
    material_deck(box, lambda r: (set_value(r, "Model/Materials/copper/Model", "neo-Hookean"),
                                  set_value(r, "Model/Blocks/BAR/Formulation", "standard")))
    refused_run(choc, box, r"parameter 'Model/Materials/copper/(Yield Stress|Hardening Modulus)' = '[0-9e+.]+': is not "
                           r"a parameter of 'neo-Hookean'")


def case_yield_stress_on_johnson_cook(choc, box):
    deck(os.path.join(ROOT, "input", "taylor_bar_johnson_cook_axisymmetric.xml"), box.path("input.xml"),
         lambda r: set_value(r, "Model/Materials/42CrMo4/Yield Stress", "400e6", "double"))
    refused_run(choc, box, r"parameter 'Model/Materials/42CrMo4/Yield Stress' = '4e\+08': is not a parameter of "
                           r"'Johnson-Cook'. the Johnson-Cook flow stress is .*'Johnson-Cook A'")


def case_yield_stress_missing(choc, box):
    def edit(r):
        remove_keys(r, "Model/Materials/copper", ("Yield Stress", "Hardening Modulus"))
    material_deck(box, edit)
    refused_run(choc, box, r"parameter 'Model/Materials/copper/Yield Stress': is missing: 'J2 plasticity' needs the "
                           r"initial yield stress")


def case_hexadecimal_in_flow_curve(choc, box):
    def edit(r):
        remove_keys(r, "Model/Materials/copper", ("Yield Stress", "Hardening Modulus"))
        set_value(r, "Model/Materials/copper/Flow Curve", "0 0x10 1 500e6")
    material_deck(box, edit)
    refused_run(choc, box, r"parameter 'Model/Materials/copper/Flow Curve' = '0 0x10 1 500e6': '0x10' is not a number")


# --- degenerate elements -------------------------------------------------------------------------

def hex_node_coordinates(lines):
    """node tag -> the index of its coordinate line in a gmsh 4.1 $Nodes section."""
    where = {}
    i = lines.index("$Nodes") + 2
    while lines[i] != "$EndNodes":
        count = int(lines[i].split()[3])
        tags = [int(t) for t in lines[i + 1:i + 1 + count]]
        for k, t in enumerate(tags):
            where[t] = i + 1 + count + k
        i += 1 + 2 * count
    return where


def volumes_only(lines):
    """The $Elements section of a gmsh 4.1 mesh without its surface blocks (the side groups)."""
    i = lines.index("$Elements")
    end = lines.index("$EndElements")
    blocks, k = [], i + 2
    while k < end:
        dim, tag, etype, count = (int(x) for x in lines[k].split())
        if dim == 3:
            blocks.append(lines[k:k + 1 + count])
        k += count + 1
    tags = [int(b.split()[0]) for blk in blocks for b in blk[1:]]
    head = "%d %d %d %d" % (len(blocks), len(tags), min(tags), max(tags))
    return lines[:i + 1] + [head] + [l for blk in blocks for l in blk] + lines[end:]


def case_hexahedron_with_a_repeated_node(choc, box):
    """A wedge written as a HEX8: its third corner's id is its second's (the mesh without side
    groups, whose faces would no longer match)."""
    lines = volumes_only(open(os.path.join(INPUTS, "two_boxes.msh")).read().split("\n"))
    i = lines.index("$Elements") + 2
    n = lines[i + 1].split()
    lines[i + 1] = " ".join(n[:3] + [n[2]] + n[4:])
    open(box.path("two_boxes.msh"), "w").write("\n".join(lines))
    def edit(r):
        model = find(r, "Model")
        model.remove(find(r, "Model/Dirichlet"))
        drop = find(r, "Analyses/drop")
        for c in list(drop):
            if c.get("name") in ("History", "Initial Conditions"):
                drop.remove(c)
    deck(os.path.join(INPUTS, "two_boxes.xml"), box.path("input.xml"), edit)
    text = open(box.path("input.xml")).read().replace(os.path.join(INPUTS, "two_boxes.msh"), "two_boxes.msh")
    open(box.path("input.xml"), "w").write(text)
    rc, out, err = run(choc_cmd(choc, "check", box.path("input.xml")), box.dir)
    expect_error(rc, err, 1, r"block 'lower', element [0-9]+ \(HEX8\): node [0-9]+ appears twice in its connectivity")


def case_hexahedron_with_coincident_corners(choc, box):
    """Two corners of the first HEX8 at one place (its second corner moved onto its first)."""
    lines = open(os.path.join(INPUTS, "two_boxes.msh")).read().split("\n")
    i = lines.index("$Elements") + 2
    while int(lines[i].split()[2]) != 5:
        i += int(lines[i].split()[3]) + 1
    first, second = (int(t) for t in lines[i + 1].split()[1:3])
    where = hex_node_coordinates(lines)
    lines[where[second]] = lines[where[first]]
    open(box.path("two_boxes.msh"), "w").write("\n".join(lines))
    ET.parse(os.path.join(INPUTS, "two_boxes.xml")).write(box.path("input.xml"))
    rc, out, err = run(choc_cmd(choc, "check", box.path("input.xml")), box.dir)
    expect_error(rc, err, 1, r"block 'lower', element [0-9]+ \(HEX8\): (corners [0-9] and [0-9] .* are at one place|"
                             r"degenerate or folded)")
    check("Merge Coincident Nodes" not in out, "the coincident-node warning suggests merging:\n" + out)


# --- warnings the docs promise -------------------------------------------------------------------

def case_plasticity_on_tet4(choc, box):
    """J2 plasticity on TET4, which the docs say never to do: a warning naming the block."""
    src = os.path.join(ROOT, "input", "patch_test.xml")  # its lower block is TET4
    def edit(r):
        mats = find(r, "Model/Materials")
        for m in mats:
            set_value(r, "Model/Materials/%s/Model" % m.get("name"), "J2 plasticity")
            set_value(r, "Model/Materials/%s/Yield Stress" % m.get("name"), "250e6", "double")
    deck(src, box.path("input.xml"), edit)
    rc, out, err = run(choc_cmd(choc, "check", box.path("input.xml")), box.dir)
    check(re.search(r"choc: warning: .*block '[^']+' is plastic \('J2 plasticity'\) on TET4 elements, which lock", out),
          "no TET4 plasticity warning (exit %s):\n%s%s" % (rc, out, err))


def case_hourglass_coefficient_one(choc, box):
    """Hourglass Coefficient = 1 on the one-point Taylor bar: the hourglass energy passes 10 % of
    the material's; a warning, and a failed check (exit 3)."""
    def edit(r):
        set_value(r, "Model/Blocks/BAR/Formulation", "one-point")
        set_value(r, "Model/Blocks/BAR/Hourglass Coefficient", "1", "double")
        set_value(r, "Analyses/impact/End Time", "3e-5", "double")
    taylor_3d(box, edit)
    rc, out, err = run_choc(choc, box)
    check(rc == 3, "exit %s, expected 3 (a failed check): %s" % (rc, err))
    check(re.search(r"warning: .*hourglass energy [0-9.]+ % of the strain and plastic energy", out), "no warning:\n" + out)
    rows = open(os.path.join(box.out, "checks.csv")).read()
    check(re.search(r"energy:hourglass / \(energy:strain \+ energy:plastic\), largest.*NOOK", rows), rows)


def case_hourglass_default_quiet(choc, box):
    """The default coefficient on the same bar: no hourglass warning, exit 0."""
    def edit(r):
        set_value(r, "Model/Blocks/BAR/Formulation", "one-point")
        set_value(r, "Analyses/impact/End Time", "3e-5", "double")
    taylor_3d(box, edit)
    rc, out, err = run_choc(choc, box)
    check(rc == 0, "exit %s: %s" % (rc, err))
    check("hourglass energy" not in out, "an hourglass warning at the default coefficient:\n" + out)


def johnson_cook_deck(box, edit):
    def both(r):
        set_value(r, "Analyses/impact/End Time", "1e-5", "double")
        edit(r)
    return deck(os.path.join(ROOT, "input", "taylor_bar_johnson_cook_axisymmetric.xml"), box.path("input.xml"), both)


def case_johnson_cook_melting(choc, box):
    """A melting temperature 30 K above T0: points reach it; one log line with the count, the
    first element and the time."""
    johnson_cook_deck(box, lambda r: set_value(r, "Model/Materials/42CrMo4/Melting Temperature", "50", "double"))
    rc, out, err = run_choc(choc, box)
    check(re.search(r"warning: [0-9]+ Johnson-Cook point\(s\) reached the melting temperature at t = [0-9.e+-]+ s, "
                    r"the first in element [0-9]+ of block 'BAR'", out), "no melting line (exit %s):\n%s%s" % (rc, out, err))


def case_johnson_cook_return_map_failure(choc, box):
    """A return map that cannot converge (reference rate 1e-300, C = 10): the message names the law
    and the parameters that drive it."""
    def edit(r):
        set_value(r, "Model/Materials/42CrMo4/Reference Strain Rate", "1e-300", "double")
        set_value(r, "Model/Materials/42CrMo4/Johnson-Cook C", "10", "double")
    johnson_cook_deck(box, edit)
    rc, out, err = run_choc(choc, box)
    expect_error(rc, err, 2, r"Johnson-Cook flow stress \(A = .*Reference Strain Rate = 1e-300.*did not converge.*"
                             r"'Johnson-Cook C', 'Reference Strain Rate'")


# --- failed runs report fully -------------------------------------------------------------------

def case_disk_full_at_impact_statistics(choc, box):
    """The disk fills while the impact statistics are written at the end (no checkpoint): their
    whole rows are kept as .incomplete.csv, the complete files keep their names."""
    library = os.environ.get("CHOC_DISK_FULL_LIBRARY", "")
    check(os.path.exists(library), "CHOC_DISK_FULL_LIBRARY is not the fault library: %r" % library)
    deck(os.path.join(ROOT, "input", "sdnv100_shock_springs.xml"), box.path("input.xml"))  # 92 impacts
    reference = box.path("reference")
    rc, _, err = run(choc_cmd(choc, "run", box.path("input.xml"), "-o", reference), box.dir)
    check(rc == 0, "reference run: exit %s: %s" % (rc, err))
    impacts = sorted(f for f in os.listdir(reference) if f.endswith(".impacts.csv"))
    check(impacts, "the reference run wrote no impact statistics: %s" % os.listdir(reference))
    largest = max(impacts, key=lambda f: os.path.getsize(os.path.join(reference, f)))  # the most rows
    name = largest[:-len(".impacts.csv")]
    size = os.path.getsize(os.path.join(reference, largest))
    env = {"LD_PRELOAD": library, "CHOC_DISK_FULL_DIR": os.path.abspath(box.out) + "/",
           "CHOC_DISK_FULL_TRIGGER": name + ".impacts.csv.part", "CHOC_DISK_FULL_AFTER": str(size // 2)}
    rc, out, err = run_choc(choc, box, env=env)
    expect_error(rc, err, 2, r"^choc: output failure: .*(No space left on device|disk full)")
    kept = os.path.join(box.out, name + ".impacts.incomplete.csv")
    check(os.path.exists(kept), "no %s: %s" % (kept, sorted(os.listdir(box.out))))
    rows = open(kept).read()
    whole = open(os.path.join(reference, largest)).read()
    check(rows.endswith("\n") and whole.startswith(rows) and 1 < rows.count("\n") < whole.count("\n"),
          "the kept rows are not the first whole rows of the statistics:\n" + rows)
    for f in (name + ".exo", name + ".history.csv"):
        check(os.path.exists(os.path.join(box.out, f)), "a complete file lost its name: %s" % sorted(os.listdir(box.out)))


def case_sigterm_to_mpirun(choc, box):
    """SIGTERM to mpirun on 2 ranks: every rank stops cleanly (the checkpoint, the incomplete files)
    and the summary says 143 and 'interrupted'; mpirun itself exits with Open MPI's own non-zero
    status (1), not 143: documented, scripts read the summary (docs/user-guide/errors.md)."""
    import signal
    import subprocess
    import time
    deck(os.path.join(ROOT, "input", "taylor_bar_3d.xml"), box.path("input.xml"))
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none", "--mca", "mpi_yield_when_idle", "1",
           "-np", "2", choc, "run", box.path("input.xml"), "-o", box.out]
    p = subprocess.Popen(cmd, cwd=box.dir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    started = time.time()
    while time.time() - started < 120:  # until the transient has begun (its first progress line)
        time.sleep(0.5)
        if os.path.exists(os.path.join(box.out, "impact.history.csv.part")):
            break
    time.sleep(1.0)
    p.send_signal(signal.SIGTERM)
    out, err = p.communicate(timeout=120)
    check(p.returncode != 0, "mpirun exit 0 after SIGTERM")
    s = summary(box, "impact")
    check(s["status"] == "interrupted" and s["exit_code"] == 143, "summary %s, exit %s" % (s["status"], s["exit_code"]))
    check("SIGTERM received: transient 'impact' stopped at t = " in err, "no clean-stop line: %s" % err)
    check(os.path.exists(os.path.join(box.out, "impact.checkpoint")), "no checkpoint: %s" % os.listdir(box.out))


CASES = {name[len("case_"):]: fn for name, fn in globals().items() if name.startswith("case_")}


if __name__ == "__main__":
    sys.exit(run_cases(CASES, "wrong_answers.py"))
