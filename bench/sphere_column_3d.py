#!/usr/bin/env python3
"""Grid study of the 3D boulder-on-column example (examples/sdof_sphere_on_column_3d.json) and its plane-strain twin
(examples/sdof_boulder_on_column.json): peak contact force, contact time, impulse, peak base shear and moment at three
cells, against Hertz's sphere on a rigid flat face. docs/verification.md, "Member contact in 3D".

  bench/sphere_column_3d.py [--cells 0.1 0.07 0.05] [--threads 2] [--out out/sphere_column_3d]

The grid is shifted so that a node plane passes through the sphere's centre across the flow at every cell (the impact
is then symmetric on the grid). Needs h5py and numpy; a run at 0.05 m takes about a minute on 2 cores."""
import argparse
import json
import math
import os

import h5py
import numpy as np

from simrun import ROOT, simulate


def peaks(path, dim):
    h = h5py.File(path, "r")["history"]
    t = h["time"][:]
    r = h["supports/base/reaction"][:]
    cf = h["frame/contact_force"][:, 0]
    on = t[np.abs(cf) > 0.01 * np.abs(cf).max()]
    moment = r[:, 4] if dim == 3 else r[:, 2]
    return {"contact_MN": np.abs(cf).max() / 1e6, "duration_ms": (on.max() - on.min()) * 1e3, "impulse_Ns": np.trapz(cf, t),
            "shear_MN": np.abs(r[:, 0]).max() / 1e6, "moment_MNm": np.abs(moment).max() / 1e6}


def hertz_rigid_face(m, v, R, E, nu):
    """Peak force of an elastic sphere on a rigid flat (Johnson 1985, ch. 11): E* = E / (1 - nu^2)."""
    Es = E / (1 - nu * nu)
    d = (15 * m * v * v / (16 * Es * math.sqrt(R))) ** 0.4
    return 4.0 / 3.0 * Es * math.sqrt(R) * d ** 1.5


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", type=float, nargs="+", default=[0.1, 0.07, 0.05])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "sphere_column_3d"))
    a = ap.parse_args()
    base = json.load(open(os.path.join(ROOT, "examples", "sdof_sphere_on_column_3d.json")))
    ball = base["bodies"][0]["shape"]
    rows = []
    for h in a.cells:
        s = json.loads(json.dumps(base))
        s["grid"]["cell_size"] = h
        n = math.floor(1.19 / h + 1e-9)  # a node plane through y = 0
        s["grid"]["origin"][1] = -n * h
        s["grid"]["size"][1] = 2 * n * h
        out = os.path.join(a.out, "h_%g" % h)
        r, wall = simulate(s, out, a.threads)
        if r.returncode != 0:
            raise SystemExit(r.stderr)
        p = peaks(os.path.join(out, "results.h5"), 3)
        p.update(h=h, wall_s=wall)
        rows.append(p)
    plane = os.path.join(a.out, "plane")
    r, wall = simulate(json.load(open(os.path.join(ROOT, "examples", "sdof_boulder_on_column.json"))), plane, a.threads)
    p2 = peaks(os.path.join(plane, "results.h5"), 2)
    m = 2650 * 4.0 / 3.0 * math.pi * ball["radius"] ** 3
    hz = hertz_rigid_face(m, 5.0, ball["radius"], 50e9, 0.25) / 1e6
    print("h (m)   R/h   contact (MN)  vs Hertz  time (ms)  impulse (N s)  base shear (MN)  base moment (MN m)  wall (s)")
    for p in rows:
        print("%-7g %5.1f %12.2f %+9.1f%% %10.2f %14.0f %16.2f %19.2f %9.1f" % (p["h"], ball["radius"] / p["h"], p["contact_MN"], 100 * (p["contact_MN"] / hz - 1),
                                                                           p["duration_ms"], p["impulse_Ns"], p["shear_MN"], p["moment_MNm"], p["wall_s"]))
    print("plane strain (2D example): contact %.2f MN over %.2f ms, impulse %.0f N s, base shear %.2f MN, moment %.2f MN m" %
          (p2["contact_MN"], p2["duration_ms"], p2["impulse_Ns"], p2["shear_MN"], p2["moment_MNm"]))
    print("Hertz, sphere (m %.0f kg, R %.3f m, 5 m/s) on a rigid flat: %.2f MN" % (m, ball["radius"], hz))


if __name__ == "__main__":
    main()
