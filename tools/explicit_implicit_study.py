#!/usr/bin/env python3
"""Explicit against implicit, error against cost (issue 17's study; part of `make study`).

Two scenes with a closed form over the whole history, each run by both schemes on a series of
meshes, the time step tied to the mesh (Courant number about 1, where both schemes are most
accurate for a bar's wave):
  - SDNV100 (BENCHMARKS section 1): input/sdnv100_explicit.xml (central differences, lumped
    mass, forward-increment Lagrange contact) and input/sdnv100.xml's analysis 'lagrange'
    (Newmark beta = 0.28, gamma = 0.55 as the deck, consistent mass with the massless contact
    face; and 'implicit, trapezoidal': beta = 1/4, gamma = 1/2, no numerical damping), n HEX8
    along (meshes/sdnv100_bar.geo), dt = 2e-5 / ceil(2e-5 / (C h / c)) so that
    the contact instant falls on a step; error: DZ(N5), the contact face.
  - SDNL111 D's scene (two 3D bars, lateral motion blocked): input/sdnl111d_explicit.xml and
    input/sdnl111d.xml (HHT alpha = -0.1 as the deck; 'implicit, trapezoidal': alpha = 0), both
    with Lagrange contact instead of their penalties (whose stiffness was chosen for 50
    elements), the implicit one at the default contact mass, n HEX8 along each bar (`choc mesh
    --dim 3`), dt = C h / c
    (c the oedometric speed, 5,875 m/s; C = 1 implicit, 0.95 explicit, below its critical step
    h / c); error: DZ(N1), bar 1's contact face.
Cost: the whole process's wall time (start-up, mesh, assembly included), median of --repeat
runs. Prints one table per scene and, per scene and scheme, the cheapest run within 1 % and
0.1 % of the peak, and writes OUT/study.csv.
    explicit_implicit_study.py [--build build] [--out results/explicit_implicit] [--repeat 2]
"""
import argparse
import csv
import math
import os
import re
import statistics
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def sub1(pattern, repl, text):
    out, n = re.subn(pattern, repl, text, count=1, flags=re.S)
    assert n == 1, pattern
    return out


def set_param(text, name, value):
    return sub1(rf'(<Parameter name="{re.escape(name)}" type="[a-z]+" value=")[^"]*"', rf'\g<1>{value}"', text)


def only_analysis(text, keep):
    """Drops every analysis of the input but `keep` (analyses are the Analyses list's children)."""
    head, rest = text.split('<ParameterList name="Analyses">', 1)
    blocks = re.findall(r'(\n    <ParameterList name="([^"]+)">.*?\n    </ParameterList>)', rest, flags=re.S)
    kept = [b for b, name in blocks if name == keep]
    assert len(kept) == 1, keep
    return head + '<ParameterList name="Analyses">' + kept[0] + "\n  </ParameterList>\n</ParameterList>\n"


def run(choc, xml, outdir, repeat):
    walls = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        p = subprocess.run([choc, "run", xml, "-o", outdir], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
        walls.append(time.perf_counter() - t0)
        if p.returncode not in (0, 3):  # 3: a check NOOK (coarse meshes miss the rows)
            raise SystemExit(f"{xml}: choc exited {p.returncode}:\n{p.stdout[-2000:]}")
    err = {m.group(1): float(m.group(2)) for m in re.finditer(
        r"exact solution, (\S+)\s*: max error \S+ \(([\d.eE+-]+)% of peak", p.stdout)}
    steps = int(re.search(r"(\d+) steps", p.stdout).group(1))
    sub = re.search(r"steps of (\d+) sub-step\(s\) \(([\d.eE+-]+) s each", p.stdout)
    # Explicit runs may cut each step into sub-steps (at 0.9 of the critical step).
    return err, statistics.median(walls), steps * (int(sub.group(1)) if sub else 1), \
        float(sub.group(2)) if sub else None


def measure(choc, out, scene, scheme, n, text, mesh, dt, h, c, quantities, repeat):
    """Runs `text` (an input) on `mesh` with step dt (no Exodus output) and returns its row:
    the max errors of `quantities` (the first is the row's error), the sub-step actually taken
    and the Courant number c dt / h."""
    text = sub1(r'(<Parameter name="File" type="string" value=")[^"]*"', rf'\g<1>{mesh}"', text)
    text = set_param(set_param(text, "Time Step", repr(dt)), "Exodus Interval", "0")
    tag = f"{scene.replace(' ', '').lower()}_{scheme.replace(', ', '_')}_{n}"
    xml = os.path.join(out, tag + ".xml")
    open(xml, "w").write(text)
    err, wall, steps, substep = run(choc, xml, os.path.join(out, tag), repeat)
    dt = substep or dt
    print(f"  {scene} {scheme} n = {n}: {err[quantities[0]]:.3g} % in {wall:.2f} s", flush=True)
    return {"scene": scene, "scheme": scheme, "along": n, "dt": dt, "courant": dt * c / h, "steps": steps,
            "error": err[quantities[0]], "error_other": err[quantities[1]] if len(quantities) > 1 else "",
            "wall": wall}


def sdnv100(choc, out, repeat):
    C = 5000.0
    rows = []
    explicit = open(os.path.join(ROOT, "input", "sdnv100_explicit.xml")).read()
    implicit = only_analysis(open(os.path.join(ROOT, "input", "sdnv100.xml")).read(), "lagrange")
    trapezoidal = set_param(set_param(implicit, "Beta", "0.25"), "Gamma", "0.5")
    plans = [("explicit", n, 0.988) for n in (40, 80, 160, 320, 640, 1000)] + \
            [(scheme, n, 1.0) for scheme in ("implicit", "implicit, trapezoidal") for n in (20, 40, 80, 160, 320, 640)]
    for scheme, n, courant in plans:
        mesh = os.path.join(out, f"sdnv100_bar_{n}.msh")
        if not os.path.exists(mesh):
            subprocess.run(["gmsh", "-3", "-format", "msh41", "-setnumber", "n", str(n),
                            os.path.join(ROOT, "meshes", "sdnv100_bar.geo"), "-o", mesh],
                           check=True, stdout=subprocess.DEVNULL)
        h = 0.2 / n
        dt = 2e-5 / math.ceil(2e-5 / (courant * h / C) - 1e-9)
        text = {"explicit": explicit, "implicit": implicit, "implicit, trapezoidal": trapezoidal}[scheme]
        rows.append(measure(choc, out, "SDNV100", scheme, n, text, mesh, dt, h, C, ("N5:DZ", "N100:DZ"), repeat))
    return rows


def sdnl111d(choc, out, repeat):
    E, nu, rho = 2e11, 0.3, 7800.0
    C = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)  # lateral motion blocked
    rows = []

    def lagrange(name):  # the input with Lagrange contact instead of its penalty
        return sub1(r'<Parameter name="Method" type="string" value="Penalty"/>\s*'
                    r'<Parameter name="Penalty Stiffness" type="double" value="[^"]*"/>',
                    '<Parameter name="Method" type="string" value="Lagrange"/>',
                    open(os.path.join(ROOT, "input", name)).read())
    explicit = lagrange("sdnl111d_explicit.xml")
    implicit = lagrange("sdnl111d.xml")
    # Lagrange contact at the default contact mass (the surfaces' mass redistributed).
    implicit = sub1(r'<Parameter name="Contact Mass" type="string" value="standard"/>', "", implicit)
    trapezoidal = set_param(implicit, "Alpha", "0")
    for scheme, text0 in (("explicit", explicit), ("implicit", implicit), ("implicit, trapezoidal", trapezoidal)):
        for n in (50, 100, 200, 400, 800) + ((1600,) if scheme == "explicit" else ()):
            mesh = os.path.join(out, f"sdnl111_3d_{n}.exo")
            if not os.path.exists(mesh):
                subprocess.run([choc, "mesh", "--dim", "3", "--axis", "z", "--along1", str(n), "--along2", str(n),
                                "--width", "0.02", "--height", "0.02", "--gap", "1e-5", "-o", mesh],
                               check=True, stdout=subprocess.DEVNULL)
            h = 1.0 / n
            # Central differences' critical step is h / c here (the element bound, exact on a
            # regular bar): 0.95 of it, which the stability check accepts without sub-steps.
            dt = (0.95 if scheme == "explicit" else 1.0) * h / C
            rows.append(measure(choc, out, "SDNL111 D", scheme, n, text0, mesh, dt, h, C, ("N1:DZ",), repeat))
    return rows


def report(rows):
    for scene, what in (("SDNV100", "DZ(N5)"), ("SDNL111 D", "DZ(N1)")):
        mine = [r for r in rows if r["scene"] == scene]
        print(f"\n{scene}: max error of {what} over the whole history, % of its peak, against the run's wall time")
        print("| scheme | HEX8 along | dt [s] | Courant | steps | max error | wall [s] |")
        print("|---|---|---|---|---|---|---|")
        for r in mine:
            print(f"| {r['scheme']} | {r['along']} | {r['dt']:.3g} | {r['courant']:.3f} | {r['steps']} | "
                  f"{r['error']:.3g} % | {r['wall']:.2f} |")
        for scheme in ("explicit", "implicit", "implicit, trapezoidal"):
            cells = []
            for target in (1.0, 0.1):
                ok = [r for r in mine if r["scheme"] == scheme and r["error"] <= target]
                best = min(ok, key=lambda r: r["wall"]) if ok else None
                cells.append(f"<= {target:g} %: " + (f"{best['along']} along, {best['error']:.3g} %, {best['wall']:.2f} s"
                                                     if best else "not reached"))
            print(f"cheapest {scheme}: " + "; ".join(cells))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="results/explicit_implicit")
    ap.add_argument("--repeat", type=int, default=2)
    a = ap.parse_args()
    choc = os.path.abspath(os.path.join(a.build, "choc"))
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    rows = sdnv100(choc, out, a.repeat) + sdnl111d(choc, out, a.repeat)
    with open(os.path.join(out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    report(rows)
    print(f"\n{os.path.join(out, 'study.csv')}")


if __name__ == "__main__":
    main()
