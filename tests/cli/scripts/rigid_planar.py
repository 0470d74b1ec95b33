#!/usr/bin/env python3
"""Rigid bodies in 2D models: Saint-Venant's problem (BENCHMARKS section 15) on SDNL111's section
(meshes/sdnl111_2d_quad8.msh: two bars of 1 m, 50 QUAD8 along, 1 across; gap 1e-5 m), bar 1 the
rigid striker at 1 m/s and bar 2 elastic (nu = 0: a uniform axial stress leaves the section as it
is), fixed at its far end; central differences, Lagrange contact by forward increments. The two
bars have the same mass per unit thickness (plane strain) or per ring (axisymmetric), so
rho A L / M = 1: contact from t0 = gap / v0 until t0 + 1.5338 T, the striker leaving at
-0.6876 m/s (tools/oracles/saint_venant.py).
Checked, in plane strain (the body moves in its plane: 2 rows per node, w along z) and
axisymmetric (the body slides along its axis: radial speed and rotation held):
  - the contact ends (its last impact) within 2 dz / c + dt of the closed form's end;
  - the rebound within (m_end / M) v0 (the struck node's catch, as in cli.saint_venant);
  - the body's velocity across the axis and its rotation stay 0 (1e-12: the contact forces are
    symmetric about the bars' axis up to the pressures' convergence; axisymmetric: held exactly).
usage: rigid_planar.py CHOC SOURCE_DIR WORK_DIR"""
import csv
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("oracles")
from saint_venant import SaintVenant  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []
L, rho, E, v0, gap, along = 1.0, 7800.0, 2e11, 1.0, 1e-5, 50
c = math.sqrt(E / rho)
mesh = os.path.join(src, "meshes", "sdnl111_2d_quad8.msh")


def deck(kinematics, dt, end):
    return f"""<ParameterList name="rigid_planar">
  <ParameterList name="Mesh"><Parameter name="File" type="string" value="{mesh}"/></ParameterList>
  <ParameterList name="Model">
    <Parameter name="Kinematics" type="string" value="{kinematics}"/>
    <ParameterList name="Materials"><ParameterList name="steel">
      <Parameter name="Young's Modulus" type="double" value="{E}"/>
      <Parameter name="Poisson's Ratio" type="double" value="0"/>
      <Parameter name="Density" type="double" value="{rho}"/>
    </ParameterList></ParameterList>
    <ParameterList name="Blocks">
      <ParameterList name="POU1">
        <Parameter name="Material" type="string" value="steel"/>
        <Parameter name="Rigid" type="bool" value="true"/>
      </ParameterList>
      <ParameterList name="POU2">
        <Parameter name="Material" type="string" value="steel"/>
        <Parameter name="Mass" type="string" value="lumped"/>
      </ParameterList>
    </ParameterList>
    <ParameterList name="Dirichlet"><ParameterList name="far end">
      <Parameter name="Node Set" type="string" value="CL_POU2"/>
      <Parameter name="Components" type="string" value="DY"/>
    </ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Analyses"><ParameterList name="strike">
    <Parameter name="Type" type="string" value="Transient"/>
    <Parameter name="Scheme" type="string" value="central differences"/>
    <Parameter name="Stability Check" type="string" value="substep"/>
    <Parameter name="Time Step" type="double" value="{dt!r}"/>
    <Parameter name="End Time" type="double" value="{end!r}"/>
    <ParameterList name="Contact">
      <Parameter name="Method" type="string" value="Lagrange"/>
      <ParameterList name="Pairs"><ParameterList name="impact">
        <Parameter name="Master Side Set" type="string" value="CNT_POU1"/>
        <Parameter name="Slave Side Set" type="string" value="CNT_POU2"/>
        <Parameter name="Search" type="string" value="reference"/>
      </ParameterList></ParameterList>
    </ParameterList>
    <ParameterList name="Initial Conditions"><ParameterList name="strike">
      <Parameter name="Node Set" type="string" value="POU1"/>
      <Parameter name="Field" type="string" value="Velocity"/>
      <Parameter name="Components" type="string" value="DY"/>
      <Parameter name="Value" type="double" value="{-v0}"/>
    </ParameterList></ParameterList>
    <Parameter name="Exodus Interval" type="int" value="0"/>
  </ParameterList></ParameterList>
</ParameterList>
"""


sv = SaintVenant(L, 1.0, rho, E, rho * L, v0)  # per unit section: rho A L / M = 1
dz = L / along
for kinematics in ("plane strain", "axisymmetric"):
    dt = 0.5 * dz / c  # QUAD8's midside nodes: half the element's transit
    steps = math.ceil((gap / v0 + sv.duration + 0.1 * sv.T) / dt)
    out = os.path.join(work, kinematics.replace(" ", "_"))
    chocrun.run(choc, chocrun.write_text(out + ".xml", deck(kinematics, dt, steps * dt)), out)
    chocrun.require_completed(chocrun.read_summary(out, "strike"))
    h = chocrun.read_history(out, "strike")
    with open(os.path.join(out, "strike.impacts.csv")) as f:
        impacts = list(csv.DictReader(f))
    end = max(float(i["end_time"]) for i in impacts) - gap / v0
    V = -h["POU1:VY"][-1]
    across = np.max(np.abs(h["POU1:VX"])) + np.max(np.abs(h["POU1:WZ"]))
    bound = 2 * dz / c + dt
    print(f"{kinematics}: contact ends {end / sv.T:.4f} T after it starts (exact {sv.duration / sv.T:.4f} T, bound "
          f"{bound / sv.T:.4f} T), rebound {V:+.6f} m/s (exact {sv.rebound_velocity():+.6f}), across {across:.1e}")
    if not abs(end - sv.duration) <= bound:
        failures.append(f"{kinematics}: contact ends at {end:.6e} s, exact {sv.duration:.6e} s")
    if not abs(V - sv.rebound_velocity()) <= dz / (2 * L) * v0:
        failures.append(f"{kinematics}: rebound {V:.6f} m/s, exact {sv.rebound_velocity():.6f}")
    if not across <= 1e-12:
        failures.append(f"{kinematics}: the body moves across the axis or turns ({across:.1e})")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("rigid_planar: the 2D rigid striker follows Saint-Venant's closed form")
