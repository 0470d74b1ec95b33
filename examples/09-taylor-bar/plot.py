#!/usr/bin/env python3
"""The Taylor bar's impact-face radius and length over time against the published final values.

    /usr/bin/python3 examples/09-taylor-bar/plot.py RESULTS_DIR [OUT.png]

RESULTS_DIR is the run's output directory (`choc run ... -o RESULTS_DIR`); it reads
impact.history.csv and writes OUT.png (default RESULTS_DIR/taylor_bar.png)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

R, L = 3.2, 32.4  # mm
# The published final radii (Simo; Zienkiewicz et al.; Foulk et al., the converged Q1/P0 hexahedron).
PUBLISHED_RADIUS = {"Simo 1992": 7.12, "Zienkiewicz et al. 1998": 7.11, "Foulk et al. 2021 (converged Q1/P0)": 7.22}
PUBLISHED_LENGTH = (21.4, 21.5)


def main():
    run = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(run, "taylor_bar.png")
    rows = list(csv.DictReader(open(os.path.join(run, "impact.history.csv"))))
    t = [float(r["time"]) * 1e6 for r in rows]
    radius = [R + float(r["EDGE:DX"]) * 1e3 for r in rows]
    length = [L + (float(r["REAR:DY"]) - float(r["CENTRE:DY"])) * 1e3 for r in rows]
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    a.plot(t, radius, label="choc, 4 x 41 F-bar QUAD4")
    values = sorted(PUBLISHED_RADIUS.values())
    a.axhspan(values[0], values[-1], color="gray", alpha=0.3,
              label="published final, %.2f-%.2f mm" % (values[0], values[-1]))
    a.set(xlabel="t [us]", ylabel="impact-face radius [mm]", title="Face radius")
    b.plot(t, length, label="choc")
    b.axhspan(*PUBLISHED_LENGTH, color="gray", alpha=0.3, label="published, 21.4-21.5 mm")
    b.set(xlabel="t [us]", ylabel="length [mm]", title="Length")
    for ax in (a, b):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="lower right" if ax is a else "upper right")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"final radius {radius[-1]:.3f} mm, length {length[-1]:.3f} mm; wrote {out}")


if __name__ == "__main__":
    main()
