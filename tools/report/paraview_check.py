#!/usr/bin/env pvbatch
"""Checks choc's transient Exodus results as ParaView reads them.

usage: pvbatch tools/report/paraview_check.py RUN_DIR [--input FILE.xml] [--node-sets A,B,...]
                                       [--side-sets S1,...] [--rtol-peak 1e-12]

RUN_DIR is one run's results directory (checks.csv, <analysis>.history.csv, <analysis>.exo).
For every <analysis>.exo with a history beside it, with both of ParaView's Exodus readers
(IOSSReader, what File > Open picks in 5.11, and the legacy ExodusIIReader):
  - the time steps: every 'Exodus Interval'-th time of the history (from the input file, else
    inferred from the second step) plus the last one, to 1e-9 of a step;
  - the nodal variables grouped into 3-component vectors DISP, VEL, ACC (the names ParaView
    shows are printed: IOSS says 'DISP', the legacy reader 'DISP_');
  - the node sets and side sets by name (default: A, B, C, D, POU1, POU2 for a mesh of line
    elements; POU1, POU2, N1 and side sets CNT_POU1, CNT_POU2 for a solid mesh); IOSS shows
    the names in lower case, the legacy reader as written;
  - for every history column <set>:D<X|Y|Z> of a one-node set, the node's DISP component read
    through ParaView's node set equals the history at five times spread over the run, to
    --rtol-peak of the column's peak (both come from the same numbers).
Exit 0 when everything holds, 1 otherwise (every failure is printed).
"""
import argparse
import csv
import glob
import os
import sys
import xml.etree.ElementTree as ET

from paraview.simple import Delete, ExodusIIReader, IOSSReader

FAILURES = []


def fail(msg):
    FAILURES.append(msg)
    print("FAIL: " + msg)


def ok(msg):
    print("ok:   " + msg)


def read_history(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = rows[0]
    cols = {n: [float(r[i]) for r in rows[1:]] for i, n in enumerate(names)}
    return names, cols


def exodus_interval(xml, analysis):
    if not xml:
        return None
    root = ET.parse(xml).getroot()
    for pl in root.iter("ParameterList"):
        if pl.get("name") == "Analyses":
            for an in pl.findall("ParameterList"):
                if an.get("name") == analysis:
                    for p in an.findall("Parameter"):
                        if p.get("name") == "Exodus Interval":
                            return int(p.get("value"))
                    return 10  # choc's default ('choc parameters')
    return None


def timesteps(reader):
    tv = reader.TimestepValues
    try:
        return [float(x) for x in tv]
    except TypeError:
        return [float(tv)] if tv is not None else []


def check_times(label, steps, t, interval):
    dt = t[1] - t[0] if len(t) > 1 else 1.0
    if interval is None:  # infer it from the second step
        interval = min(range(len(t)), key=lambda i: abs(t[i] - steps[1])) if len(steps) > 1 else 1
        how = "inferred"
    else:
        how = "from the input"
    idx = list(range(0, len(t), interval))
    if idx[-1] != len(t) - 1:
        idx.append(len(t) - 1)
    want = [t[i] for i in idx]
    if len(steps) != len(want):
        fail(f"{label}: {len(steps)} time steps, {len(want)} expected (history of {len(t)} rows, "
             f"interval {interval} {how})")
        return
    worst = max(abs(a - b) for a, b in zip(steps, want))
    if worst > 1e-9 * dt:
        fail(f"{label}: time steps differ from the history's by up to {worst:.3g} s")
    else:
        ok(f"{label}: {len(steps)} time steps = the history's every {interval}th time ({how}) "
           f"and the last, {want[0]:g} to {want[-1]:g} s (max diff {worst:.1e} s)")


def check_vectors(label, point_data, suffix):
    names = list(point_data.keys())
    for base in ("DISP", "VEL", "ACC"):
        name = base + suffix
        if name not in names:
            fail(f"{label}: no point array '{name}' (ParaView shows: {', '.join(names)})")
            continue
        n = point_data[name].GetNumberOfComponents()
        if n != 3:
            fail(f"{label}: '{name}' has {n} components, 3 expected")
    if not [f for f in FAILURES if f.startswith(label)]:
        ok(f"{label}: point arrays {', '.join(names)}; DISP, VEL, ACC shown as "
           f"'DISP{suffix}', 'VEL{suffix}', 'ACC{suffix}' with 3 components")


def check_sets(label, available, expected, kind, lower):
    have = set(available)
    want = {e.lower() if lower else e for e in expected}
    missing = sorted(want - have)
    if missing:
        fail(f"{label}: {kind} {', '.join(missing)} missing (ParaView lists: {', '.join(sorted(have))})")
    else:
        ok(f"{label}: {kind} {', '.join(sorted(want))} present (ParaView lists: "
           f"{', '.join(available)})")


def node_set_block(reader, set_name):
    """The vtkUnstructuredGrid of a node set in the IOSS reader's output, or None."""
    out = reader.GetClientSideObject().GetOutputDataObject(0)
    for i in range(out.GetNumberOfPartitionedDataSets()):
        md = out.GetMetaData(i) if out.HasMetaData(i) else None
        if md is None or md.Get(out.NAME()) != set_name:
            continue
        pds = out.GetPartitionedDataSet(i)
        for k in range(pds.GetNumberOfPartitions()):
            b = pds.GetPartition(k)
            if b is not None and b.GetNumberOfPoints() > 0:
                return b
    return None


def check_values(label, reader, steps, t, cols, names):
    comps = {"DX": 0, "DY": 1, "DZ": 2}
    probes = [n for n in names if ":" in n and n.split(":")[1] in comps]
    if not probes:
        ok(f"{label}: no displacement column in the history to compare")
        return
    sets = sorted({n.split(":")[0] for n in probes})
    reader.NodeSets = [s.lower() for s in sets]
    # five steps spread over the run (skip t = 0, where everything is 0)
    picks = sorted({steps[min(len(steps) - 1, max(1, round(k * (len(steps) - 1) / 5)))]
                    for k in range(1, 6)})
    for col in probes:
        s, c = col.split(":")
        peak = max(abs(v) for v in cols[col]) or 1.0
        worst, compared, single = 0.0, 0, True
        for tt in picks:
            reader.UpdatePipeline(tt)
            b = node_set_block(reader, s.lower())
            if b is None:
                fail(f"{label}: ParaView gives no data for node set {s}")
                single = False
                break
            if b.GetNumberOfPoints() != 1:
                ok(f"{label}: node set {s} has {b.GetNumberOfPoints()} nodes; {col} not compared")
                single = False
                break
            v = b.GetPointData().GetArray("DISP").GetComponent(0, comps[c])
            i = min(range(len(t)), key=lambda j: abs(t[j] - tt))
            worst = max(worst, abs(v - cols[col][i]))
            compared += 1
        if not single:
            continue
        if worst > args.rtol_peak * peak:
            fail(f"{label}: {s}'s DISP_{c[1]} differs from the history's {col} by {worst:.3g} "
                 f"({worst / peak:.3g} of peak {peak:.4g})")
        else:
            ok(f"{label}: {s}'s DISP_{c[1]} = history {col} at {compared} times "
               f"({', '.join(f'{x:g}' for x in picks)} s): max diff {worst:.2g} "
               f"({worst / peak:.2g} of peak {peak:.4g})")


def check_file(exo, analysis, hist, xml):
    names, cols = read_history(hist)
    t = cols["time"]
    interval = exodus_interval(xml, analysis)
    label = os.path.basename(exo)

    r = IOSSReader(FileName=[exo])
    r.ApplyDisplacements = 0
    r.UpdatePipelineInformation()
    steps = timesteps(r)
    check_times(f"{label} (IOSS)", steps, t, interval)
    r.UpdatePipeline(steps[-1] if steps else 0.0)
    check_vectors(f"{label} (IOSS)", r.PointData, "")
    b = r.GetDataInformation().GetBounds()
    solid = sum(1 for k in range(3) if b[2 * k + 1] - b[2 * k] > 0) >= 2  # else line elements
    ns = args.node_sets.split(",") if args.node_sets else \
        (["POU1", "POU2", "N1"] if solid else ["A", "B", "C", "D", "POU1", "POU2"])
    ss = args.side_sets.split(",") if args.side_sets is not None else \
        (["CNT_POU1", "CNT_POU2"] if solid else [])
    ss = [x for x in ss if x]
    check_sets(f"{label} (IOSS)", list(r.NodeSets.Available), ns, "node sets", True)
    if ss:
        check_sets(f"{label} (IOSS)", list(r.SideSets.Available), ss, "side sets", True)
    check_values(f"{label} (IOSS)", r, steps, t, cols, names)
    Delete(r)

    e = ExodusIIReader(FileName=[exo])
    e.UpdatePipelineInformation()
    check_times(f"{label} (ExodusII)", timesteps(e), t, interval)
    e.PointVariables = list(e.PointVariables.Available)
    e.UpdatePipeline(timesteps(e)[-1])
    check_vectors(f"{label} (ExodusII)", e.PointData, "_")
    check_sets(f"{label} (ExodusII)", list(e.NodeSetArrayStatus.Available), ns, "node sets", False)
    if ss:
        check_sets(f"{label} (ExodusII)", list(e.SideSetArrayStatus.Available), ss, "side sets", False)
    Delete(e)


def main():
    global args
    ap = argparse.ArgumentParser()
    ap.add_argument("run_dir")
    ap.add_argument("--input", help="the run's input file (for its 'Exodus Interval')")
    ap.add_argument("--node-sets", help="comma-separated node set names expected")
    ap.add_argument("--side-sets", help="comma-separated side set names expected ('' for none)")
    ap.add_argument("--rtol-peak", type=float, default=1e-12)
    args = ap.parse_args()
    found = 0
    for exo in sorted(glob.glob(os.path.join(args.run_dir, "*.exo"))):
        analysis = os.path.basename(exo)[:-len(".exo")]
        hist = os.path.join(args.run_dir, analysis + ".history.csv")
        if not os.path.exists(hist):
            print(f"skip: {os.path.basename(exo)} (no history: a modal or incomplete result)")
            continue
        found += 1
        try:
            check_file(exo, analysis, hist, args.input)
        except Exception as ex:  # noqa: BLE001
            fail(f"{os.path.basename(exo)}: {type(ex).__name__}: {ex}")
    if not found:
        fail(f"no transient Exodus result with a history in {args.run_dir}")
    print(f"paraview_check: {found} file(s), {len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0


args = None
if __name__ == "__main__":
    sys.exit(main())
