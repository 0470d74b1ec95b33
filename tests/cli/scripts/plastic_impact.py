#!/usr/bin/env python3
"""An elastic-plastic sphere on a rigid plane (docs/verification/plastic-impact.md): a steel sphere,
R = 10 mm, J2 with yield 2 GPa and no hardening (input/plastic_impact_axisymmetric.xml, small strain,
central differences, Lagrange contact), on TRI6 of 0.1 mm at the contact, at 0.5, 10 and 100 times
its yield velocity v_y = 0.2162 m/s (tools/oracles/plastic_impact.py: Hertz's first yield below the
surface, p0 = 1.61 Y). The runs and the checks are tools/study/plastic_impact_study.py --check:
  - one impact each; the energy the rebound leaves in the sphere, E0 - (1/2) m (e v)^2 - W_p, at or
    above -1e-3 E0 and energy:balance at or below 1e-3 E0 (no energy created);
  - below yield no point yields (EQ_PLASTIC_STRAIN exactly 0) and e = 1 within 5e-3 (the vibration
    the impact leaves, a fraction of a percent of E0, as in the elastic Hertz test);
  - above yield e falls with the speed and stays above Thornton's closed form (1997), which caps the
    pressure at first yield and so overestimates the plastic work, as the published finite-element
    studies of this impact found (Zhang and Vu-Quoc 2002; Wu, Li and Thornton 2003);
  - the 10 v_y run on 2 ranks gives the 1-rank histories (the centre's motion and velocity, the
    contact force, the plastic work) to 1e-8 of their peaks (central differences have no solver
    tolerance: round-off of the sums in another order).
usage: plastic_impact.py CHOC SOURCE_DIR WORK_DIR"""
import os
import subprocess
import sys

choc, src, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools", "lib"))
import chocrun  # noqa: E402

study = os.path.join(src, "tools", "study", "plastic_impact_study.py")
build = os.path.dirname(os.path.abspath(choc))
failures = []
if subprocess.call([sys.executable, study, "--build", build, "--out", work, "--ratios", "0.5", "10", "100",
                    "--h", "1e-4", "--check", "--no-plots"]) != 0:
    failures.append("the study's checks (above)")
deck = os.path.join(work, "h0.0001_v10.xml")  # written by the study
if os.path.exists(deck):
    chocrun.run(choc, deck, os.path.join(work, "np2"), ranks=2)
    failures += chocrun.ranks_agree(chocrun.read_history(os.path.join(work, "h0.0001_v10"), "impact"),
                                    chocrun.read_history(os.path.join(work, "np2"), "impact"),
                                    ("C:DY", "C:VY", "plane:force", "energy:plastic"))
else:
    failures.append(f"{deck}: not written by the study")
chocrun.finish(failures, "plastic_impact: every check holds")
