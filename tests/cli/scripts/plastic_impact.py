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
    studies of this impact found (Zhang and Vu-Quoc 2002; Wu, Li and Thornton 2003).
usage: plastic_impact.py CHOC SOURCE_DIR WORK_DIR"""
import os
import subprocess
import sys

choc, src, work = sys.argv[1:4]
study = os.path.join(src, "tools", "study", "plastic_impact_study.py")
build = os.path.dirname(os.path.abspath(choc))
sys.exit(subprocess.call([sys.executable, study, "--build", build, "--out", work, "--ratios", "0.5", "10", "100",
                          "--h", "1e-4", "--check", "--no-plots"]))
