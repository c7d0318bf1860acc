#!/usr/bin/python3
"""The dynamic impact coefficient alpha = F / (rho v^2 h w) of a steady stream against a wall, over the Froude
number, against the reflected bore of shallow-water theory (study, not a test; docs/verification.md, "alpha
against the Froude number").

Set-up (2D plane strain, per metre of width): water (the Newtonian slurry, rho 1000 kg/m3, 1e-3 Pa s, weakly
compressible with c0 = 10 v) enters a frictionless horizontal channel through an inflow section with depth h0 = 0.1 m
and velocity v = Fr sqrt(g h0), runs L = 4 m and strikes a vertical slip wall. The stream first shoots up the wall,
falls back and forms a bore that travels upstream at c; between the bore and the wall the water rests at depth H.
Mass and momentum across the bore (Stoker 1957, ch. 10; the debris-impact form of Armanini 1997):
    c (H - h0) = v h0,   (eta - 1)^2 (eta + 1) = 2 eta Fr^2   with eta = H / h0,
and the wall carries the hydrostatic thrust of the rest state, F = rho g H^2 / 2, so
    alpha_bore = eta^2 / (2 Fr^2),   c = v / (eta - 1).
No parameter of the model is fitted: the reference is conservation of mass and momentum with hydrostatic pressure
(exact when the bore is long against H). The run ends before the bore reaches the inflow section.

Printed (Markdown): per Fr and cell size, the peak alpha (the jet), the mean alpha over the last third of the run
(the bore state) and the spread of the means of its three thirds (the sloshing of the roller), the mean depth
0.1-0.4 m from the wall (it counts the falling spray, so it reads high), the speed of the bore's toe (where the
depth first exceeds 1.5 h0, fitted over the last ten snapshots), each against theory, and wall time. By momentum
over the channel, the mean wall force is rho v^2 h0 + rho g h0^2/2 + rho v h0 c (the stream the bore stops), which
is the theory's alpha when c is the bore's speed: alpha and the toe speed test the same balance twice.

    /usr/bin/python3 bench/alpha_froude.py [--fr 1.5,2,3,4] [--cells 0.025,0.0125] [--threads 2] [--length 4]
                                           [--viscosity 1e-3] [--volume-relaxation 0]

Runs `damimpact simulate FILE -o /tmp/alpha_fr/<name> -q`. Requires /usr/bin/python3 with h5py and numpy, and
build/app/damimpact.
"""
import argparse
import math
import os

import h5py
import numpy as np

from simrun import simulate

TMP = "/tmp/alpha_fr"
G, RHO, H0, L, X_IN = 9.81, 1000.0, 0.1, 4.0, 0.5


def bore(fr):
    """eta = H / h0 of the bore reflected by a wall: the root > 1 of (eta - 1)^2 (eta + 1) = 2 eta Fr^2."""
    lo, hi = 1.0, 2.0 + 2.0 * fr
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (mid - 1) ** 2 * (mid + 1) - 2 * mid * fr * fr < 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def scenario(fr, cell, mu=1e-3, relax=0.0):
    v = fr * math.sqrt(G * H0)
    eta = bore(fr)
    c = v / (eta - 1)
    x_wall = X_IN + L
    end = L / v + 0.75 * (L - 0.3) / c
    vf = v + 2 * math.sqrt(G * H0)  # the front on the dry bed runs ahead at v + 2 sqrt(g h0) (Ritter's dry-bed wave)
    ymax = max(1.5 * eta * H0, H0 + 2.5 * vf * vf / (2 * G)) + 0.1  # splashes leave faster than they came
    return end, {
        "schema_version": 1,
        "name": "alpha-Fr Fr=%g h=%g" % (fr, cell),
        "analysis": {"dimension": 2, "plane": "strain", "end_time": round(end, 3), "cfl": 0.5, "gravity": [0, -G]},
        "mpm": {"shape_function": "bspline2", "transfer": "apic"},
        "grid": {"origin": [0, -8 * cell], "size": [x_wall + 8 * cell, ymax + 8 * cell], "cell_size": cell},
        "materials": [{"name": "water", "model": "newtonian", "density": RHO, "bulk_modulus": RHO * (10 * v) ** 2,
                       "viscosity": mu, "volume_relaxation": relax}],
        "bodies": [{"name": "stream", "material": "water", "particles_per_cell": 2,
                    "inflow": {"point": [X_IN, 0], "direction": [1, 0],
                               "hydrograph": {"time": [0, 0.05, end + 1], "depth": [0, H0, H0], "velocity": [v, v, v]}}}],
        "walls": [{"name": "bed", "type": "plane", "point": [0, 0], "normal": [0, 1], "condition": "slip"},
                  {"name": "upstream_end", "type": "plane", "point": [0.1, 0], "normal": [1, 0], "condition": "slip"},
                  {"name": "barrier", "type": "plane", "point": [x_wall, 0], "normal": [-1, 0], "condition": "slip"}],
        "output": {"vtk": False, "snapshot_interval": round(end / 30, 4), "history_interval": 0.005},
    }


def depth_profile(x, vol, bin_w, nbins):
    """Depth per bin along the channel: the particles' area in the bin over its width."""
    idx = np.clip((x[:, 0] / bin_w).astype(int), 0, nbins - 1)
    area = np.zeros(nbins)
    np.add.at(area, idx, vol)
    return area / bin_w


def bore_toe(x, vol):
    """The bore's toe: walking upstream from the wall, the end of the water deeper than 1.5 h0 (bins 0.05 m; a
    single shallower bin, a trough of the roller, does not end it)."""
    bw = 0.05
    nb = int((X_IN + L) / bw) + 1
    d = depth_profile(x, vol, bw, nb)
    k = nb - 2
    while k > 1 and (d[k] > 1.5 * H0 or d[k - 1] > 1.5 * H0):
        k -= 1
    return (k + 1) * bw, d


def run(fr, cell, threads, mu, relax=0.0):
    end, sc = scenario(fr, cell, mu, relax)
    name = "fr%g_h%g_mu%g_L%g_r%g" % (fr, cell, mu, L, relax)
    out = os.path.join(TMP, name)
    r, wall = simulate(sc, out, threads)
    if r.returncode != 0:
        raise SystemExit("%s failed: %s" % (name, r.stderr[-400:]))
    v = fr * math.sqrt(G * H0)
    eta = bore(fr)
    q = RHO * v * v * H0
    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        t = f["history/time"][:]
        F = f["history/walls/barrier/force"][:, 0]
        late = t > end - (end - L / v) / 3
        thirds = [F[w].mean() / q for w in np.array_split(np.nonzero(late)[0], 3)]
        snaps = sorted(f["snapshots"].keys(), key=lambda k: f["snapshots"][k].attrs["time"])
        toes = []
        for key in snaps[-10:]:
            s = f["snapshots"][key]
            toes.append((float(s.attrs["time"]), bore_toe(s["position"][:], s["volume"][:])[0]))
        s = f["snapshots"][snaps[-1]]
        _, d = bore_toe(s["position"][:], s["volume"][:])
        near = d[int((X_IN + L - 0.4) / 0.05):int((X_IN + L - 0.1) / 0.05)]
    ts, xs = np.array(toes).T
    speed = -np.polyfit(ts, xs, 1)[0]
    return {"fr": fr, "cell": cell, "peak": F.max() / q, "dyn": F[late].mean() / q, "spread": max(thirds) - min(thirds), "eta": near.mean() / H0,
            "speed": speed, "wall": wall, "eta_th": eta, "alpha_th": eta * eta / (2 * fr * fr), "c_th": v / (eta - 1)}


def main():
    global L
    ap = argparse.ArgumentParser()
    ap.add_argument("--fr", default="1.5,2,3,4")
    ap.add_argument("--cells", default="0.025,0.0125")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--length", type=float, default=L, help="channel length from the section to the wall (m)")
    ap.add_argument("--viscosity", type=float, default=1e-3, help="Pa s (water 1e-3; a slurry 1)")
    ap.add_argument("--volume-relaxation", type=float, default=0.0, help="the water's volume_relaxation (0: off)")
    a = ap.parse_args()
    L = a.length
    print("| Fr | h (m) | peak alpha (jet) | alpha, bore state | spread of its thirds | bore theory | error | mean depth 0.1-0.4 m from the wall / h0 | theory H/h0 | toe speed (m/s) | theory c | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for fr in (float(x) for x in a.fr.split(",")):
        for cell in (float(x) for x in a.cells.split(",")):
            r = run(fr, cell, a.threads, a.viscosity, a.volume_relaxation)
            print("| %g | %g | %.2f | %.3f | %.3f | %.3f | %+.1f %% | %.2f | %.2f | %.3f | %.3f | %.0f |" % (
                fr, cell, r["peak"], r["dyn"], r["spread"], r["alpha_th"], 100 * (r["dyn"] / r["alpha_th"] - 1), r["eta"], r["eta_th"],
                r["speed"], r["c_th"], r["wall"]), flush=True)


if __name__ == "__main__":
    main()
