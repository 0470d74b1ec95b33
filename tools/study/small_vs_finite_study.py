#!/usr/bin/env python3
"""Small against finite strain (docs/verification/rubber-ball.md): the rubber ball of
input/rubber_ball.xml dropped at rising speeds, once with 'Strain' = 'finite' (neo-Hookean, the
deck) and once with 'small' (linear elastic, the same E and nu). For each speed: Hertz's contact
radius a/R, the peak force, contact duration, largest approach and rebound velocity of both
models, the small model's error against the finite one, the largest energy balance of each and
the cost ratio (wall time, finite over small). Steps of Hertz's contact duration / 450, runs to
1.1 times it, up to 6 cuts of a step that fails. Writes OUT/small_vs_finite.csv and OUT/small_vs_finite.png (the errors against
a/R) and prints a Markdown table.
    small_vs_finite_study.py [--build build] [--out results/small_vs_finite] [--speeds 1 2 4 8 16]"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

chocrun.add_tool_path("oracles")
import hertz  # noqa: E402

R, E, NU, RHO = 0.01, 1e7, 0.45, 1100.0
QUANTITIES = ("peak force", "contact duration", "largest approach", "rebound velocity")


def run(choc, out_dir, speed, strain):
    h = hertz.hertz(R, E, NU, RHO, speed)
    d = chocrun.load_deck(chocrun.input_path("rubber_ball.xml"))
    a = "Analyses/drop"
    chocrun.set_param(d, a + "/Time Step", h["tc"] / 450)
    chocrun.set_param(d, a + "/End Time", 1.1 * h["tc"])
    chocrun.set_param(d, a + "/Exodus Interval", 0)
    # Above about 10 m/s a Newton correction of the first contact steps can invert an element
    # (backtracked) or meet an indefinite tangent (CG stops): such a step is retried with dt / 2.
    chocrun.set_param(d, a + "/Step Control/Maximum Step Cuts", 6, create=True)
    chocrun.set_param(d, a + "/Initial Conditions/falling/Value", -speed)
    if strain == "small":
        chocrun.set_param(d, "Model/Blocks/SPHERE/Strain", "small")
        chocrun.set_param(d, "Model/Materials/rubber/Model", "linear elastic")
    tag = f"v{speed:g}_{strain}"
    out = os.path.join(out_dir, tag)
    wall = chocrun.run(choc, chocrun.write_deck(d, os.path.join(out_dir, tag + ".xml")), out).wall
    chocrun.require_completed(chocrun.read_summary(out, "drop"))
    return h, hertz.measure(chocrun.history_path(out, "drop"), h), wall


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    x = [r["a/R"] for r in rows]
    for q in QUANTITIES:
        ax.plot(x, [abs(r[f"small error {q} %"]) for r in rows], "o-", label=q)
    ax.set_xlabel("Hertz's contact radius a / R")
    ax.set_ylabel("|small - finite| / finite [%]")
    ax.set_title("Rubber ball (nu = 0.45): the small-strain model's error")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/small_vs_finite")
    ap.add_argument("--speeds", type=float, nargs="+", default=[1, 2, 4, 8, 16])
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    print("| v [m/s] | a/R (Hertz) | " + " | ".join(f"{q}: finite (small, error)" for q in QUANTITIES)
          + " | energy balance max, finite / small | cost finite / small |")
    print("|---" * (4 + len(QUANTITIES)) + "|")
    for v in a.speeds:
        h, fin, wall_f = run(choc, a.out, v, "finite")
        _, sml, wall_s = run(choc, a.out, v, "small")
        row = {"speed": v, "a/R": (h["dmax"] / R) ** 0.5, "cost ratio": wall_f / wall_s,
               "balance finite": fin["_balance"], "balance small": sml["_balance"]}
        cells = []
        for q in QUANTITIES:
            err = 100 * (sml[q][0] / fin[q][0] - 1)
            row.update({f"finite {q}": fin[q][0], f"small {q}": sml[q][0], f"small error {q} %": err})
            cells.append(f"{fin[q][0]:.4g} ({sml[q][0]:.4g}, {err:+.1f} %)")
        rows.append(row)
        print(f"| {v:g} | {row['a/R']:.3f} | " + " | ".join(cells)
              + f" | {fin['_balance']:+.1e} / {sml['_balance']:+.1e} E0 | {row['cost ratio']:.1f} |", flush=True)
    with open(os.path.join(a.out, "small_vs_finite.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(a.out, "small_vs_finite.png"))
    print(f"figure: {os.path.join(a.out, 'small_vs_finite.png')}")


if __name__ == "__main__":
    main()
