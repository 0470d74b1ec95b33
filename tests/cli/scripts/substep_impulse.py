#!/usr/bin/env python3
"""Impact statistics take every sub-step of an explicit scheme.

SDNL111 D's scene by central differences (input/sdnl111d_explicit.xml, penalty contact): run A
at a step dt_A = 0.85 L below the stable step L (no sub-steps), run B at 13 dt_A, which the
'substep' stability check cuts into 13 sub-steps of dt_A. Both compute the same states, so the
impacts B reports (impulse, peak force and time, start, end, velocity) must be A's to round-off (1e-9 of
each value: the sub-steps' lengths differ from dt_A by a few ulps). Sampled at its step ends
only, B's impulse was 0.5-1.4 % off (the force of one sub-step stood for the whole step).

  substep_impulse.py CHOC SOURCE WORK
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from deck_run import run_deck  # noqa: E402


def set_param(deck, name, value):
    new, n = re.subn(r'(<Parameter name="%s" type="[a-z]+" value=")[^"]*(")' % re.escape(name),
                     r"\g<1>%s\g<2>" % value, deck, count=1)
    if n != 1:
        sys.exit("substep_impulse: no parameter '%s' in the deck" % name)
    return new


def drop_checks(deck):
    return re.sub(r'<ParameterList name="Checks">.*?\n      </ParameterList>\n', "", deck, flags=re.S)


def impacts(out):
    rows = list(csv.DictReader(open(os.path.join(out, "d_explicit.impacts.csv"))))
    if not rows:
        sys.exit("substep_impulse: no impact in %s" % out)
    return [{k: float(v) for k, v in r.items() if k not in ("link", "impact", "open")} for r in rows]


def main():
    choc, src, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    # The stable step, from the refusal of a step far above it.
    probe = set_param(set_param(open(os.path.join(src, "input", "sdnl111d_explicit.xml")).read(),
                                "Stability Check", "refuse"), "Time Step", "1e-4")
    probe = probe.replace('value="../meshes/', 'value="%s/meshes/' % src)
    path = os.path.join(work, "probe.xml")
    open(path, "w").write(probe)
    r = subprocess.run([choc, "check", path], capture_output=True, text=True)
    m = re.search(r"use a time step at most ([0-9.e+-]+) s", r.stderr)
    if r.returncode != 1 or not m:
        sys.exit("substep_impulse: no stable step in the refusal: %s" % r.stderr)
    limit = float(m.group(1))
    dt = 0.85 * limit
    steps_b = math.ceil(1e-3 / (13 * dt))
    end = steps_b * 13 * dt

    def deck(step):
        return lambda d: drop_checks(set_param(set_param(d, "Time Step", repr(step)), "End Time", repr(end)))
    out_a, _ = run_deck(choc, src, work, "sdnl111d_explicit.xml", "a", deck(dt), "substep_impulse")
    out_b, log_b = run_deck(choc, src, work, "sdnl111d_explicit.xml", "b", deck(13 * dt), "substep_impulse")
    if not re.search(r"\b13 sub-step\(s\) per step", log_b):
        sys.exit("substep_impulse: run B is not cut into 13 sub-steps")
    all_a, all_b = impacts(out_a), impacts(out_b)
    if len(all_a) != len(all_b):
        sys.exit("substep_impulse: %d impacts without sub-steps, %d with" % (len(all_a), len(all_b)))
    failures = []
    for k, (a, b) in enumerate(zip(all_a, all_b), start=1):
        for q in ("impulse", "peak_force", "peak_time", "start_time", "end_time", "duration", "impact_velocity"):
            err = abs(a[q] - b[q]) / abs(a[q])
            print("impact %d %-15s A %.12g  B (13 sub-steps) %.12g  relative difference %.2e" % (k, q, a[q], b[q], err))
            if not err <= 1e-9:
                failures.append("impact %d %s" % (k, q))
    if failures:
        sys.exit("substep_impulse: with sub-steps the impact differs: %s" % ", ".join(failures))
    print("substep_impulse: OK")


if __name__ == "__main__":
    main()
