#!/usr/bin/env python3
"""Frame invariance of a contact scene (docs/verification/properties.md): SDNV100 or the sliding block
turned as a rigid whole.

usage: tools/oracles/frame_invariance.py [--scene sdnv100|sdnv100_springs|sliding] [--friction MU]
                                         [--build DIR] [--out DIR] [--angle RAD] [--axis X Y Z]
                                         [--tolerance T] [--cost-tolerance C] [--energy-tolerance E]
                                         [--explicit] [--mortar]

Runs input/sdnv100.xml twice with every displacement component free (nu = 0, so the wave stays
1D): once as drawn, once with the bar, its initial velocity and the wall turned by the rotation
R (angle about axis, through the origin; the mesh made by gmsh from meshes/sdnv100_bar.geo with
the turned section and extrusion). The motion of N5 and N100 seen in the turned frame, R^T u,
must equal the unturned motion to TOL times the peak displacement (default 1e-8), the wall
force likewise, the cost (Newton iterations, factorisations: each analysis's summary.json)
must agree within C (default 10%), and no run's energy balance may rise above E (default 1e-3, the +0.1% of docs/verification/properties.md) times E0
at the default contact mass. Exit 0 when it holds, 1 otherwise (naming what differs). `ctest -R frame_invariance`.

--scene sdnv100_springs: input/sdnv100_shock_springs.xml (SDNV100 (f): 4 shock links on a fixed
PLAN_Z through 'Obstacle Origin', central differences), every component free, the bar, its
velocity and the plane (origin, and the links' Axis and Twist so that the plane's normal turns
with the scene) turned; compared: N5's and N100's motion, the force of link wall.1, the steps.

--scene sliding: input/sliding.xml (the block pushed across the foundation, search in the
current configuration), its mesh turned (meshes/sliding_blocks.geo), the block's velocity and
the pressure's nodal forces turned; compared: the motion of the block's corner, the contact
force, the cost. The contact pressures and slips of every node are compared too (same
numbering), to the same tolerance of their peaks. --mortar runs its pair in mortar.
"""
import argparse
import math
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

TOP = chocrun.TOP
LENGTH = 0.2


def rotation(angle, axis):
    k = np.asarray(axis, float)
    k /= np.linalg.norm(k)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx


def vec(v):
    return " ".join(repr(float(x)) for x in v)


def drop_analysis(s, name):
    """The input text without analysis `name` (its sublist under Analyses)."""
    start = s.index(f'<ParameterList name="{name}">')
    comment = s.rfind("<!--", 0, start)
    if comment >= 0 and s[s.rfind("-->", 0, start) + 3 if s.rfind("-->", 0, start) > comment else comment:start].strip() == "":
        start = comment  # and the comment that introduces it
    depth, k = 0, start
    for m in re.finditer(r"<ParameterList[^>]*?(/?)>|</ParameterList>", s[start:]):
        if m.group(0).startswith("</"):
            depth -= 1
        elif not m.group(1):
            depth += 1
        if depth == 0:
            k = start + m.end()
            break
    return s[:start] + s[k:]


def deck(mesh, R, explicit=False):
    """input/sdnv100.xml with every component free, turned by R, without its checks; with
    `explicit`, the lumped mass, and the penalty (a_penalty) and Lagrange (lagrange, forward
    increments) runs by central differences; the continuous one, which needs pressure unknowns,
    left out."""
    s = open(os.path.join(TOP, "input", "sdnv100.xml")).read()
    if explicit:
        s = s.replace('<Parameter name="Material" type="string" value="steel"/>',
                      '<Parameter name="Material" type="string" value="steel"/>\n'
                      '        <Parameter name="Mass" type="string" value="lumped"/>')
        s = re.sub(r'<Parameter name="Scheme" type="string" value="Newmark"/>\s*'
                   r'<Parameter name="Beta" type="double" value="0.28"/>\s*'
                   r'<Parameter name="Gamma" type="double" value="0.55"/>',
                   '<Parameter name="Scheme" type="string" value="central differences"/>\n'
                   '      <Parameter name="Stability Check" type="string" value="substep"/>', s)
        s = drop_analysis(s, "c_continuous")
        assert "central differences" in s
    if LINEAR[0]:  # every analysis by this Krylov method (obstacle contact: pressures condensed)
        s = s.replace('<Parameter name="Method" type="string" value="Direct"/>',
                      f'<Parameter name="Method" type="string" value="{LINEAR[0][0]}"/>\n'
                      f'        <Parameter name="Preconditioner" type="string" value="{LINEAR[0][1]}"/>')
    s = s.replace('value="../meshes/sdnv100_bar.msh"', f'value="{mesh}"')
    s = s.replace('<Parameter name="Active Components" type="string" value="DZ"/>',
                  '<Parameter name="Active Components" type="string" value="DX DY DZ"/>')
    s = s.replace('value="0 0 -0.002"', f'value="{vec(R @ [0, 0, -0.002])}"')
    s = s.replace('<Parameter name="Normal" type="string" value="0 0 1"/>',
                  f'<Parameter name="Normal" type="string" value="{vec(R @ [0, 0, 1])}"/>')
    v = R @ [0, 0, -100.0]
    ic = "".join(f'''<ParameterList name="v{c}">
          <Parameter name="Node Set" type="string" value="BAR"/>
          <Parameter name="Field" type="string" value="Velocity"/>
          <Parameter name="Components" type="string" value="D{c}"/>
          <Parameter name="Value" type="double" value="{v[i]!r}"/>
        </ParameterList>''' for i, c in enumerate("XYZ"))
    s = re.sub(r'<ParameterList name="the bar falls at 100 m/s">.*?</ParameterList>', ic, s,
               flags=re.S)
    s = s.replace('value="N5:DZ N5:VZ N100:DZ N100:VZ"',
                  'value="N5:DX N5:DY N5:DZ N100:DX N100:DY N100:DZ"')
    s = re.sub(r'<ParameterList name="Checks">.*?\n      </ParameterList>\n', '', s, flags=re.S)
    return s


def components(name, node_set, field, vector):
    """Sublists giving `vector` to node_set, one per component (initial conditions or forces)."""
    out = ""
    for i, c in enumerate("XYZ"):
        if field == "force":
            out += f'''<ParameterList name="{name} {c}">
          <Parameter name="Node Set" type="string" value="{node_set}"/>
          <Parameter name="Component" type="string" value="D{c}"/>
          <Parameter name="Value" type="double" value="{vector[i]!r}"/>
        </ParameterList>'''
        else:
            out += f'''<ParameterList name="{name} {c}">
          <Parameter name="Node Set" type="string" value="{node_set}"/>
          <Parameter name="Field" type="string" value="Velocity"/>
          <Parameter name="Components" type="string" value="D{c}"/>
          <Parameter name="Value" type="double" value="{vector[i]!r}"/>
        </ParameterList>'''
    return out


def sliding_deck(mesh, R, explicit=False):
    """input/sliding.xml turned by R (velocity and nodal forces), without its checks."""
    assert not explicit, "the sliding scene runs Lagrange contact: no explicit variant"
    s = open(os.path.join(TOP, "input", "sliding.xml")).read()
    s = s.replace('value="../meshes/sliding_blocks.msh"', f'value="{mesh}"')
    forces = ""
    for m in re.finditer(r'<ParameterList name="([^"]+)">\s*<Parameter name="Node Set" type="string" '
                         r'value="([^"]+)"/>\s*<Parameter name="Component" type="string" value="DZ"/>\s*'
                         r'<Parameter name="Value" type="double" value="([^"]+)"/>\s*</ParameterList>', s):
        forces += components(m.group(1), m.group(2), "force", R @ [0, 0, float(m.group(3))])
    assert forces.count("<ParameterList") == 9
    s = re.sub(r'(<ParameterList name="Nodal Forces">).*?(\n      </ParameterList>\n      <ParameterList name="Initial)',
               lambda m: m.group(1) + forces + m.group(2), s, flags=re.S)
    s = re.sub(r'<ParameterList name="the block is pushed at 10 m/s">.*?</ParameterList>',
               components("v", "BLOCK", "velocity", R @ [10.0, 0, 0]), s, flags=re.S)
    s = s.replace('value="BLOCK_TOP_CORNER:DX BLOCK_TOP_CORNER:DZ"',
                  'value="BLOCK_TOP_CORNER:DX BLOCK_TOP_CORNER:DY BLOCK_TOP_CORNER:DZ"')
    s = re.sub(r'<ParameterList name="Checks">.*?\n      </ParameterList>\n', '', s, flags=re.S)
    if MORTAR[0]:  # --mortar: the pair in mortar
        s = s.replace('<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>',
                      '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>\n'
                      '            <Parameter name="Discretization" type="string" value="mortar"/>')
    if FRICTION[0] > 0:  # --friction: Coulomb friction on the pair
        s = s.replace('<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>',
                      '<Parameter name="Slave Side Set" type="string" value="BLOCK_BOTTOM"/>\n'
                      f'            <Parameter name="Friction Coefficient" type="double" value="{FRICTION[0]!r}"/>')
    return s


def link_axis_and_twist(axis, normal):
    """The shock links' 'Twist' [degrees] about `axis` (unit, orthogonal to `normal`) that brings
    their frame's e3, the PLAN_Z normal, onto `normal` (src/contact/ObstacleFrame.cpp: the frame
    is Rz(alpha) Ry(beta) Rx(twist), so e3 = cos(twist) e3(0) - sin(twist) e2(0))."""
    n = np.asarray(axis, float)
    alpha, beta = math.atan2(n[1], n[0]), -math.asin(max(-1.0, min(1.0, n[2])))
    ca, sa, cb, sb = math.cos(alpha), math.sin(alpha), math.cos(beta), math.sin(beta)
    e2, e3 = np.array([-sa, ca, 0.0]), np.array([ca * sb, sa * sb, cb])
    return math.degrees(math.atan2(-np.dot(normal, e2), np.dot(normal, e3)))


def springs_deck(mesh, R, explicit=False):
    """input/sdnv100_shock_springs.xml (SDNV100 (f): nodal shock links on a fixed plane, central
    differences) with every component free, turned by R: the plane's origin and normal, the
    initial velocity; without its checks."""
    s = open(os.path.join(TOP, "input", "sdnv100_shock_springs.xml")).read()
    s = s.replace('value="../meshes/sdnv100_bar.msh"', f'value="{mesh}"')
    s = s.replace('<Parameter name="Active Components" type="string" value="DZ"/>',
                  '<Parameter name="Active Components" type="string" value="DX DY DZ"/>')
    axis = R @ [1.0, 0.0, 0.0]  # the input's Axis, 1 0 0, turned
    twist = link_axis_and_twist(axis, R @ [0.0, 0.0, 1.0])
    old = '<Parameter name="Axis" type="string" value="1 0 0"/>'
    assert old in s
    s = s.replace(old, f'<Parameter name="Axis" type="string" value="{vec(axis)}"/>\n'
                       f'          <Parameter name="Twist" type="double" value="{twist!r}"/>')
    s = s.replace('value="0 0 -0.002"', f'value="{vec(R @ [0, 0, -0.002])}"')
    s = re.sub(r'<ParameterList name="the bar falls at 100 m/s">.*?</ParameterList>',
               components("v", "BAR", "velocity", R @ [0, 0, -100.0]), s, flags=re.S)
    s = s.replace('value="N5:DZ N5:VZ N100:DZ N100:VZ"',
                  'value="N5:DX N5:DY N5:DZ N100:DX N100:DY N100:DZ"')
    s = re.sub(r'<ParameterList name="Checks">.*?\n      </ParameterList>\n', '', s, flags=re.S)
    return s


FRICTION = [0.0]  # the sliding scene's Coulomb coefficient (--friction)
MORTAR = [False]  # the sliding scene's pair in mortar (--mortar)
LINEAR = [None]  # --linear-solver (method, preconditioner)


# Per scene: its gmsh file, the extrusion the turned mesh takes, its deck, the nodes whose
# motion is compared, the contact force column.
SCENES = {
    "sdnv100": ("sdnv100_bar.geo", [0, 0, LENGTH], deck, ("N5", "N100"), "wallforce"),
    "sliding": ("sliding_blocks.geo", [0, 0, -1.0], sliding_deck, ("BLOCK_TOP_CORNER",), "slideforce"),
    "sdnv100_springs": ("sdnv100_bar.geo", [0, 0, LENGTH], springs_deck, ("N5", "N100"), "wall1force"),
}


def exodus_fields(path, names):
    import netCDF4
    with netCDF4.Dataset(path) as d:
        all_names = ["".join(c.decode() for c in n if c != b"").strip() for n in d["name_nod_var"][:]]
        return {n: np.asarray(d[f"vals_nod_var{all_names.index(n) + 1}"][:]) for n in names}


def run(a, label, R, turned):
    work = os.path.join(a.out, label)
    os.makedirs(work, exist_ok=True)
    geo, extrusion, make_deck = SCENES[a.scene][:3]
    mesh = os.path.join(work, "scene.msh")
    cmd = ["gmsh", "-3", "-format", "msh41", os.path.join(TOP, "meshes", geo), "-o", mesh]
    if turned:
        axis = np.asarray(a.axis, float)
        d = R @ extrusion
        for name, value in (("angle", a.angle), ("ax", axis[0]), ("ay", axis[1]), ("az", axis[2]),
                            ("dx", d[0]), ("dy", d[1]), ("dz", d[2])):
            cmd[2:2] = ["-setnumber", name, repr(float(value))]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    path = os.path.join(work, "scene.xml")
    text = make_deck(mesh, R, a.explicit)
    for name in re.findall(r'<ParameterList name="(\w+)">\s*<Parameter name="Type" type="string" value="Transient"/>', text):
        if a.only and name not in a.only:
            text = drop_analysis(text, name)
    with open(path, "w") as f:
        f.write(text)
    log = subprocess.run([os.path.join(a.build, "choc"), "run", path, "-o", work],
                         capture_output=True, text=True)
    if log.returncode != 0:
        sys.exit(f"frame_invariance: {label} run failed ({log.returncode}): {log.stderr.strip()}")
    cost = {}  # from each analysis's summary: implicit (Newton iterations, factorisations), explicit (steps, sub-steps)
    for name in chocrun.analyses(chocrun.parse_deck(text)):
        s = chocrun.read_summary(work, name)
        if s["type"] != "Transient":
            continue
        cost[name] = ((s["newton"]["iterations"], s["factorizations"]) if "newton" in s else
                      (s["steps"], s["substeps_per_step"]))
    runs = {}
    for name in cost:
        d = np.genfromtxt(os.path.join(work, f"{name}.history.csv"), delimiter=",", names=True)
        runs[name] = d
    return runs, cost


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scene", choices=sorted(SCENES), default="sdnv100")
    ap.add_argument("--build", default=os.path.join(TOP, "build"))
    ap.add_argument("--out", default=os.path.join(TOP, "results", "frame_invariance"))
    ap.add_argument("--angle", type=float, default=0.7)
    ap.add_argument("--axis", type=float, nargs=3, default=[1.0, 2.0, 0.5])
    ap.add_argument("--tolerance", type=float, default=1e-8)
    ap.add_argument("--cost-tolerance", type=float, default=0.10)
    ap.add_argument("--energy-tolerance", type=float, default=1e-3)
    ap.add_argument("--explicit", action="store_true",
                    help="run the penalty and Lagrange analyses by explicit central differences on "
                         "the lumped mass (the continuous one is left out)")
    ap.add_argument("--only", nargs="*", default=[],
                    help="the analyses to run and check (default: all of the scene's)")
    ap.add_argument("--friction", type=float, default=0.0,
                    help="sliding scene: Coulomb friction mu on the pair (the friction force and "
                         "work are compared too)")
    ap.add_argument("--reaction-tolerance", type=float, default=1e-5,
                    help="--friction: the friction force's tolerance, of its peak. A sticking node's "
                         "friction force is a reaction, known to Newton's residual tolerance (1e-8 of "
                         "the 6,400 N load: 6.4e-5 N per node, 28 nodes, 2.6e-6 of the 128 N peak); "
                         "a sliding node's is mu f_N, compared with the normal force")
    ap.add_argument("--linear-solver", nargs=2, metavar=("METHOD", "PRECONDITIONER"), default=None,
                    help="sdnv100 scene: every analysis by this Krylov method instead of Direct (the "
                         "contact pressures against the wall condensed out)")
    ap.add_argument("--mortar", action="store_true",
                    help="sliding scene: the pair in mortar ('Discretization' = mortar)")
    a = ap.parse_args()
    FRICTION[0] = a.friction
    MORTAR[0] = a.mortar
    LINEAR[0] = a.linear_solver
    R = rotation(a.angle, a.axis)
    ref, ref_cost = run(a, "as_drawn", np.eye(3), False)
    rot, rot_cost = run(a, "turned", R, True)
    nodes, force = SCENES[a.scene][3:]
    failures = []
    for name in ref:
        d0, d1 = ref[name], rot[name]
        for node in nodes:
            u0 = np.column_stack([d0[f"{node}D{c}"] for c in "XYZ"])
            u1 = np.column_stack([d1[f"{node}D{c}"] for c in "XYZ"]) @ R  # rows: R^T u
            peak = np.abs(u0).max()
            diff = np.abs(u1 - u0).max() / peak
            print(f"{name} {node}: max |R^T u_turned - u| = {diff:.2e} of the peak {peak:.3e} m")
            if not diff <= a.tolerance:
                failures.append(f"{name} {node} differs by {diff:.2e} of the peak")
        for label, d in (("as drawn", d0), ("turned", d1)):  # properties.md: no growth
            growth = d["energybalance"].max() / d["energytotal"][0]
            print(f"{name} {label}: largest energy balance {growth:+.2e} of E0")
            if not growth <= a.energy_tolerance:
                failures.append(f"{name} {label} energy balance {growth:+.2e} of E0")
        if name == "lagrange" and a.scene == "sdnv100":  # exact contact: no penetration
            worst = min(d0["wallgap"].min(), d1["wallgap"].min())
            print(f"{name}: smallest gap {worst:.2e} m")
            if not worst >= -1e-12 * np.abs(d0["N100DZ"]).max():
                failures.append(f"{name} penetrates the wall by {-worst:.2e} m")
        columns = [(force, "contact force", a.tolerance)]
        if a.friction > 0:
            columns += [("slidetangential_force", "friction force", a.reaction_tolerance),
                        ("slidefriction_work", "friction work", a.tolerance)]
        for column, what, tol in columns:
            f0, f1 = d0[column], d1[column]
            fdiff = np.abs(f1 - f0).max() / np.abs(f0).max()
            print(f"{name} {what}: max difference {fdiff:.2e} of the peak")
            if not fdiff <= tol:
                failures.append(f"{name} {what} differs by {fdiff:.2e} of the peak")
        if a.scene == "sliding":  # every node's pressure and slip (the same numbering)
            e0, e1 = (exodus_fields(os.path.join(a.out, w, f"{name}.exo"),
                                    ("CONTACT_PRESSURE", "CONTACT_SLIP")) for w in ("as_drawn", "turned"))
            for field in e0:
                diff = np.abs(e1[field] - e0[field]).max() / np.abs(e0[field]).max()
                print(f"{name} {field}: max difference {diff:.2e} of the peak")
                if not diff <= a.tolerance:
                    failures.append(f"{name} {field} differs by {diff:.2e} of the peak")
        for k, what in enumerate(("Newton iterations or steps", "factorisations or sub-steps")):
            c0, c1 = ref_cost[name][k], rot_cost[name][k]
            print(f"{name} {what}: {c0} as drawn, {c1} turned")
            if abs(c1 - c0) > a.cost_tolerance * c0:
                failures.append(f"{name} {what} {c1} turned against {c0}")
    if failures:
        sys.exit("frame_invariance: " + "; ".join(failures))
    print(f"frame_invariance: the turned scene gives the same motion within {a.tolerance} of the "
          "peak and the same cost")


if __name__ == "__main__":
    main()
