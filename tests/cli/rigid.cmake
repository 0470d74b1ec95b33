# Rigid bodies (issue 74): a rigid box spinning near its intermediate axis by central differences
# (input/rigid_spin.xml, BENCHMARKS section 17): its shape, energy and flip period against Euler's
# equations, 1 and 2 ranks alike; the inputs rigid blocks cannot run yet refused.
choc_cli_script(rigid_spin 300)
# A rigid block dropped on a finite-strain slab with penalty contact (input/block_on_slab.xml's
# scene): its momentum change is the contact's impulse, one impact, 1 and 2 ranks alike.
choc_cli_script(rigid_drop 300)
# Saint-Venant's problem (input/saint_venant.xml, BENCHMARKS section 15): a rigid mass strikes an
# elastic bar with exactly enforced contact; the force, contact end and rebound against the
# closed form for three mass ratios, the force's convergence, 1 and 2 ranks alike.
choc_cli_script(saint_venant 300)
# Gravity: the rigid spinning box falls on its parabola with its spin unchanged and its energy
# balanced; a bar stands under its own weight with the closed-form shortening (scripts/gravity.py).
choc_cli_script(gravity 300)
# Rigid bodies in 2D models: Saint-Venant's problem on SDNL111's plane-strain and axisymmetric
# section, the striker rigid (scripts/rigid_planar.py).
choc_cli_script(rigid_planar 300)
