"""The d'Alembert exact solution of the SDNL111 two-bar impact (docs/verification/benchmarks.md),
in Python.

An independent re-implementation of src/reference/BarImpactExact.cpp for the report and the
plots: same closed forms, same parameter defaults, same floating-point operation order, so
both should agree to round-off. Also reads a choc input (Teuchos XML parameter list).

With tau = 2L/c and s = (t - t0)/tau:
  unilateral: s < 0 A approaches at v0; 0 <= s < 1 A moves at v0/2; 1 <= s < 2 at -v0/2;
              s >= 2 the contact opens and AB leaves at -v0.
  bilateral:  triangle wave of amplitude |v0| L/c and period 4 tau, starting at v0/2.
  force (compression positive): Z|v0|/2 while in contact, Z = rho c S; bilateral: +Z|v0|/2 on
  [2k tau, 2(k+1) tau) for even k, -Z|v0|/2 for odd k. Right limits at discontinuities.
"""
import math
import xml.etree.ElementTree as ET

import numpy as np

# The check type and the defaults of its parameters (src/checks/BarImpactCheck.cpp).
EXACT_CHECK_TYPE = "Bar Impact Exact Solution"
EXACT_DEFAULTS = {
    "Node Set": "A", "Component": "DX", "Wave Speed": "bar",
    "Given Wave Speed": 0.0, "Length": 1.0, "Section Area": 4e-4, "Impact Velocity": -1.0,
    "Contact Start": 0.0, "Bilateral": False, "Force Column": "",
    "Max Error Tolerance": 0.0, "RMS Error Tolerance": 0.0,
    "Obstacle": "bar", "Point": "contact end",
}


def _value(elem):
    kind, text = elem.get("type", "string"), elem.get("value", "")
    if kind == "bool":
        return text.strip().lower() in ("true", "1", "yes")
    if kind == "int":
        return int(text)
    if kind == "double":
        return float(text)
    return text


def _plist(elem):
    out = {}
    for child in elem:
        if child.tag == "ParameterList":
            out[child.get("name")] = _plist(child)
        elif child.tag == "Parameter":
            out[child.get("name")] = _value(child)
    return out


def read_input(path):
    """A choc input file as nested dicts (sublists are dicts, parameters typed values)."""
    return _plist(ET.parse(path).getroot())


class BarImpactExact:
    def __init__(self, length, wave_speed, impedance, impact_velocity=-1.0, contact_start=0.0,
                 bilateral=False, rigid_wall=False, free_end=False):
        for name, v in (("length", length), ("wave speed", wave_speed), ("impedance", impedance)):
            if not (math.isfinite(v) and v > 0):
                raise ValueError(f"exact solution: {name} {v!r} must be > 0")
        if not math.isfinite(impact_velocity) or impact_velocity == 0:
            raise ValueError(f"exact solution: impact velocity {impact_velocity!r} must be non-zero")
        if not (math.isfinite(contact_start) and contact_start >= 0):
            raise ValueError(f"exact solution: contact start {contact_start!r} must be >= 0")
        self.length, self.c, self.z = length, wave_speed, impedance
        self.v0, self.t0, self.bilateral = impact_velocity, contact_start, bilateral
        if rigid_wall and bilateral:
            raise ValueError("exact solution: a rigid wall is unilateral")
        if free_end and not rigid_wall:
            raise ValueError("exact solution: the free end is available against a rigid wall only")
        self.rigid_wall, self.free_end = rigid_wall, free_end
        self.tau = 2.0 * length / wave_speed

    @staticmethod
    def bar_wave_speed(e, rho):
        return math.sqrt(e / rho)

    @staticmethod
    def oedometric_wave_speed(e, nu, rho):
        if not -1.0 < nu < 0.5:
            raise ValueError(f"exact solution: Poisson's ratio {nu!r} must lie in (-1, 0.5)")
        return math.sqrt(e * (1.0 - nu) / (rho * (1.0 + nu) * (1.0 - 2.0 * nu)))

    def _phase(self, t):
        t = np.asarray(t, dtype=float)
        if not np.all(np.isfinite(t)) or np.any(t < 0):
            raise ValueError("exact solution: times must be finite and >= 0")
        return t, (t - self.t0) / self.tau

    def displacement(self, t):
        t, s = self._phase(t)
        v0 = self.v0
        if self.rigid_wall:  # the free end turns at s = 1/2, the contact end at s = 1
            start, turn = (0.5, 0.5) if self.free_end else (0.0, 1.0)
            held = v0 * (self.t0 + (0.5 * self.tau if self.free_end else 0.0))
            after = np.where(s < turn, held, held - v0 * (t - self.t0 - turn * self.tau))
            return np.where(s < start, v0 * t, after)
        if self.bilateral:
            r = s - 4.0 * np.floor(s / 4.0)
            g = np.where(r < 1.0, r, np.where(r < 3.0, 2.0 - r, r - 4.0))
        else:
            g = np.where(s < 1.0, s, np.where(s < 2.0, 2.0 - s, -2.0 * (s - 2.0)))
        return np.where(t < self.t0, v0 * t, v0 * self.t0 + 0.5 * v0 * self.tau * g)

    def velocity(self, t):
        t, s = self._phase(t)
        v0 = self.v0
        if self.rigid_wall:
            if self.free_end:
                return np.where(s < 0.5, v0, -v0)
            return np.where(s < 0.0, v0, np.where(s < 1.0, 0.0, -v0))
        if self.bilateral:
            r = s - 4.0 * np.floor(s / 4.0)
            v = np.where((r < 1.0) | (r >= 3.0), 0.5 * v0, -0.5 * v0)
        else:
            v = np.where(s < 1.0, 0.5 * v0, np.where(s < 2.0, -0.5 * v0, -v0))
        return np.where(t < self.t0, v0, v)

    def force_magnitude(self):
        return (1.0 if self.rigid_wall else 0.5) * self.z * abs(self.v0)

    def force(self, t):
        t, s = self._phase(t)
        f = self.force_magnitude()
        if self.rigid_wall:
            v = np.where(s < 1.0, f, 0.0)
        elif self.bilateral:
            k = np.floor(s / 2.0)
            v = np.where(np.fmod(k, 2.0) == 0.0, f, -f)
        else:
            v = np.where(s < 2.0, f, 0.0)
        return np.where(t < self.t0, 0.0, v)

    def peak_displacement(self):
        if self.rigid_wall:
            return abs(self.v0) * (self.t0 + (0.5 * self.tau if self.free_end else 0.0))
        return abs(self.v0) * (self.t0 + 0.5 * self.tau)


class ExactSpec:
    """The 'Bar Impact Exact Solution' check of one analysis, resolved with the input's material."""

    def __init__(self, params, material, wave_speed, exact):
        self.params, self.material, self.wave_speed, self.exact = params, material, wave_speed, exact
        self.ucol = params["Node Set"] + ":" + params["Component"]
        self.vcol = params["Node Set"] + ":V" + params["Component"][1:]
        self.fcol = params["Force Column"]


def exact_for_analysis(inp, analysis):
    """ExactSpec for Analyses/<analysis> of a read_input() dict, or None when not enabled.
    Raises ValueError (with the reason) when the input does not define what is needed."""
    specs = exact_specs_for_analysis(inp, analysis)
    return specs[0] if specs else None


def exact_specs_for_analysis(inp, analysis):
    """An ExactSpec per 'Bar Impact Exact Solution' check of Analyses/<analysis>, in order."""
    an = inp.get("Analyses", {}).get(analysis)
    if an is None:
        raise ValueError(f"no analysis '{analysis}' in the input")
    rows = [c for c in an.get("Checks", {}).values()
            if isinstance(c, dict) and c.get("Type") == EXACT_CHECK_TYPE]
    return [_exact_spec(inp, row) for row in rows]


def _exact_spec(inp, row):
    p = dict(EXACT_DEFAULTS)
    p.update(row)
    mats = inp.get("Model", {}).get("Materials", {})
    if not mats:
        raise ValueError("no Model/Materials in the input")
    mname = sorted(mats)[0]
    if len(mats) > 1:  # the C++ takes the material of the block holding the node
        blocks = inp.get("Model", {}).get("Blocks", {})
        used = {b.get("Material") for b in blocks.values()}
        if len(used) == 1 and used <= set(mats):
            mname = used.pop()
    m = mats[mname]
    e, rho, nu = m["Young's Modulus"], m["Density"], m.get("Poisson's Ratio", 0.0)
    ws = p["Wave Speed"]
    if ws == "bar":
        c = BarImpactExact.bar_wave_speed(e, rho)
    elif ws == "oedometric":
        c = BarImpactExact.oedometric_wave_speed(e, nu, rho)
    else:
        c = p["Given Wave Speed"]
    exact = BarImpactExact(p["Length"], c, rho * c * p["Section Area"], p["Impact Velocity"],
                           p["Contact Start"], p["Bilateral"], p["Obstacle"] == "rigid wall",
                           p["Point"] == "free end")
    return ExactSpec(p, dict(m, name=mname), ws, exact)


def history_error(times, values, reference):
    """Same as src/reference/HistoryError.cpp: max |y - r|, its first time, RMS, peak max |r|."""
    d = np.abs(values - reference)
    i = int(np.argmax(d))
    peak = float(np.max(np.abs(reference)))
    if not peak > 0:
        raise ValueError("the reference is 0 at every sample")
    rms = math.sqrt(float(np.sum(d * d)) / len(d))
    return {"max": float(d[i]), "time_of_max": float(times[i]), "rms": rms, "peak": peak,
            "max_rel": float(d[i]) / peak, "rms_rel": rms / peak}
