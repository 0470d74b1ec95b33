"""The Taylor bar's runs shared by the CLI scripts: an input run to its end, its final shape
(impact-face radius R + EDGE:DX, length L + REAR:DY - CENTRE:DY), and the comparison of two
shapes within a relative tolerance."""
import os

import chocrun

R0, L0 = 3.2e-3, 32.4e-3  # the bar's radius and length (meshes/taylor_bar*.geo)


class ShapeRun:
    """`name` (an input of input/) run into WORK/tag without Exodus output; completed."""

    def __init__(self, choc, work, tag, name):
        d = chocrun.load_deck(chocrun.input_path(name))
        chocrun.set_param(d, "Analyses/impact/Exodus Interval", 0)
        out = os.path.join(work, tag)
        self.result = chocrun.run(choc, chocrun.write_deck(d, os.path.join(work, tag + ".xml")), out)
        self.summary = chocrun.read_summary(out, "impact")
        self.history = chocrun.read_history(out, "impact")
        chocrun.require_completed(self.summary)
        h = self.history
        self.shape = (R0 + float(h["EDGE:DX"][-1]), L0 + float(h["REAR:DY"][-1]) - float(h["CENTRE:DY"][-1]))
        self.e0 = float(h["energy:total"][0])
        self.balance = [float(b) / self.e0 for b in h["energy:balance"]]


def compare_shapes(implicit, explicit, tolerance, failures):
    """Prints the radius and length of both and appends a failure for each beyond `tolerance`."""
    for k, what in enumerate(("radius", "length")):
        a, b = implicit[k], explicit[k]
        rel = abs(a - b) / b
        print(f"{what}: implicit {a * 1e3:.4f} mm, explicit {b * 1e3:.4f} mm: {rel:.2e} apart (at most {tolerance:g})")
        if not rel <= tolerance:
            failures.append(f"implicit {what} {a * 1e3:.4f} mm against explicit {b * 1e3:.4f} mm")
