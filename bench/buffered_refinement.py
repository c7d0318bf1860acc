#!/usr/bin/env python3
"""The buffered demo dam under refinement, in 2D and in 3D (docs/verification.md, "The buffered demo dam converges
under refinement to h = 0.01 m" and "What plane strain costs").

Runs examples/concrete_dam_boulder_buffer.json without `compare` and without the solid check (the buffered variant
alone) at the given cells, in 2D and optionally in 3D ("analysis": {"dimension": 3}, the boulder's velocity along x),
and prints per cell the peak base shear, base moment and contact force on the member with the wall time, then the
observed order, the extrapolated value and the GCI (Fs 1.25) from the three finest cells (bench/buffer_convergence.py's
triple: no extrapolation when oscillating, diverging or below order 0.5).

  bench/buffered_refinement.py [--cells2d 0.04 0.0283 0.02 0.0141 0.01] [--cells3d 0.1 0.0707 0.05]
                               [--threads 2] [--out out/buffered_refinement]

Needs h5py and numpy; 2D at 0.01 m takes about 70 s on 2 cores, 3D at 0.05 m about 2.5 min (0.0354 m: 9 min)."""
import argparse
import json
import math
import os
import subprocess

import h5py
import numpy as np

from buffer_convergence import triple
from simrun import EXE, ROOT, simulate


def peaks(out, dim):
    if dim == 3:
        r = subprocess.run([EXE, "check", out, "--json"], capture_output=True, text=True)
        if r.returncode not in (0, 1):
            raise SystemExit(r.stderr)
        run = json.loads(r.stdout)["runs"][0]
        return {"base shear": run["base_total"]["H_N"]["abs_max"]["value"],
                "base moment": run["base_total"]["M_overturning_Nm"]["abs_max"]["value"],
                "contact": run["contact"]["peak_force_N"]}
    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        h = f["history"]
        r = h["supports/base/reaction"][:]
        return {"base shear": float(np.abs(r[:, 0]).max()), "base moment": float(np.abs(r[:, 2]).max()),
                "contact": float(np.linalg.norm(h["frame/contact_force"][:], axis=1).max())}


def run(cells, dim, threads, out_root):
    base = json.load(open(os.path.join(ROOT, "examples", "concrete_dam_boulder_buffer.json")))
    base.pop("compare", None)
    base.pop("solid_check", None)
    if dim == 3:
        base["analysis"] = {"dimension": 3}
        base["boulder"]["velocity"] = base["boulder"]["velocity"] + [0]
    rows = []
    for h in cells:
        s = json.loads(json.dumps(base))
        s["grid"] = {"cell_size": h}
        out = os.path.join(out_root, "%dd_h_%g" % (dim, h))
        r, wall = simulate(s, out, threads)
        if r.returncode != 0:
            raise SystemExit(r.stderr)
        rows.append((h, peaks(out, dim), wall))
    print("\n%dD, buffered variant" % dim)
    print("h (m)    base shear (kN)  base moment (kN m)  contact (kN)  wall (s)")
    for h, p, wall in rows:
        print("%-8.4g %15.1f %19.1f %13.1f %9.1f" % (h, p["base shear"] / 1e3, p["base moment"] / 1e3, p["contact"] / 1e3, wall))
    if len(rows) >= 3:
        hs = [h for h, _, _ in rows[-3:]]
        for k in ("base shear", "base moment", "contact"):
            p, ext, note = triple(hs, [q[k] for _, q, _ in rows[-3:]])
            if math.isfinite(ext):  # GCI (Fs 1.25) = 1.25 |f1 - f2| / f1 / (r^p - 1) = 1.25 |ext - f1| / f1
                f1 = rows[-1][1][k]
                print("%-12s order %.2f, extrapolated %.1f, GCI %.1f %%" % (k, p, ext / 1e3, 125 * abs(ext - f1) / abs(f1)))
            else:
                print("%-12s %s%s" % (k, note, "" if not math.isfinite(p) else " (order %.2f)" % p))

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells2d", type=float, nargs="*", default=[0.04, 0.04 / math.sqrt(2), 0.02, 0.02 / math.sqrt(2), 0.01])
    ap.add_argument("--cells3d", type=float, nargs="*", default=[0.1, 0.1 / math.sqrt(2), 0.05])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "buffered_refinement"))
    a = ap.parse_args()
    if a.cells2d:
        run(a.cells2d, 2, a.threads, a.out)
    if a.cells3d:
        run(a.cells3d, 3, a.threads, a.out)


if __name__ == "__main__":
    main()
