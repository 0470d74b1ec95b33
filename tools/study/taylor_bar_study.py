#!/usr/bin/env python3
"""The Taylor bar's mesh convergence (docs/verification/taylor-bar.md).
--law j2 (default): input/taylor_bar_axisymmetric.xml (copper, J2, finite strain, 227 m/s, 80 us,
central differences) on QUAD4 F-bar meshes of n elements across the radius (0.8, 0.4, 0.2, 0.1 mm
for n = 4, 8, 16, 32; the time step scaled with the element), the standard QUAD4 and QUAD8 on 0.4 mm
beside them. --law johnson-cook: input/taylor_bar_johnson_cook_axisymmetric.xml (42CrMo4, 287 m/s,
adiabatic heating) on the F-bar meshes only (n = 5, 4, 8, 16 by default; 5 x 51 is the published
mesh's density), with the largest plastic strain and temperature. For each run: the final impact-face radius
and length (rear face minus impact face), the range the length sweeps once the bar has left the
wall (its free axial vibration: the length at 80 us is one phase of it), the plastic work over
E0, the balance, the wall time; the
successive differences' observed order and the Richardson extrapolation of the F-bar series.
--wall roller holds the impact face on the wall (DY = 0 on IMPACT, bilateral: the face cannot lift
off) instead of the inputs' frictionless contact, as the published runs model the wall.
Writes OUT/taylor_bar.csv and OUT/taylor_bar.png, prints a Markdown table.
    taylor_bar_study.py [--build build] [--out results/study/taylor-bar] [--law j2] [--n 4 8 16]
                        [--wall contact|roller]"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "lib"))
import chocrun  # noqa: E402

R0, L0 = 3.2e-3, 32.4e-3
LAWS = {
    "j2": {"deck": "taylor_bar_axisymmetric.xml", "title": "copper J2, 227 m/s",
           "published": {"radius": (7.11, 7.22), "length": (21.4, 21.5)}},
    "johnson-cook": {"deck": "taylor_bar_johnson_cook_axisymmetric.xml",
                     "title": "42CrMo4 Johnson-Cook, 287 m/s",
                     "published": {"radius": (5.575, 5.61), "length": (26.52, 26.56), "strain": (1.78, 1.84),
                                   "temperature": (582, 597)}},
}
PUBLISHED = LAWS["j2"]["published"]


def run(choc, out_dir, n, formulation="F-bar", order=1, deck="taylor_bar_axisymmetric.xml", wall="contact"):
    tag = f"{deck[:-4]}_n{n}_{formulation}_order{order}" + ("_roller" if wall == "roller" else "")
    msh = os.path.join(out_dir, f"bar_n{n}_order{order}.msh")
    chocrun.gmsh("taylor_bar_axisymmetric.geo", msh, 2, "-order", order, "-setnumber", "n", n)
    d = chocrun.load_deck(chocrun.input_path(deck))
    chocrun.set_param(d, "Mesh/File", msh)
    chocrun.set_param(d, "Model/Blocks/BAR/Formulation", formulation)
    chocrun.set_param(d, "Analyses/impact/Time Step", 4e-8 * 8 / n)
    if wall == "roller":  # DY = 0 on the impact face in place of the contact pair
        chocrun.hold_on_wall(d, "Analyses/impact", "IMPACT", "DY", "central differences", 4e-8 * 8 / n, 8e-5)
    chocrun.set_param(d, "Analyses/impact/Exodus Interval", 1000000)  # the first and the last step
    out = os.path.join(out_dir, tag)
    seconds = chocrun.run(choc, chocrun.write_deck(d, os.path.join(out_dir, tag + ".xml")), out).wall
    chocrun.require_completed(chocrun.read_summary(out, "impact"))
    h = chocrun.read_history(out, "impact")
    e0 = h["energy:total"][1]
    fields = chocrun.read_element_fields(os.path.join(out, "impact.exo"), ["EQ_PLASTIC_STRAIN"])
    try:
        hottest = float(chocrun.read_element_fields(os.path.join(out, "impact.exo"), ["TEMPERATURE"])
                        ["TEMPERATURE"].max())
    except KeyError:
        hottest = float("nan")
    lengths = [(L0 + rear - centre) * 1e3 for rear, centre in zip(h["REAR:DY"], h["CENTRE:DY"])]
    free = free_flight(h["wall:force"], lengths) if wall == "contact" else None
    return {"mesh": f"{'QUAD8' if order == 2 else 'QUAD4'} {formulation}, {3.2 / n:.2g} mm", "n": n,
            "radius": (R0 + h["EDGE:DX"][-1]) * 1e3,
            "length": lengths[-1],
            "lift-off [us]": h["time"][free["index"]] * 1e6 if free else float("nan"),
            "free length min": free["min"] if free else float("nan"),
            "free length max": free["max"] if free else float("nan"),
            "strain": float(fields["EQ_PLASTIC_STRAIN"].max()), "temperature": hottest,
            "plastic work / E0": h["energy:dissipated"][-1] / e0,
            "balance min / E0": min(h["energy:balance"]) / e0, "balance max / E0": max(h["energy:balance"]) / e0,
            "wall [s]": seconds, "history": h}


def free_flight(force, lengths):
    """After the bar's last step on the wall (wall force zero from then to the end), its length
    rings in its free axial vibration (period about 2 L / c): the range it sweeps, and the index
    of the first free step. None when the bar still touches the wall at the end."""
    touching = [i for i, f in enumerate(force) if f > 0]
    if not touching or touching[-1] == len(force) - 1:
        return None
    first = touching[-1] + 1
    return {"index": first, "min": min(lengths[first:]), "max": max(lengths[first:])}


def extrapolate(rows, key):
    """Observed order of the last three F-bar meshes halving the element (n = 4, 8, 16, 32) and
    the Richardson extrapolation."""
    rows = [r for r in rows if r["n"] in (4, 8, 16, 32)]
    if len(rows) < 3:
        return None, None
    a, b, c = (r[key] for r in rows[-3:])
    if (b - a) * (c - b) <= 0:
        return None, None
    p = math.log2((b - a) / (c - b))
    return p, c + (c - b) / (2 ** p - 1)


def plot(rows, path, law):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key in zip(axes, ("radius", "length")):
        fb = sorted((r for r in rows if "F-bar" in r["mesh"] and "QUAD4" in r["mesh"]), key=lambda r: r["n"])
        ax.semilogx([3.2 / r["n"] for r in fb], [r[key] for r in fb], "o-", label="QUAD4 F-bar")
        ringing = [r for r in fb if key == "length" and not math.isnan(r["lift-off [us]"])]
        if ringing:
            ax.vlines([3.2 / r["n"] for r in ringing], [r["free length min"] for r in ringing],
                      [r["free length max"] for r in ringing], color="C0", alpha=0.5,
                      label="swept after lift-off (free vibration)")
        for r in rows:
            if r not in fb:
                ax.plot(3.2 / r["n"], r[key], "s", label=r["mesh"])
        lo, hi = LAWS[law]["published"][key]
        ax.axhspan(lo, hi, color="0.85", label="published")
        ax.set_xlabel("element size [mm]")
        ax.set_ylabel(f"final {key} [mm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Taylor bar, {LAWS[law]['title']}, 80 us (axisymmetric)")
    chocrun.save_figure(fig, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/study/taylor-bar")
    ap.add_argument("--law", choices=sorted(LAWS), default="j2")
    ap.add_argument("--n", type=int, nargs="+", default=None)
    ap.add_argument("--wall", choices=["contact", "roller"], default="contact")
    a = ap.parse_args()
    choc = chocrun.choc_path(a.build)
    os.makedirs(a.out, exist_ok=True)
    law = LAWS[a.law]
    ns = a.n or ([4, 8, 16] if a.law == "j2" else [5, 4, 8, 16])
    fbar = [run(choc, a.out, n, deck=law["deck"], wall=a.wall) for n in ns]
    others = ([run(choc, a.out, 8, "standard", wall=a.wall), run(choc, a.out, 8, "standard", order=2, wall=a.wall)]
              if a.law == "j2" else [])
    rows = fbar + others
    print("| mesh | radius [mm] | length [mm] | after lift-off [mm] | largest alpha | largest T | plastic work / E0 | "
          "balance / E0 | wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        free = (f"{r['free length min']:.3f}-{r['free length max']:.3f} from {r['lift-off [us]']:.0f} us"
                if not math.isnan(r["lift-off [us]"]) else "on the wall")
        print(f"| {r['mesh']} | {r['radius']:.4f} | {r['length']:.4f} | {free} | {r['strain']:.3f} | {r['temperature']:.1f} | "
              f"{r['plastic work / E0']:.4f} | {r['balance min / E0']:.1e} to {r['balance max / E0']:.1e} | "
              f"{r['wall [s]']:.0f} |")
    for key in ("radius", "length"):
        p, x = extrapolate(fbar, key)
        if p is not None:
            print(f"{key}: observed order {p:.2f}, Richardson extrapolation {x:.4f} mm "
                  f"(published {law['published'][key][0]}-{law['published'][key][1]} mm)")
    with open(os.path.join(a.out, "taylor_bar.csv"), "w", newline="") as f:
        fields = [k for k in rows[0] if k != "history"]
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(a.out, "taylor_bar.png"), a.law)


if __name__ == "__main__":
    main()
