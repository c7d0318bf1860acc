#!/usr/bin/python3
"""How the debris-surge load depends on numerical and material choices (study, not a test).

Runs examples/concrete_dam_debris_surge.json (or --scenario) through the CLI with one choice changed
at a time and prints a Markdown table of the load's three phases (Cui et al. 2015):

    /usr/bin/python3 bench/debris_sensitivity.py [--study modulus|cells|shape|all] [--scenario FILE]
                                                 [--front-length L] [--cell H]

--front-length sets debris_surge.front_length (0: a blunt, vertical front; default: the preset's snout).

Variants (the preset keeps everything else):
  modulus: debris Young's modulus E = 1.25 ... 80 MPa at the preset cell (10 cells across the depth) or --cell;
  cells:   cell size h = depth / 10, / 20, / 40 at E = 5 and 20 MPa;
  froude:  front speed v = Fr sqrt(g h) for Fr = 1, 1.5, 2, 3, 4, 6 at E 20 MPa (alpha against the Froude number);
  shape:   shape functions linear, uGIMP and quadratic B-spline (the default) at depth / 20, E = 20 MPa; FLIP
           transfer and MUSL (the preset's) throughout.
Each runs `damimpact simulate FILE -o /tmp/debris_sens/<name> -q -t 1`.

Measured from results.h5 (x = horizontal, towards the dam; W the strip width):
  arrival t_a: first sample with |contact force x| > 1 % of rho v^2 h W;
  peak contact force and peak base shear |reaction x| over the whole run;
  spike impulse: integral of the contact force over [t_a, t_a + 4 h / c] (c = sqrt(M / rho), the
    P-wave speed; 4 h / c is two return trips of the front wave through the depth);
  impulse of the passage: integral over [t_a, t_a + L / v] against the surge momentum rho h (L - L_f / 2) v W
    (L_f the snout length);
  dynamic phase: mean contact force over [t_a + 0.25 L / v, t_a + L / v] (the body of the surge);
  static tail: mean over the last 0.1 s;
  alpha = force / (rho v^2 h W) for peak and dynamic phase.
Requires /usr/bin/python3 with h5py and numpy, and build/app/damimpact.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "damimpact")
TMP = "/tmp/debris_sens"
TIMEOUT_S = 900  # a run still going after this (a collapsing step) is reported as such


def variants(study, depth, cell=None):
    h0 = cell or depth / 10
    out = []
    if study == "froude":  # (name, E, h, shape, speed): Fr = v / sqrt(g h) = 1 ... 6 at E 20 MPa
        for fr in (1, 1.5, 2, 3, 4, 6):
            v = fr * math.sqrt(9.81 * depth)
            out.append(("Fr%g_h%g" % (fr, h0), 20e6, h0, None, v))
        return out
    if study in ("modulus", "all"):
        for e in (1.25e6, 2.5e6, 5e6, 10e6, 20e6, 40e6, 80e6):
            out.append(("E%g_h%g" % (e / 1e6, h0), e, h0, None, None))
    if study in ("cells", "all"):
        for e in (5e6, 20e6):
            for n in (10, 20, 40):
                out.append(("E%g_h%g" % (e / 1e6, depth / n), e, depth / n, None, None))
    if study in ("shape", "all"):
        for s in ("linear", "gimp", "bspline2"):
            out.append(("E20_h%g_%s" % (depth / 20, s), 20e6, depth / 20, s, None))
    seen, uniq = set(), []
    for v in out:
        if v[0] not in seen:
            seen.add(v[0]), uniq.append(v)
    return uniq


def run(base, name, e, h, shape, front, speed=None):
    d = json.loads(json.dumps(base))
    if speed:
        d["debris_surge"]["velocity"] = speed
    if front is not None:
        d["debris_surge"]["front_length"] = front
        name += "_front%g" % front
    d["debris_surge"].setdefault("material", {})["youngs_modulus"] = e
    d["grid"] = {"cell_size": h}
    if shape:
        d["mpm"] = {"shape_function": shape}
    os.makedirs(TMP, exist_ok=True)
    path = os.path.join(TMP, name + ".json")
    with open(path, "w") as f:
        json.dump(d, f, indent=1)
    out = os.path.join(TMP, name)
    t0 = time.time()
    try:
        r = subprocess.run([EXE, "simulate", path, "-o", out, "-q", "-t", "1"], capture_output=True, text=True, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return None, time.time() - t0
    if r.returncode != 0:
        sys.exit("%s failed (rc %d):\n%s%s" % (name, r.returncode, r.stdout, r.stderr))
    return out, time.time() - t0


def measure(out, rho, nu, e, depth, length, v, width):
    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        t = f["history/time"][()]
        fc = np.abs(f["history/frame/contact_force"][:, 0])
        vb = np.abs(f["history/supports/base/reaction"][:, 0])
        text = f["scenario_expanded"][()] if "scenario_expanded" in f else f["scenario"][()]
        basis = json.loads(text).get("design_basis", {}).get("debris_surge", {})
    front = basis.get("front_length_m", 0.0)  # the snout holds half the mass of a full-depth block its length
    flux = rho * v * v * depth * width
    m_mod = e * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    c = math.sqrt(m_mod / rho)
    ia = int(np.argmax(fc > 0.01 * flux))
    ta = t[ia]
    dt = np.diff(t, prepend=t[0])

    def integral(t0, t1):
        k = (t > t0) & (t <= t1)
        return float(np.sum(fc[k] * dt[k]))

    def mean(t0, t1):
        k = (t > t0) & (t <= t1)
        return float(np.mean(fc[k])) if k.any() else float("nan")

    tp = length / v
    return dict(c=c, ta=ta, peak=fc.max(), tpeak=t[int(np.argmax(fc))] - ta, shear=vb.max(),
                spike=integral(ta, ta + 4 * depth / c), passage=integral(ta, ta + tp),
                momentum=rho * depth * (length - front / 2) * v * width, front=front, dyn=mean(ta + 0.25 * tp, ta + tp),
                tail=mean(t[-1] - 0.1, t[-1]), flux=flux, rho_c_v=rho * c * v * depth * width)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--study", default="all", choices=["modulus", "cells", "shape", "froude", "all"])
    ap.add_argument("--front-length", type=float, default=None)
    ap.add_argument("--cell", type=float, default=None, help="cell size of the modulus study (default depth / 10)")
    ap.add_argument("--scenario", default=os.path.join(ROOT, "examples", "concrete_dam_debris_surge.json"))
    a = ap.parse_args()
    with open(a.scenario) as f:
        base = json.load(f)
    s = base["debris_surge"]
    mat = s.get("material", {})
    rho, nu = mat.get("density", 2000.0), mat.get("poisson_ratio", 0.3)
    depth, length, v = s["depth"], s["length"], s["velocity"]
    width = base["dam"].get("width", 1.0)
    print("| variant | front (m) | E (MPa) | h (m) | c (m/s) | peak contact (kN) | α peak | ρcvhW (kN) | peak base shear (kN) | "
          "spike impulse 4h/c (N s) | passage impulse / surge momentum | dynamic phase (kN) | α dynamic | static tail (kN) | wall s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, e, h, shape, speed in variants(a.study, depth, a.cell):
        out, wall = run(base, name, e, h, shape, a.front_length, speed)
        v = speed or s["velocity"]
        if out is None:
            print("| %s | | %g | %g | did not finish in %.0f s (the step collapsed) | | | | | | | | | | |" % (shape or "bspline2", e / 1e6, h, wall), flush=True)
            continue
        m = measure(out, rho, nu, e, depth, length, v, width)
        print("| %s | %.2f | %g | %g | %.0f | %.0f | %.2f | %.0f | %.0f | %.0f | %.3f | %.1f | %.2f | %.1f | %.1f |" % (
            (shape or "bspline2") + (", v %.2f m/s, Fr %.2f" % (v, v / math.sqrt(9.81 * depth)) if speed else ""), m["front"], e / 1e6, h, m["c"], m["peak"] / 1e3, m["peak"] / m["flux"], m["rho_c_v"] / 1e3,
            m["shear"] / 1e3, m["spike"], m["passage"] / m["momentum"], m["dyn"] / 1e3, m["dyn"] / m["flux"],
            m["tail"] / 1e3, wall), flush=True)


if __name__ == "__main__":
    main()
