#!/usr/bin/env python3
"""What plane strain costs on the bare concrete check dam: examples/dam_boulder_no_buffer.json (2D: the 1 t boulder as a
cylinder of its mass across the 2 m face) against its 3D twin (examples/concrete_dam_sphere_3d.json with the crest
cut to the same 2 m and the sphere, R 0.448 m, striking the middle of the crest) at three cells. Prints the peak
contact force, base shear, base moment, base fibre tension and the governing utilisation of `damimpact check`.
docs/verification.md, "Space frames through the checks".

  bench/plane_vs_space_dam.py [--cells 0.1 0.07 0.05] [--threads 2] [--out out/plane_vs_space_dam]

Needs h5py and numpy; the 3D run at 0.05 m takes about four minutes on 2 cores."""
import argparse
import json
import math
import os
import subprocess

from simrun import EXE, ROOT, simulate


def design(out):
    r = subprocess.run([EXE, "check", out, "--json"], capture_output=True, text=True)
    if r.returncode not in (0, 1):
        raise SystemExit(r.stderr)
    run = json.loads(r.stdout)["runs"][0]
    dim = run.get("dimension", 2)
    tension = max(m["peaks"]["sigma_tension_max"]["value"] for m in run["members"])
    return {"contact_MN": run["contact"]["peak_force_N"] / 1e6,
            "shear_MN": run["base_total"]["H_N" if dim == 3 else "Fx_N"]["abs_max"]["value"] / 1e6,
            "moment_MNm": run["base_total"]["M_overturning_Nm" if dim == 3 else "M_Nm"]["abs_max"]["value"] / 1e6,
            "tension_MPa": tension / 1e6, "utilisation": run["verdict"]["max_utilisation"],
            "governing": run["verdict"]["governing"]["title"]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", type=float, nargs="+", default=[0.1, 0.07, 0.05])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "plane_vs_space_dam"))
    a = ap.parse_args()
    base = json.load(open(os.path.join(ROOT, "examples", "concrete_dam_sphere_3d.json")))
    rows = []
    for h in a.cells:
        s = json.loads(json.dumps(base))
        s["name"] = "3D twin of dam_boulder_no_buffer (2 m crest, sphere in the middle)"
        s["structure"]["members"][0]["section"]["width"] = 2.0
        s["design_basis"]["dam"]["width_m"] = 2.0
        s["bodies"][0]["shape"]["center"][1] = 0.0
        n = math.ceil(1.3 / h)  # a node plane through y = 0, the sphere and the 2 m face inside
        s["grid"]["cell_size"] = h
        s["grid"]["origin"][1] = -n * h
        s["grid"]["size"][1] = 2 * n * h
        out = os.path.join(a.out, "space_h_%g" % h)
        r, wall = simulate(s, out, a.threads)
        if r.returncode != 0:
            raise SystemExit(r.stderr)
        p = design(out)
        p.update(h=h, wall_s=wall, dim=3)
        rows.append(p)
    plane = os.path.join(a.out, "plane")
    r, wall = simulate(json.load(open(os.path.join(ROOT, "examples", "dam_boulder_no_buffer.json"))), plane, a.threads)
    if r.returncode != 0:
        raise SystemExit(r.stderr)
    p = design(plane)
    p.update(h=0.05, wall_s=wall, dim=2)
    rows.append(p)
    print("model      h (m)  contact (MN)  base shear (MN)  base moment (MN m)  base tension (MPa)  utilisation  governing  wall (s)")
    for p in rows:
        print("%-9s %6g %13.2f %16.2f %19.2f %19.2f %12.2f  %s  %.0f" % ("3D" if p["dim"] == 3 else "2D", p["h"], p["contact_MN"], p["shear_MN"],
                                                                      p["moment_MNm"], p["tension_MPa"], p["utilisation"], p["governing"], p["wall_s"]))


if __name__ == "__main__":
    main()
