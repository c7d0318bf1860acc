#!/usr/bin/python3
"""One surge by two routes: a block released next to the dam, and the same surge fed through an inflow section
(study, not a test; docs/verification.md, "Inflow boundary").

The block: debris_surge depth 1 m, length 6 m, 6 m/s, snout 2.4 m, gap 0.2 m, on a frictionless horizontal bed (so
that neither route loses speed on its way), Drucker-Prager phi 32 deg, against the 4 m concrete dam of the examples.
The hydrograph: the same surge passing a section -- depth 0 -> 1 m over 0.4 s (the snout at 6 m/s), 1 m until 1.0 s,
6 m/s throughout: the same 4.8 m^3 per metre, 9 600 kg -- entering the default section_distance (2 V / H + 2 h =
4.4 m) upstream. Both at cell sizes 0.1, 0.05, 0.025 m:

    /usr/bin/python3 bench/inflow_crosscheck.py [--cells 0.1,0.05,0.025] [--threads 1]

Printed (Markdown): the peak contact force, the dynamic phase (design.json debris_phases), the impulse of the contact
force over [arrival, arrival + 1.5 s], the inflow's mass, and the driven zone's impulse on the debris (the upstream
thrust of a fed flow, which a released block does not have). Runs `damimpact run FILE -o /tmp/inflow_xc/<name> -q
--no-report`. Requires /usr/bin/python3 with h5py and numpy, and build/app/damimpact.
"""
import argparse
import json
import os
import subprocess
import time

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "damimpact")
TMP = "/tmp/inflow_xc"
DAM = {"type": "concrete_gravity", "height": 4.0, "crest_thickness": 1.0, "base_thickness": 1.6, "width": 1.0}
BED = {"channel_slope": 0, "bed_friction": 0, "material": {"friction_angle": 32}}
ROUTES = {
    "block": dict(BED, depth=1.0, length=6.0, velocity=6.0, front_length=2.4, gap=0.2),
    "inflow": dict(BED, hydrograph={"time": [0, 0.4, 1.0], "depth": [0, 1.0, 1.0], "velocity": [6, 6, 6]}),
}


def run(route, cell, threads):
    name = "%s_h%g" % (route, cell)
    os.makedirs(TMP, exist_ok=True)
    scen = os.path.join(TMP, name + ".json")
    with open(scen, "w") as f:
        json.dump({"schema_version": 1, "name": name, "dam": DAM, "debris_surge": ROUTES[route], "grid": {"cell_size": cell}}, f)
    out = os.path.join(TMP, name)
    t0 = time.time()
    subprocess.run([EXE, "run", scen, "-o", out, "-q", "--no-report", "-t", str(threads)], check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.time() - t0
    phases = json.load(open(os.path.join(out, "design.json")))["runs"][0]["debris_phases"]
    H = h5py.File(os.path.join(out, "results.h5"), "r")["history"]
    t, F = H["time"][:], H["frame/contact_force"][:, 0]
    dt = np.diff(t, prepend=0.0)  # forces are interval means: sum F dt is the exact impulse
    a = phases["arrival_s"]
    window = (t > a) & (t <= a + 1.5)
    row = {"peak": phases["peak_N"] / 1e3, "dynamic": phases["dynamic_N"] / 1e3, "impulse": (F[window] * dt[window]).sum() / 1e3,
           "wall": wall, "mass": None, "zone": None}
    if "inflows" in H:
        row["mass"] = H["inflows/debris/mass"][-1, 0]
        row["zone"] = -(H["inflows/debris/force"][:, 0] * dt).sum() / 1e3
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", default="0.1,0.05,0.025")
    ap.add_argument("--threads", type=int, default=1)
    a = ap.parse_args()
    print("| route | h (m) | peak contact (kN) | dynamic phase (kN) | impulse, arrival + 1.5 s (kN s) | mass entered (kg) | zone impulse (kN s) | wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for cell in (float(c) for c in a.cells.split(",")):
        for route in ROUTES:
            r = run(route, cell, a.threads)
            extra = ("%.1f | %.2f" % (r["mass"], r["zone"])) if r["mass"] is not None else "– | –"
            print("| %s | %g | %.1f | %.1f | %.2f | %s | %.1f |" % (route, cell, r["peak"], r["dynamic"], r["impulse"], extra, r["wall"]), flush=True)


if __name__ == "__main__":
    main()
