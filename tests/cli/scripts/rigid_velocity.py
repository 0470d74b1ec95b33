#!/usr/bin/env python3
"""Initial Conditions with Field = 'Rigid Velocity': v = Translation + Angular Velocity x
(x - Centre). A free steel cube (meshes/compact_block.geo, side a = 0.1 m, 4 x 4 x 4 HEX8,
consistent mass) given V = (1, -2, 0.5) m/s and omega = (3, -1, 2) rad/s about its centroid c.
Checked:
  - the kinetic energy at t = 0 is 1/2 m |V|^2 + 1/2 omega . I omega, with m = rho a^3 and the
    cube's I = m a^2 / 6 (any axis through c): the field is linear, so HEX8's consistent mass
    (2 x 2 x 2 Gauss points) integrates rho |v|^2 exactly: to 1e-12;
  - the corner (0, 0, a) starts at V + omega x (corner - c), to 1e-12 of |V|;
  - the same motion written about the origin (Centre 0 0 0, Translation V + omega x (0 - c))
    gives the same histories, to 1e-12 of their peaks;
  - the strain energy stays at round-off, 1e-12 of the kinetic energy (a velocity field
    omega x r has a skew gradient);
  - on 2 ranks (each setting the nodes it owns) the histories equal 1 rank's to 1e-10 of their
    peaks (direct solves gathered to rank 0: round-off);
  - input errors, exit 1 and one line naming the parameter: a Rigid Velocity with Components;
    a Velocity without Components; an Angular Velocity of two numbers; in the plane-strain
    SDNL111 C input, an Angular Velocity out of the plane.
usage: rigid_velocity.py CHOC SOURCE_DIR WORK_DIR"""
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

A, RHO = 0.1, 7800.0
V = np.array([1.0, -2.0, 0.5])
W = np.array([3.0, -1.0, 2.0])
C = np.array([A / 2, A / 2, A / 2])
os.makedirs(work, exist_ok=True)
mesh = chocrun.gmsh_mesh("compact_block.geo", os.path.join(work, "cube.msh"), order=1, n=4)


def vec(x):
    return " ".join(repr(float(v)) for v in x)


def deck(extra=None, translation=V, centre=C, field="Rigid Velocity"):
    extra = extra or ""
    return f"""<ParameterList name="rigid_velocity">
  <ParameterList name="Mesh"><Parameter name="File" type="string" value="{mesh}"/></ParameterList>
  <ParameterList name="Model">
    <ParameterList name="Materials"><ParameterList name="steel">
      <Parameter name="Young's Modulus" type="double" value="2e11"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.3"/>
      <Parameter name="Density" type="double" value="{RHO}"/>
    </ParameterList></ParameterList>
    <ParameterList name="Blocks"><ParameterList name="block">
      <Parameter name="Material" type="string" value="steel"/>
    </ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Analyses"><ParameterList name="spin">
    <Parameter name="Type" type="string" value="Transient"/>
    <Parameter name="Time Step" type="double" value="1e-5"/>
    <Parameter name="End Time" type="double" value="5e-5"/>
    <Parameter name="History" type="string" value="corner:VX corner:VY corner:VZ corner:DX corner:DY corner:DZ"/>
    <Parameter name="Exodus Interval" type="int" value="0"/>
    <ParameterList name="Initial Conditions"><ParameterList name="spin">
      <Parameter name="Node Set" type="string" value="block"/>
      <Parameter name="Field" type="string" value="{field}"/>
      <Parameter name="Translation" type="string" value="{vec(translation)}"/>
      <Parameter name="Angular Velocity" type="string" value="{vec(W)}"/>
      <Parameter name="Centre" type="string" value="{vec(centre)}"/>
      {extra}
    </ParameterList></ParameterList>
  </ParameterList></ParameterList>
</ParameterList>
"""


def write(name, text):
    return chocrun.write_text(os.path.join(work, name + ".xml"), text)


failures = []
out = os.path.join(work, "about_centroid")
chocrun.run(choc, write("about_centroid", deck()), out)
h = chocrun.read_history(out, "spin")
m = RHO * A ** 3
exact = 0.5 * m * V @ V + 0.5 * (m * A * A / 6.0) * W @ W
ke = h["energy:kinetic"][0]
print(f"kinetic energy at t = 0: {ke:.15e} J, exact {exact:.15e} J ({abs(ke / exact - 1):.1e})")
if not abs(ke / exact - 1.0) <= 1e-12:
    failures.append(f"kinetic energy {ke!r} J against {exact!r} J")
corner = V + np.cross(W, np.array([0.0, 0.0, A]) - C)
got = np.array([h[f"corner:V{c}"][0] for c in "XYZ"])
print(f"corner velocity at t = 0: {got}, exact {corner}")
if not np.max(np.abs(got - corner)) <= 1e-12 * np.linalg.norm(V):
    failures.append(f"corner velocity {got} against {corner}")

out_o = os.path.join(work, "about_origin")
chocrun.run(choc, write("about_origin", deck(translation=V + np.cross(W, -C), centre=np.zeros(3))), out_o)
ho = chocrun.read_history(out_o, "spin")
for c in ("corner:DX", "corner:DY", "corner:DZ", "corner:VX", "energy:kinetic"):
    peak = np.max(np.abs(h[c]))
    rel = np.max(np.abs(ho[c] - h[c])) / peak
    print(f"about the origin: {c} differs by {rel:.1e} of its peak")
    if not rel <= 1e-12:
        failures.append(f"about the origin: {c} differs by {rel:.1e} of its peak (at most 1e-12)")
out2 = os.path.join(work, "about_centroid_np2")
chocrun.run(choc, os.path.join(work, "about_centroid.xml"), out2, ranks=2)
h2 = chocrun.read_history(out2, "spin")
for c in ("corner:DX", "corner:DY", "corner:DZ", "corner:VX", "corner:VY", "corner:VZ", "energy:kinetic"):
    rel = np.max(np.abs(h2[c] - h[c])) / np.max(np.abs(h[c]))
    print(f"2 ranks: {c} differs by {rel:.1e} of its peak")
    if not rel <= 1e-10:
        failures.append(f"2 ranks: {c} differs by {rel:.1e} of its peak (at most 1e-10)")
# The displacement of a velocity field omega x r has a skew gradient: no small strain at all,
# so the strain energy is round-off (a wrong field, a sign in the cross product, would strain
# the cube by about |omega| t = 2e-4 and store about 4 J at the end).
strain = np.max(np.abs(h["energy:strain"]))
print(f"largest strain energy {strain:.1e} J ({strain / ke:.1e} of the kinetic energy)")
if not strain <= 1e-12 * ke:
    failures.append(f"strain energy {strain:.1e} J of a rigid motion (at most 1e-12 of the kinetic energy)")


def expect_error(name, text, parameter, deck_path=None):
    path = deck_path or write(name, text)
    r = chocrun.run(choc, path, os.path.join(work, name + "_out"), ok=(1,))
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    print(f"{name}: exit {r.returncode}: {lines[0] if lines else ''}")
    if r.returncode != 1 or len(lines) != 1 or parameter not in lines[0]:
        failures.append(f"{name}: exit {r.returncode}, stderr {r.stderr!r} (one line naming {parameter})")


spin = "Analyses/spin/Initial Conditions/spin"
expect_error("components_with_rigid", deck('<Parameter name="Components" type="string" value="DX"/>'),
             f"{spin}/Components")
expect_error("velocity_without_components",
             deck('<Parameter name="Value" type="double" value="1"/>', field="Velocity"), f"{spin}/Components")
expect_error("two_numbers", deck().replace(f'value="{vec(W)}"', 'value="1 2"'), f"{spin}/Angular Velocity")
d = chocrun.load_deck(os.path.join(src, "input", "sdnl111c_plane_strain.xml"))
an = chocrun.analyses(d)[0]
chocrun.keep_analyses(d, [an])
ic = f"Analyses/{an}/Initial Conditions/spin"
chocrun.set_params(d, {f"{ic}/Node Set": "POU1", f"{ic}/Field": "Rigid Velocity",
                       f"{ic}/Angular Velocity": "1 0 0"}, create=True)
expect_error("plane_strain_out_of_plane", None, f"{ic}/Angular Velocity",
             chocrun.write_deck(d, os.path.join(work, "plane_strain.xml")))
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("rigid_velocity: the rigid motion's energy and velocities are exact; bad inputs are refused")
