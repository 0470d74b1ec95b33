#!/usr/bin/env python3
"""A large-deflection cantilever (docs/verification/elastica.md): a neo-Hookean beam modelled
with solids, L = 1 m, square section h = 20 mm (L / h = 50), nu = 0, clamped at x = 0 and bent
by a dead end force P = 10 EI / L^2 at 135 degrees from its axis (backwards and up), grown
quasi-statically (input/elastica_beam.xml: HHT, 200 steps of 0.2 s, 650 periods of the first
mode per ramp). The tip turns through 101 degrees at half the force and 122 degrees at the full
force. The reference is tools/oracles/elastica.py: Reissner's geometrically exact beam with the
section's EI, EA and kGA (Euler's elastica when EA and kGA are infinite), solved by shooting
and itself checked here against the elastica's closed forms (an end moment: a circle; a force
normal to the axis: the first integral; a small force: Timoshenko's deflection).

Checked on two mesh series (meshes/elastica_beam.geo by gmsh; 2 layers through the thickness,
1 across): HEX20 with 8, 16, 32 elements along, TET10 with 16, 32, 64:
  - the oracle agrees with each closed form to 1e-9 of L;
  - every run completes (exit 0, the energy balance within the monitor's band) and ends at rest:
    the kinetic energy at most 1e-6 of the strain energy (a quasi-static solution);
  - the tip's position converges: the observed order of the successive differences of the
    series is at least 2 (quadratic elements; displacements converge at order 3 when smooth);
  - the finest mesh's tip is within E_mesh + E_beam of the reference at 101 and 122 degrees,
    with E_mesh twice the Richardson estimate (the last difference / (2^p - 1)) and E_beam =
    2 (h/L)^2 |u_tip| the size of what beam theory leaves out of a solid of slenderness L / h
    (the load's end distribution, the section's warping, the (kappa h)^2 terms of a finite
    strain): a wrong EI, a missing rotation term or a load that followed the beam would each
    move the tip by 1e-2 L and more.
The figure shows the deformed centre lines of the oracle, the tip's path of the finest meshes
along the ramp, and the convergence of the tip's error.
usage: elastica.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
sys.path.insert(0, os.path.join(src, "tools", "oracles"))
import chocrun  # noqa: E402
import elastica  # noqa: E402

L, H, E, ANGLE, K, RAMP = 1.0, 0.02, 2e11, math.radians(135.0), 10.0, 40.0
EI, EA, KGA = E * H ** 4 / 12, E * H * H, 5.0 / 6.0 * (E / 2) * H * H  # nu = 0: G = E / 2
P = K * EI / L ** 2
FORCE = (P * math.cos(ANGLE), P * math.sin(ANGLE))
CHECK_TIMES = (20.0, 40.0)  # half and full force
os.makedirs(work, exist_ok=True)
failures = []

for name, err in elastica.closed_form_checks().items():
    print(f"oracle against the closed form, {name}: {err:.2e}")
    if not err <= 1e-9:
        failures.append(f"oracle: {err:.2e} from the closed form ({name})")

beam = elastica.Beam(L, EI, EA, KGA)
euler = elastica.Beam(L, EI)
fractions = [t / RAMP for t in CHECK_TIMES]
reference = beam.ramp(FORCE, 0.0, fractions, substeps=20)
inextensible = euler.ramp(FORCE, 0.0, fractions, substeps=20)
for t, (x, y, th), (xe, ye, _) in zip(CHECK_TIMES, reference, inextensible):
    print(f"reference at t = {t:g} s: tip ({x:.6f}, {y:.6f}) m, turned {math.degrees(th):.2f} degrees "
          f"(Euler's elastica: ({xe:.6f}, {ye:.6f}))")


def end_face_nodes(msh):
    """The nodes of the end face x = L in a gmsh 4.1 ASCII file (the force is shared by them)."""
    lines = open(msh).read().split("\n")
    i = lines.index("$Nodes") + 1
    blocks = int(lines[i].split()[0])
    i += 1
    count = 0
    for _ in range(blocks):
        n = int(lines[i].split()[3])
        i += 1 + n  # the block's header and node tags
        count += sum(abs(float(lines[i + k].split()[0]) - L) < 1e-9 for k in range(n))
        i += n
    return count


def run(kind, nx):
    label = f"{kind}_nx{nx}"
    msh = chocrun.gmsh("elastica_beam.geo", os.path.join(work, label + ".msh"), 3, "-order", 2,
                       "-setnumber", "nx", nx, "-setnumber", "hex", 1 if kind == "HEX20" else 0)
    nodes = end_face_nodes(msh)
    d = chocrun.load_deck(os.path.join(src, "input", "elastica_beam.xml"))
    chocrun.set_params(d, {"Mesh/File": msh, "Analyses/bend/Exodus Interval": 0,
                           "Analyses/bend/Nodal Forces/end force x/Value": FORCE[0] / nodes,
                           "Analyses/bend/Nodal Forces/end force y/Value": FORCE[1] / nodes})
    out = os.path.join(work, label)
    chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, label + ".xml")), out)
    s = chocrun.require_completed(chocrun.read_summary(out, "bend"))
    h = chocrun.read_history(out, "bend")
    kinetic, strain = h["energy:kinetic"][-1], h["energy:strain"][-1]
    print(f"{label}: {chocrun.summary_value(s, 'unknowns')} unknowns, {nodes} end-face nodes, "
          f"{chocrun.summary_value(s, 'newton')['iterations']} Newton iterations in {len(h['time']) - 1} steps, "
          f"{chocrun.summary_value(s, 'wall_seconds'):.1f} s; kinetic {kinetic:.2e} J, strain {strain:.6g} J, "
          f"balance {h['energy:balance'][-1]:.2e} J")
    if not kinetic <= 1e-6 * strain:
        failures.append(f"{label}: kinetic energy {kinetic:.2e} J at the end (at most 1e-6 of {strain:.4g} J)")
    return h


def tips(h):
    """The tip's position (x, y) at each check time."""
    out = []
    for t in CHECK_TIMES:
        k = int(np.argmin(np.abs(h["time"] - t)))
        out.append(np.array([L + h["TIP:DX"][k], h["TIP:DY"][k]]))
    return out


def series(kind, levels):
    runs = [run(kind, nx) for nx in levels]
    pos = [tips(h) for h in runs]
    errors = []
    for c, (t, ref) in enumerate(zip(CHECK_TIMES, reference)):
        r = np.array(ref[:2])
        err = [float(np.linalg.norm(p[c] - r)) for p in pos]
        diffs = [float(np.linalg.norm(pos[i + 1][c] - pos[i][c])) for i in range(len(pos) - 1)]
        order = math.log2(diffs[-2] / diffs[-1])
        estimate = diffs[-1] / (2 ** order - 1)
        budget = 2 * estimate + 2 * (H / L) ** 2 * float(np.linalg.norm(r - [L, 0.0]))
        euler_err = float(np.linalg.norm(pos[-1][c] - np.array(inextensible[c][:2])))
        print(f"{kind} at {math.degrees(ref[2]):.0f} degrees: tip errors {', '.join(f'{e:.2e}' for e in err)} m "
              f"(nx = {', '.join(map(str, levels))}); successive differences "
              f"{', '.join(f'{e:.2e}' for e in diffs)}, observed order {order:.2f}; finest {err[-1]:.2e} "
              f"within {budget:.2e} (Richardson {estimate:.2e}); against Euler's elastica {euler_err:.2e}")
        if not order >= 2.0:
            failures.append(f"{kind} at t = {t:g} s: observed order {order:.2f} (at least 2)")
        if not err[-1] <= budget:
            failures.append(f"{kind} at t = {t:g} s: tip {err[-1]:.2e} m from the reference (at most {budget:.2e})")
        errors.append(err)
    return runs, errors


hex_levels, tet_levels = (8, 16, 32), (16, 32, 64)
hex_runs, hex_errors = series("HEX20", hex_levels)
tet_runs, tet_errors = series("TET10", tet_levels)


def plot(path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.6), gridspec_kw={"width_ratios": [1.35, 1]})
    guess = None
    done = 0.0
    for f in (0.25, 0.5, 0.75, 1.0):
        for k in range(1, 11):
            g = done + (f - done) * k / 10
            *_, guess = beam.solve((g * FORCE[0], g * FORCE[1]), 0.0, guess)
        done = f
        path_ = beam.integrate(guess, (f * FORCE[0], f * FORCE[1]), record=True)
        xs, ys = [p[0] for p in path_], [p[1] for p in path_]
        ax.plot(xs, ys, "k-", lw=1)
        ax.annotate(f"{f:.2g} P", (xs[-1], ys[-1]), textcoords="offset points", xytext=(4, 4), fontsize=8)
    for h, mark, lab in ((hex_runs[-1], "-", f"choc HEX20, {hex_levels[-1]} along: tip path"),
                         (tet_runs[-1], "--", f"choc TET10, {tet_levels[-1]} along: tip path")):
        ax.plot(L + h["TIP:DX"], h["TIP:DY"], mark, lw=1.5, label=lab)
    ax.plot([], [], "k-", lw=1, label="reference centre lines (Reissner beam)")
    ax.arrow(reference[-1][0], reference[-1][1], 0.12 * math.cos(ANGLE), 0.12 * math.sin(ANGLE),
             head_width=0.02, color="r")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("Cantilever under a dead end force at 135 degrees")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower left", fontsize=8)
    for levels, errors, mark, lab in ((hex_levels, hex_errors, "o-", "HEX20"), (tet_levels, tet_errors, "s--", "TET10")):
        for c, t in enumerate(CHECK_TIMES):
            bx.loglog(levels, errors[c], mark, mfc="none" if c else None,
                      label=f"{lab}, {math.degrees(reference[c][2]):.0f} degrees")
    bx.axhline(2 * (H / L) ** 2, color="gray", lw=0.8, ls=":")
    bx.annotate("2 (h/L)^2 L: beam theory's size", (hex_levels[0], 2 * (H / L) ** 2), fontsize=8,
                textcoords="offset points", xytext=(0, 4))
    bx.set_xticks(sorted(set(hex_levels + tet_levels)))
    bx.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    bx.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    bx.set_xlabel("elements along the beam")
    bx.set_ylabel("tip error against the reference [m]")
    bx.grid(alpha=0.3, which="both")
    bx.legend(fontsize=8)
    chocrun.save_figure(fig, path)


plot(os.path.join(work, "elastica.png"))
chocrun.finish(failures, "large-deflection cantilever: OK")
