# Writes the extremes inputs (regression/extremes/*.xml); rerun after editing a case here.
import os, sys
D = os.path.dirname(os.path.abspath(__file__))

def model_head(name, comment, mesh, component, nu, section, dirichlet, node_set):
    """The deck up to the Analyses' contents: title, mesh, steel bars POU1 and POU2, one clamp."""
    return f'''<ParameterList name="{name}">
  <!-- {comment} -->
  <Parameter name="Title" type="string" value="extremes: {name}"/>
  <ParameterList name="Mesh">
    <Parameter name="File" type="string" value="{mesh}"/>
  </ParameterList>
  <ParameterList name="Model">
    <Parameter name="Active Components" type="string" value="{component}"/>
    <ParameterList name="Materials">
      <ParameterList name="steel">
        <Parameter name="Young's Modulus" type="double" value="2e11"/>
        <Parameter name="Poisson's Ratio" type="double" value="{nu}"/>
        <Parameter name="Density" type="double" value="7800"/>
      </ParameterList>
    </ParameterList>
    <ParameterList name="Blocks">
      <ParameterList name="POU1">
        <Parameter name="Material" type="string" value="steel"/>
{section}      </ParameterList>
      <ParameterList name="POU2">
        <Parameter name="Material" type="string" value="steel"/>
{section}      </ParameterList>
    </ParameterList>
    <ParameterList name="Dirichlet">
      <ParameterList name="{dirichlet}">
        <Parameter name="Node Set" type="string" value="{node_set}"/>
        <Parameter name="Components" type="string" value="{component}"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Analyses">
'''

SQUARE = '''        <ParameterList name="Section">
          <Parameter name="Square Side" type="double" value="0.02"/>
        </ParameterList>
'''

def modal(name, comment, mesh, dt, end, k=5e9, c=2e4, d1=5e-6, d2=5e-6, v=-1.0, scheme="symplectic Euler",
          stab="refuse", modes_block=None, obstacle="BI_PLAN_Z", axis="0 0 1", damping=0.001, exo=100, progress=5.0,
          history="A:DX A:VX C:DX"):
    modes_block = modes_block or '''    <!-- The complete basis of the small model (dense), rigid-body mode included. -->
    <ParameterList name="modes">
      <Parameter name="Type" type="string" value="Modal"/>
      <Parameter name="Method" type="string" value="dense"/>
      <Parameter name="Number of Modes" type="int" value="21"/>
      <Parameter name="Write Exodus" type="bool" value="false"/>
    </ParameterList>'''
    s = model_head(name, comment, mesh, "DX", "0", SQUARE, "clamped end D", "D") + f'''{modes_block}
    <ParameterList name="run">
      <Parameter name="Type" type="string" value="Modal Transient"/>
      <Parameter name="Modal Basis" type="string" value="modes"/>
      <Parameter name="Modal Damping" type="double" value="{damping:g}"/>
      <Parameter name="Time Step" type="double" value="{dt:g}"/>
      <Parameter name="End Time" type="double" value="{end:g}"/>
      <Parameter name="Scheme" type="string" value="{scheme}"/>
      <Parameter name="Stability Check" type="string" value="{stab}"/>
      <Parameter name="History" type="string" value="{history}"/>
      <Parameter name="Exodus Interval" type="int" value="{exo}"/>
      <Parameter name="Progress Interval" type="double" value="{progress}"/>
      <ParameterList name="Initial Conditions">
        <ParameterList name="bar AB moves towards CD">
          <Parameter name="Node Set" type="string" value="POU1"/>
          <Parameter name="Field" type="string" value="Velocity"/>
          <Parameter name="Components" type="string" value="DX"/>
          <Parameter name="Value" type="double" value="{v:g}"/>
        </ParameterList>
      </ParameterList>
      <ParameterList name="Shock Links">
        <ParameterList name="shock">
          <Parameter name="Node 1" type="string" value="A"/>
          <Parameter name="Node 2" type="string" value="C"/>
          <Parameter name="Obstacle" type="string" value="{obstacle}"/>
          <Parameter name="Axis" type="string" value="{axis}"/>
          <Parameter name="DIST_1" type="double" value="{d1:g}"/>
          <Parameter name="DIST_2" type="double" value="{d2:g}"/>
          <Parameter name="Normal Stiffness" type="double" value="{k:g}"/>
          <Parameter name="Normal Damping" type="double" value="{c:g}"/>
        </ParameterList>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
'''
    open(f"{D}/{name}.xml", "w").write(s)

def implicit(name, comment, mesh, dt, end, scheme="modified average acceleration", alpha=-0.1,
             method="Lagrange", kpen=1e10, v=-1.0, mass="standard", exo=50, extra=""):
    s = model_head(name, comment, mesh, "DZ", "0.3", "", "clamped face of bar 2", "CL_POU2") + f'''    <ParameterList name="run">
      <Parameter name="Type" type="string" value="Transient"/>
      <Parameter name="Scheme" type="string" value="{scheme}"/>
      <Parameter name="Alpha" type="double" value="{alpha:.17g}"/>
      <Parameter name="Time Step" type="double" value="{dt:g}"/>
      <Parameter name="End Time" type="double" value="{end:g}"/>
      <Parameter name="Contact Mass" type="string" value="{mass}"/>
{extra}      <ParameterList name="Contact">
        <Parameter name="Method" type="string" value="{method}"/>
        <Parameter name="Penalty Stiffness" type="double" value="{kpen:g}"/>
        <ParameterList name="Pairs">
          <ParameterList name="interface">
            <Parameter name="Master Side Set" type="string" value="CNT_POU1"/>
            <Parameter name="Slave Side Set" type="string" value="CNT_POU2"/>
          </ParameterList>
        </ParameterList>
      </ParameterList>
      <ParameterList name="Linear Solver">
        <Parameter name="Method" type="string" value="Direct"/>
      </ParameterList>
      <ParameterList name="Initial Conditions">
        <ParameterList name="bar 1 moves towards bar 2">
          <Parameter name="Node Set" type="string" value="POU1"/>
          <Parameter name="Field" type="string" value="Velocity"/>
          <Parameter name="Components" type="string" value="DZ"/>
          <Parameter name="Value" type="double" value="{v:g}"/>
        </ParameterList>
      </ParameterList>
      <Parameter name="History" type="string" value="N1:DZ N1:VZ"/>
      <Parameter name="Exodus Interval" type="int" value="{exo}"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
'''
    open(f"{D}/{name}.xml", "w").write(s)

M1 = "bars1d_10.exo"   # --dim 1 --along1 10 --along2 10 --gap 1e-5
M3 = "bars3d_10.exo"   # --dim 3 --axis z --along1 10 --along2 10 --gap 1e-5
modal("modal_dt1e-8", "dt = 1e-8 s, 282 x below the critical step: completes; leapfrog energy bound (h/dt_crit)^2 ~ 1e-5 (regression/extremes/CMakeLists.txt)", M1, 1e-8, 4.2e-4, exo=5000)
modal("modal_dt1e-4_refused", "dt = 1e-4 s above the critical step (2.8e-6 s) with the default 'Stability Check' = refuse: input error, exit 1", M1, 1e-4, 1e-3)
modal("modal_dt1e-4_substep", "dt = 1e-4 s with 'Stability Check' = substep: each step cut below 0.9 dt_crit; completes with bounded energy", M1, 1e-4, 1e-3, stab="substep", exo=1)
modal("modal_k1e6", "soft shock link K = 1e6 N/m, no dashpot: A and C 1e-2 m apart (DIST_1 + DIST_2 = 1e-2, touching at t = 0) so that the 1.2 mm penetration never makes the nodes cross", "bars1d_10_gap1e-2.exo", 1e-6, 6e-3, k=1e6, c=0, d1=5e-3, d2=5e-3)
modal("modal_k1e16_refused", "stiff shock link K = 1e16 N/m at dt = 1e-6 s with the default 'Stability Check': refused (critical step 4.2e-9 s), exit 1", M1, 1e-6, 4.2e-4, k=1e16)
modal("modal_k1e16", "stiff shock link K = 1e16 N/m at dt = 1e-6 s: 'Stability Check' = substep (263 sub-steps of 3.8e-9 s); without it the run is refused (modal_k1e16_refused)", M1, 1e-6, 4.2e-4, k=1e16, stab="substep")
modal("modal_gap_negative", "initial penetration: DIST_1 + DIST_2 = 2e-5 m for nodes 1e-5 m apart (gap -1e-5 m, 0.25 J stored in the link): the first steps push the bars apart", M1, 1e-6, 1e-3, d1=1e-5, d2=1e-5)
modal("modal_v1e-3", "impact speed 1e-3 m/s, link touching at t = 0 (zero gap, nodes 1e-3 m apart): positively homogeneous problem, compared with modal_v1e2", "bars1d_10_gap1e-3.exo", 1e-6, 1.02e-3, d1=5e-4, d2=5e-4, v=-1e-3)
modal("modal_v1e2", "impact speed 1e2 m/s, link touching at t = 0 (nodes 1e-3 m apart: the 1.6e-4 m penetration never makes them cross)", "bars1d_10_gap1e-3.exo", 1e-6, 1.02e-3, d1=5e-4, d2=5e-4, v=-1e2)
modal("modal_long", "SDNL111 B to 0.1 s: 100,000 steps of 1e-6 s, bilateral inner-circle link, 0.1% modal damping; no Exodus output", "sdnl111b_1d.exo", 1e-6, 0.1, obstacle="BI_CERC_INT", axis="0 1 0", d1=1e-6, d2=2e-6,
      exo=0, progress=5.0, history="A:DX A:VX",
      modes_block='''    <ParameterList name="modes">
      <Parameter name="Type" type="string" value="Modal"/>
      <Parameter name="Number of Modes" type="int" value="40"/>
      <Parameter name="Which" type="string" value="Nearest Shift"/>
      <Parameter name="Shift Frequency" type="double" value="20000"/>
      <Parameter name="Write Exodus" type="bool" value="false"/>
    </ParameterList>''')
implicit("implicit_dt1e-8", "implicit, dt = 1e-8 s (2000 steps over the impact at 1e-5 s); Lagrange contact with redistributed contact mass", M3, 1e-8, 2e-5, exo=200, mass="redistributed")
implicit("implicit_dt1e-4", "implicit, dt = 1e-4 s (20 steps; the contact lasts 3.4e-4 s); Lagrange contact with redistributed contact mass", M3, 1e-4, 2e-3, exo=1, mass="redistributed")
implicit("implicit_k1e6", "penalty E_N = 1e6 N/m per slave node (soft: 0.6 mm penetration)", M3, 2e-6, 4e-3, method="Penalty", kpen=1e6)
implicit("implicit_k1e16", "penalty E_N = 1e16 N/m per slave node on the standard mass: contact as exact as Lagrange's, the contact nodes chatter and the scheme creates energy, which the run reports (see CMakeLists.txt)", M3, 1e-6, 1e-3, method="Penalty", kpen=1e16)
implicit("implicit_alpha0", "HHT alpha = 0 (average acceleration, no numerical dissipation), Lagrange contact, redistributed contact mass", M3, 1e-6, 1e-3, scheme="HHT", alpha=0.0, mass="redistributed")
implicit("implicit_alpha-1_3", "HHT alpha = -1/3 (strongest numerical dissipation), Lagrange contact, redistributed contact mass", M3, 1e-6, 1e-3, scheme="HHT", alpha=-1/3, mass="redistributed")
implicit("implicit_gap0", "zero initial gap (mesh gap 0): contact from t = 0, Lagrange, redistributed contact mass", "bars3d_10_gap0.exo", 1e-6, 1e-3, mass="redistributed")
implicit("implicit_gap_negative", "initial penetration 1e-6 m (mesh gap -1e-6), penalty 1e10 N/m per slave node (0.02 J stored at t = 0)", "bars3d_10_gapneg.exo", 1e-6, 1e-3, method="Penalty", kpen=1e10)
implicit("implicit_v1e2", "impact speed 1e2 m/s, Lagrange contact, redistributed contact mass", M3, 1e-6, 1e-3, v=-1e2, mass="redistributed")
