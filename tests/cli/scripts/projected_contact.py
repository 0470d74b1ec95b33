#!/usr/bin/env python3
"""Lagrange contact between meshed bodies solved by CG on every rank, the multipliers projected
out (src/contact/ContactProjection.hpp): the same Newton iterates as the saddle-point system
solved directly, to the solvers' tolerances.
  - The scale scene's bars at 9,648 unknowns (the kept-factorisation scene: 100 steps, the
    contact nodes opening and closing at each of several impacts): Direct (the saddle point)
    against CG + Jacobi and CG + Multigrid (projected), and CG + Jacobi on 2 ranks. The histories
    agree to 1e-7 of each peak (Newton's test holds each iterate to 1e-8 of the force scale, the
    bound kept_factorization.py uses for the same scene), with the same number of impacts; the
    log says the pressures are projected out; the preconditioner is W's, so a change of contact
    status builds none: at most 2 set-ups (the initial acceleration's and the steps') where the
    direct run factors at every change.
  - The same bars with Coulomb friction (mu = 0.1) and bar 1 also moving sideways at 0.5 m/s, so
    that the contact nodes slide (the tangential force is mu times the normal force): the oblique
    projection P_L = I - V (C^T V)^-1 C^T, GMRES + Jacobi on 1 and 2 ranks against Direct, the
    first 30 steps (two impacts), to 1e-7 of each peak, friction's force and work included, and in
    as many Newton iterations as the direct run, one more at most (a projection that ignores
    friction's multiplier columns converges to the same states through an inexact tangent: more
    iterations, 7 % more over 100 steps).
  - SDNL111 on non-matching meshes (input/sdnl111_nonmatching.xml: TET4 slave nodes inside the
    HEX8 master faces, so C^T C couples the constraints; node to face and mortar, whose columns
    span several slave nodes; the followed search re-linearises every step): the input's Direct
    against CG + Jacobi, to 1e-7 of each peak, and its 9 checks pass; its node-to-face analysis by
    CG + Jacobi on the mesh renumbered (chocrun.renumbered_mesh) equals the drawn one to 1e-8 of
    each peak (Newton's relative tolerance; the order of the sums changes).
  - The sparse factorisation of G and C^T V (ReplicatedSparseLU, used from 300 active
    constraints) forced from the first (CHOC_TEST_SPARSE_GRAM_FROM=1): the bars by CG + Jacobi,
    the sliding bars by GMRES on 1 and 2 ranks (C^T V's friction entries gathered from both) and
    the non-matching meshes, against Direct to the same bounds; and the renumbered mesh against the
    drawn one on that path too.
usage: projected_contact.py CHOC SOURCE_DIR WORK_DIR"""
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from scale_bars import bars_3_100, run_deck  # noqa: E402

choc, src, work, mesh = bars_3_100()
sys.path.insert(0, os.path.join(src, "tools", "lib"))
sys.path.insert(0, os.path.join(src, "tools", "bench"))
import chocrun  # noqa: E402
from bench_kept_factorization import scene_deck  # noqa: E402  (the benchmark's scene)

PROJECTED = "projected out of the Newton system"
SPARSE = {"CHOC_TEST_SPARSE_GRAM_FROM": "1"}  # G and C^T V factored sparse from one active constraint
failures = []


def deck(method, preconditioner=None, budget=0, friction=0.0):
    d = scene_deck(mesh, budget)
    an = "Analyses/" + chocrun.only_analysis(d)
    if friction:
        chocrun.set_param(d, f"{an}/Contact/Pairs/interface/Friction Coefficient", friction, create=True)
        chocrun.set_param(d, f"{an}/End Time", 3e-5)
        ic = an + "/Initial Conditions/bar 1 slides"
        for key, value in (("Node Set", "POU1"), ("Field", "Velocity"), ("Components", "DX")):
            chocrun.set_param(d, f"{ic}/{key}", value, create=True)
        chocrun.set_param(d, f"{ic}/Value", 0.5, type="double", create=True)
    chocrun.set_param(d, f"{an}/Linear Solver/Method", method)
    if method != "Direct":
        chocrun.remove_param(d, f"{an}/Linear Solver/Update Budget", missing_ok=True)
        chocrun.set_param(d, f"{an}/Linear Solver/Preconditioner", preconditioner, create=True)
    return chocrun.deck_text(d)


def figures(log):
    return (int(re.search(r"(\d+) factorisations", log).group(1)),
            int(re.search(r"impacts of 'interface': (\d+)", log).group(1)))


def compare(a, b, columns, label, tolerance=1e-7):
    d = chocrun.history_difference(chocrun.read_history(a), chocrun.read_history(b), columns)
    worst = max(d.values())
    print(f"{label}: largest difference {worst:.2e} of a peak ({', '.join(f'{k} {v:.1e}' for k, v in d.items())})")
    if not worst <= tolerance:
        failures.append(f"{label}: the histories differ by {worst:.2e} of a peak (bound {tolerance:g})")


def bars():
    columns = ["A:DZ", "A:VZ", "C:DZ", "interface:force", "energy:total"]
    direct = figures(run_deck(choc, work, "direct", deck("Direct")))
    print(f"Direct: {direct[0]} factorisations, {direct[1]} impacts")
    for name, prec, ranks, env in (("cg_jacobi", "Jacobi", 1, None), ("cg_multigrid", "Multigrid", 1, None),
                                   ("cg_jacobi_np2", "Jacobi", 2, None), ("cg_jacobi_sparse", "Jacobi", 1, SPARSE)):
        log = run_deck(choc, work, name, deck("CG", prec), ranks, env)
        f, impacts = figures(log)
        print(f"{name}: {f} preconditioner set-ups, {impacts} impacts")
        if PROJECTED not in log:
            failures.append(f"{name}: the log does not say the pressures are projected out")
        if impacts != direct[1]:
            failures.append(f"{name}: {impacts} impacts against the direct run's {direct[1]}")
        if f > 2:
            failures.append(f"{name}: {f} preconditioner set-ups (a change of contact status must build none)")
        compare(os.path.join(work, "direct", "impact.history.csv"), os.path.join(work, name, "impact.history.csv"),
                columns, f"bars, {name} against Direct")


def sliding():
    columns = ["A:DZ", "A:DX", "C:DZ", "interface:force", "interface:tangential_force", "interface:friction_work",
               "energy:total"]
    newton = lambda name: chocrun.summary_value(chocrun.read_summary(os.path.join(work, name), "impact"),  # noqa: E731
                                                "newton/iterations")
    run_deck(choc, work, "friction_direct", deck("Direct", friction=0.1))
    h = chocrun.read_history(os.path.join(work, "friction_direct", "impact.history.csv"))
    ratio = max(abs(h["interface:tangential_force"])) / max(abs(h["interface:force"]))
    print(f"friction: the largest tangential force over the largest normal force {ratio:.4f} (mu = 0.1)")
    if not abs(ratio - 0.1) <= 1e-3:
        failures.append(f"friction: the nodes do not slide (tangential over normal force {ratio:.4f}, mu = 0.1)")
    for name, ranks, env in (("friction_gmres", 1, None), ("friction_gmres_np2", 2, None),
                             ("friction_gmres_sparse", 1, SPARSE), ("friction_gmres_sparse_np2", 2, SPARSE)):
        log = run_deck(choc, work, name, deck("GMRES", "Jacobi", friction=0.1), ranks, env)
        if PROJECTED not in log:
            failures.append(f"{name}: the log does not say the pressures are projected out")
        compare(os.path.join(work, "friction_direct", "impact.history.csv"),
                os.path.join(work, name, "impact.history.csv"), columns, f"sliding bars, {name} against Direct")
        print(f"{name}: {newton(name)} Newton iterations, Direct {newton('friction_direct')}")
        if newton(name) > newton("friction_direct") + 1:
            failures.append(f"{name}: {newton(name)} Newton iterations against Direct's {newton('friction_direct')}")


def nonmatching():
    d = chocrun.load_deck(chocrun.input_path("sdnl111_nonmatching.xml"))
    for an in chocrun.analyses(d):
        assert chocrun.get_param(d, f"Analyses/{an}/Linear Solver/Method") == "Direct"
    direct = os.path.join(work, "nonmatching_direct")
    chocrun.run(choc, chocrun.input_path("sdnl111_nonmatching.xml"), direct)
    for an in chocrun.analyses(d):
        chocrun.set_param(d, f"Analyses/{an}/Linear Solver/Method", "CG")
        chocrun.set_param(d, f"Analyses/{an}/Linear Solver/Preconditioner", "Jacobi", create=True)
    for name, env in (("nonmatching_cg", None), ("nonmatching_cg_sparse", SPARSE)):
        log = run_deck(choc, work, name, chocrun.deck_text(d), env=env)
        if log.count(PROJECTED) != 2:
            failures.append(f"{name}: the log does not say both analyses' pressures are projected out")
        m = re.search(r"(\d+) checks, (\d+) NOOK", log)
        if not m or m.group(2) != "0":
            failures.append(f"{name}: its checks do not all pass")
        for an in chocrun.analyses(d):
            compare(chocrun.history_path(direct, an), chocrun.history_path(os.path.join(work, name), an),
                    ["N1:DZ", "interface:force", "energy:total"], f"non-matching '{an}', {name} against Direct")


def renumbered(env=None, tag=""):
    renum = os.path.join(work, "renumbered.msh")
    chocrun.renumbered_mesh(os.path.join(src, "meshes", "sdnl111_nonmatching.msh"), renum)
    for name, mesh in (("drawn", os.path.join(src, "meshes", "sdnl111_nonmatching.msh")), ("renumbered", renum)):
        d = chocrun.load_deck(os.path.join(src, "tests", "restart", "inputs", "sdnl111_nonmatching_projected.xml"))
        chocrun.set_param(d, "Mesh/File", mesh)
        run_deck(choc, work, f"numbering_{name}{tag}", chocrun.deck_text(d), env=env)
    compare(chocrun.history_path(os.path.join(work, "numbering_drawn" + tag), "lagrange"),
            chocrun.history_path(os.path.join(work, "numbering_renumbered" + tag), "lagrange"),
            ["N1:DZ", "interface:force", "energy:total"], f"non-matching{tag}, renumbered against drawn", 1e-8)


bars()
sliding()
nonmatching()
renumbered()
renumbered(SPARSE, "_sparse")  # the sparse factorisation orders G itself: the numbering must not show
if failures:
    sys.exit("projected_contact: " + "; ".join(failures))
print("projected_contact: OK")
