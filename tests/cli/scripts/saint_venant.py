#!/usr/bin/env python3
"""Saint-Venant's problem (input/saint_venant.xml; BENCHMARKS section 15): a rigid mass strikes
the free end of an elastic bar fixed at the other, explicit central differences, the striker a
rigid block, exactly enforced contact (forward increments: the pressures move the body).
Exact (tools/oracles/saint_venant.py, the interval equations solved as polynomials): the contact
force, its end and the mass's rebound velocity, for rho A L / M = 0.5, 1 and 2 (the contact ends
in the third, second and second wave transit). The bar has 100 elements along its 1 m, the step
is 0.96 of an element's transit time dz / c.
Checked, each mass ratio:
  - the contact ends (the end of its last impact: the discrete faces may part and touch again
    for a few steps where the exact pressure falls to 0) within 2 dz / c + dt of the exact end:
    the struck end's stress is resolved over its first element;
  - the mass's rebound velocity within (m_end / M) v0 of the exact, m_end = rho A dz / 2 the
    struck node's mass (its sticking catch at the impact is the discrete scheme's loss);
  - the mean contact force over each tenth of a transit 2T/10 that keeps 2 dz / c away from the
    force's jumps (at 0, T, 2T, ... and the separation) within (m_end v0) / (T / 10): the
    momentum of the struck node over the window;
  - the striker's momentum change equals the contact's impulse in the impact statistics to 1e-6
    of it (the only force on it; the same step sums);
  - no energy created: the balance ends at or below 0 (forward increments only take energy, at
    the catch) and never exceeds 1e-3 E0 (central differences' conserved energy differs from
    the energy by O((w h)^2) of the highest modes, which the reflected fronts excite);
and, for rho A L / M = 1:
  - the force's L1 error over the contact falls with the mesh (50, 100, 200 elements, the same
    Courant number) at least as fast as h^(1/3) over the two halvings (a jump's L1 error
    falls as h^(1/2) under the scheme's dispersion; measured 0.42-0.51);
  - 2 ranks give the same histories to 1e-8 of their peaks;
and the striker driven at v0 ('Held' = every component, 'Held Velocity' = v0; the closed form's
infinite mass: the end's stress rho c v0 (2k + 1) on the k-th transit), over 2.9 transits:
  - the mean force over the windows clear of the jumps within (m_end v0) / (T / 10), as above;
  - the striker's velocity v0 and angular velocity 0 to round-off, the hold's reaction the
    contact force's opposite to round-off (1e-12), and the energy balance 0 to 1e-9 of the
    energy the punch put in (the hold's work is the external work);
and the same push through a kinematic coupling of the bar's end face (Model/Couplings, Type =
kinematic, held at v0; the striker fixed out of the way): the bar's force on the face within the
same bound of the staircase, the hold's reaction its opposite (1e-12);
and the striker bonded to the bar (its face's nodes merged with the bar's end: shared nodes, no
contact; the closed form's equations without separation), 100 and 200 elements:
  - the body's mass is the striker's and the bar's end node's lumped mass (1e-12);
  - the striker's velocity over 3.4 transits within 0.02 v0 of the closed form (the end node's
    mass, m_end / M = 0.5 %, on an exponential decaying at beta T = 2 per transit), the error
    falling at least as h^(1/2) (its acceleration jumps at each kT; measured h^0.67);
  - the energy balance within 1e-3 E0.
usage: saint_venant.py CHOC SOURCE_DIR WORK_DIR"""
import math
import os
import sys

import numpy as np

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = []
rho, A, c = 7800.0, 4e-4, math.sqrt(2e11 / 7800.0)


def run(ratio, along=100, ranks=1):
    """The scene for rho A L / M = ratio, `along` elements, the step 0.96 dz / c."""
    h, impacts, sv, dz, dt, _ = chocrun.saint_venant_run(choc, work, ratio, along, 0.96, ranks)
    return h, impacts, sv, dz, dt


for ratio in (0.5, 1.0, 2.0):
    h, impacts, sv, dz, dt = run(ratio)
    end = max(float(i["end_time"]) for i in impacts)
    bound = 2 * dz / c + dt
    print(f"rho A L / M = {ratio}: contact ends at {end / sv.T:.4f} T, exact {sv.duration / sv.T:.4f} T "
          f"({len(impacts)} impact(s); bound {bound / sv.T:.4f} T)")
    if not abs(end - sv.duration) <= bound:
        failures.append(f"ratio {ratio}: contact ends at {end:.6e} s, exact {sv.duration:.6e} s (within {bound:.2e} s)")
    V = -h["POU1:VZ"][-1]
    m_end = rho * A * dz / 2
    print(f"  rebound {V:+.6f} m/s, exact {sv.rebound_velocity():+.6f} (within {m_end / sv.M * sv.v0:.1e})")
    if not abs(V - sv.rebound_velocity()) <= m_end / sv.M * sv.v0:
        failures.append(f"ratio {ratio}: rebound {V:.6f} m/s, exact {sv.rebound_velocity():.6f}")
    we = sv.window_errors(h["time"], h["impact:force"], 2 * dz / c)
    wbound = m_end / (sv.T / 10) / sv.Z
    print(f"  mean force over {len(we)} windows of T/10 clear of the jumps: largest error {np.max(np.abs(we)):.2e} "
          f"Z v0 (within {wbound:.2e})")
    if len(we) < 5 or not np.max(np.abs(we)) <= wbound:
        failures.append(f"ratio {ratio}: mean force error {np.max(np.abs(we)):.2e} Z v0 over {len(we)} windows")
    P = -np.asarray(h["POU1:PZ"])
    impulse = sum(float(i["impulse"]) for i in impacts)
    print(f"  striker momentum change {P[0] - P[-1]:.9f} N s, contact impulse {impulse:.9f} N s")
    if not abs((P[0] - P[-1]) - impulse) <= 1e-6 * impulse:
        failures.append(f"ratio {ratio}: momentum change {P[0] - P[-1]:.9f} against the impulse {impulse:.9f}")
    chocrun.check_no_energy_created(h, f"ratio {ratio}", failures)

errors = []
for along in (50, 100, 200):
    h, _, sv, _, _ = run(1.0, along)
    errors.append(sv.l1_error(h["time"], h["impact:force"]))
rate = math.log(errors[0] / errors[2]) / math.log(4)
print("force L1 error over the contact, 50/100/200 elements: " + " ".join(f"{e:.4f}" for e in errors) +
      f" (rate {rate:.2f})")
if not rate >= 1 / 3:
    failures.append(f"the force's L1 error falls at the rate {rate:.2f} (at least 1/3)")

# The striker driven at v0 ('Held' = every component, 'Held Velocity' = v0): the infinite mass of
# the closed form, the end's stress rho c v0 (2k + 1) on the k-th transit.
d = chocrun.load_deck(os.path.join(src, "input", "saint_venant.xml"))
steps = 600  # 2.9 transits
chocrun.set_params(d, {"Model/Blocks/POU1/Held": "DX DY DZ DRX DRY DRZ", "Model/Blocks/POU1/Held Velocity": "0 0 -1"},
                   create=True)
chocrun.set_param(d, "Analyses/strike/End Time", steps * 1.9e-6)
held = os.path.join(work, "held")
chocrun.run(choc, chocrun.write_deck(d, held + ".xml"), held)
h = chocrun.read_history(held, "strike")
chocrun.add_tool_path("oracles")
from saint_venant import SaintVenant  # noqa: E402
sv = SaintVenant(1.0, A, rho, 2e11, math.inf, 1.0)
we = sv.window_errors(h["time"], h["impact:force"], 2 * 0.01 / c)
wbound = rho * A * 0.01 / 2 / (sv.T / 10) / sv.Z
print(f"driven at v0: mean force over {len(we)} windows clear of the jumps within {np.max(np.abs(we)):.2e} Z v0 "
      f"(within {wbound:.2e}) of rho c v0 A (2k + 1)")
if len(we) < 10 or not np.max(np.abs(we)) <= wbound:
    failures.append(f"driven: mean force error {np.max(np.abs(we)):.2e} Z v0 over {len(we)} windows")
speed = np.max(np.abs(np.asarray(h["POU1:VZ"]) + 1.0)) + max(np.max(np.abs(h[f"POU1:W{x}"])) for x in "XYZ")
# (from the first step: the initial state has had no kick)
balance = np.max(np.abs(h["POU1:reactionZ"][1:] + h["POU1:FZ"][1:])) / np.max(np.abs(h["POU1:FZ"]))
energy = np.max(np.abs(h["energy:balance"])) / h["energy:total"][-1]
print(f"  held speed error {speed:.1e}, reaction + contact force {balance:.1e} of the peak, energy balance "
      f"{energy:.1e} of the final energy (the hold's work counted)")
if not (speed <= 1e-12 and balance <= 1e-12 and energy <= 1e-9):
    failures.append(f"driven: speed {speed:.1e} (1e-12), reaction {balance:.1e} (1e-12), balance {energy:.1e} (1e-9)")

# The bar's end face driven at v0 through a kinematic coupling (its nodes one rigid body, held),
# the striker left out (fixed): the same staircase, its reaction the bar's force.
d = chocrun.load_deck(os.path.join(src, "input", "saint_venant.xml"))
for sub in ("Analyses/strike/Contact", "Analyses/strike/Initial Conditions"):
    chocrun.remove_sublist(d, sub)
chocrun.set_params(d, {"Model/Blocks/POU1/Rigid": False, "Model/Dirichlet/striker out/Node Set": "POU1",
                       "Model/Dirichlet/striker out/Components": "DX DY DZ",
                       "Model/Couplings/piston/Type": "kinematic", "Model/Couplings/piston/Node Set": "FACE_POU2",
                       "Model/Couplings/piston/Held": "DX DY DZ DRX DRY DRZ",
                       "Model/Couplings/piston/Held Velocity": "0 0 -1", "Analyses/strike/End Time": steps * 1.9e-6},
                   create=True)
out = os.path.join(work, "piston")
chocrun.run(choc, chocrun.write_deck(d, out + ".xml"), out)
h = chocrun.read_history(out, "strike")
we = sv.window_errors(h["time"], h["piston:FZ"], 2 * 0.01 / c)
opposite = np.max(np.abs(h["piston:reactionZ"][1:] + h["piston:FZ"][1:])) / np.max(np.abs(h["piston:FZ"]))
print(f"driven through a kinematic coupling: the bar's force on the face over {len(we)} windows within "
      f"{np.max(np.abs(we)):.2e} Z v0 of rho c v0 A (2k + 1) (within {wbound:.2e}); reaction + force {opposite:.1e}")
if len(we) < 10 or not np.max(np.abs(we)) <= wbound or not opposite <= 1e-12:
    failures.append(f"piston: force error {np.max(np.abs(we)):.2e} Z v0 over {len(we)} windows, reaction {opposite:.1e}")

# The striker bonded to the bar (the mesh's coincident nodes merged, no contact): the bar's end
# nodes are the body's, and their lumped mass from the bar's elements moves with it.
bonded = []
for along in (100, 200):
    d = chocrun.load_deck(os.path.join(src, "input", "saint_venant.xml"))
    if along != 100:
        chocrun.set_param(d, "Mesh/File", os.path.join(work, f"bar{along}.exo"))  # made by run() above
    chocrun.set_param(d, "Mesh/Merge Coincident Nodes", True, create=True)
    chocrun.remove_sublist(d, "Analyses/strike/Contact")
    dt = 0.96 / along / c
    sv = SaintVenant(1.0, A, rho, 2e11, 3.12, 1.0, bonded=True)
    chocrun.set_params(d, {"Analyses/strike/Time Step": dt, "Analyses/strike/End Time": math.ceil(3.4 * sv.T / dt) * dt})
    out = os.path.join(work, f"bonded{along}")
    chocrun.run(choc, chocrun.write_deck(d, out + ".xml"), out)
    h = chocrun.read_history(out, "strike")
    V = -np.asarray(h["POU1:VZ"])
    bonded.append(np.max(np.abs(V - np.array([sv.mass_velocity(t) for t in h["time"]]))))
    mass, expected = -h["POU1:PZ"][0], 3.12 + rho * A * (1.0 / along) / 2
    E0 = h["energy:total"][0]
    balance = np.max(np.abs(h["energy:balance"])) / E0
    print(f"bonded, {along} elements: body mass {mass:.6f} kg (striker + the bar's end node {expected:.6f}), "
          f"velocity within {bonded[-1]:.2e} m/s of the closed form over 3.4 transits, balance within {balance:.1e} E0")
    if not abs(mass - expected) <= 1e-12 * expected:
        failures.append(f"bonded {along}: body mass {mass} kg, expected {expected}")
    if not balance <= 1e-3:
        failures.append(f"bonded {along}: energy balance {balance:.1e} E0 (1e-3)")
if not (bonded[0] <= 0.02 and bonded[1] <= bonded[0] / math.sqrt(2)):
    failures.append(f"bonded: velocity errors {bonded[0]:.2e}, {bonded[1]:.2e} m/s (at most 0.02, falling as h^(1/2))")

h1, _, _, _, _ = run(1.0)
h2, _, _, _, _ = run(1.0, ranks=2)
chocrun.check_ranks_alike(h1, h2, ["POU1:VZ", "POU1:FZ", "impact:force", "C:DZ"], "", failures)
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("saint_venant: the rigid striker's force, contact time and rebound follow the closed form")
