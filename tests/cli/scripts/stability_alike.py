#!/usr/bin/env python3
"""The direct and the modal transient apply one stability policy (timeint/StabilityPolicy).

SDND101's oscillator (one DOF: 100 kg, 1e4 N/m, a 1e6 N/m penalty stop) by the modal transient
on its single mode and by the direct transient with central differences: both bound the same
highest frequency, sqrt((1e4 + 1e6) / 100) rad/s, so their critical step is the same, 1.99e-2 s,
and with the switching stop their stable step is half of it. At dt = 1.2e-2 s (above the stable
step, below the critical one) both must:
  refuse  exit 1, one line naming the same stable and critical steps (to 1e-9);
  warn    complete (the energy check may then fail them: exit 3) with a warning naming them;
  substep cut every step into the same number of sub-steps (ceil(dt / (0.9 stable)) = 2).

  stability_alike.py CHOC SOURCE WORK
"""
import os
import re
import shutil
import sys

SOURCE = sys.argv[2]
sys.path.insert(0, os.path.join(SOURCE, "tools", "lib"))
import chocrun  # noqa: E402

DT = 1.2e-2


def decks(check):
    """The modal input and its direct counterpart, both at dt = DT with this 'Stability Check'."""
    modal = chocrun.load_deck(os.path.join(SOURCE, "input", "sdnd101.xml"))
    chocrun.keep_analyses(modal, ["mode", "stop"])
    for c in chocrun.sublists(modal, "Analyses/stop"):
        if c == "Checks":
            chocrun.remove_sublist(modal, "Analyses/stop/Checks")
    chocrun.set_param(modal, "Analyses/stop/Time Step", DT)
    chocrun.set_param(modal, "Analyses/stop/End Time", 50 * DT)
    chocrun.set_param(modal, "Analyses/stop/Stability Check", check, create=True)
    direct = chocrun.parse_deck(chocrun.deck_text(modal))
    chocrun.keep_analyses(direct, ["stop"])
    stop = chocrun.sublist(direct, "Analyses/stop")
    for key in ("Modal Basis", "Modal Damping"):
        if chocrun.has(direct, "Analyses/stop/" + key):
            chocrun.remove_param(direct, "Analyses/stop/" + key)
    chocrun.set_param(direct, "Analyses/stop/Type", "Transient")
    del stop
    return modal, direct


def numbers(text):
    m = re.search(r"exceeds the stable step of the explicit scheme, ([0-9.e+-]+) s \(half the critical step ([0-9.e+-]+) s\)",
                  text)
    if not m:
        sys.exit("stability_alike: no stable step in: %s" % text[-600:])
    return float(m.group(1)), float(m.group(2))


def close(a, b):
    return abs(a - b) <= 1e-9 * abs(b)


def main():
    choc, work = sys.argv[1], sys.argv[3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = []
    results = {}
    for check in ("refuse", "warn", "substep"):
        for kind, deck in zip(("modal", "direct"), decks(check)):
            path = os.path.join(work, "%s_%s.xml" % (kind, check))
            chocrun.write_deck(deck, path)
            out = os.path.join(work, "%s_%s" % (kind, check))
            r = chocrun.run(choc, path, out, ok=None)
            results[(kind, check)] = r
            # 'warn' runs on above the stable step, where the switching stop creates energy: it
            # completes, and the energy check may fail it (exit 3).
            expected = (1,) if check == "refuse" else (0, 3) if check == "warn" else (0,)
            if r.returncode not in expected:
                failures.append("%s, %s: exit %d, %s expected: %s" % (kind, check, r.returncode, expected, r.stderr))
    ref = {k: numbers(results[(k, "refuse")].stderr) for k in ("modal", "direct")}
    warn = {k: numbers(results[(k, "warn")].stdout) for k in ("modal", "direct")}
    print("refused at: modal %s, direct %s; warned at: modal %s, direct %s" % (ref["modal"], ref["direct"],
                                                                             warn["modal"], warn["direct"]))
    for label, pair in (("refusal", ref), ("warning", warn)):
        if not (close(pair["modal"][0], pair["direct"][0]) and close(pair["modal"][1], pair["direct"][1])):
            failures.append("the %s's steps differ: modal %s, direct %s" % (label, pair["modal"], pair["direct"]))
    for k in ("modal", "direct"):
        if len(results[(k, "refuse")].stderr.strip().splitlines()) != 1:
            failures.append("%s refusal is not one line" % k)
    if results[("modal", "warn")].returncode != results[("direct", "warn")].returncode:
        failures.append("warned, the two transients end differently")
    if results[("modal", "warn")].returncode != results[("direct", "warn")].returncode:
        failures.append("warned, the two transients end differently")
    counts = {k: chocrun.summary_value(chocrun.read_summary(results[(k, "substep")].out_dir, "stop"), "substeps_per_step")
              for k in ("modal", "direct")}
    print("sub-steps per step: %s" % counts)
    if counts["modal"] != counts["direct"] or counts["modal"] != 2:
        failures.append("sub-steps per step differ or are not ceil(dt / (0.9 x stable step)) = 2: %s" % counts)
    if failures:
        sys.exit("stability_alike: " + "; ".join(failures))
    print("stability_alike: OK")


if __name__ == "__main__":
    main()
