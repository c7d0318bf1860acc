#!/usr/bin/python3
"""Lin & Yang (2024), verification 1, under joint refinement of grid, particles and elements.

    /usr/bin/python3 bench/a5_refinement.py [--levels 4] [--out DIR]

Study, not a test. Level k: cell 0.25 / 2^k m, 4x4 particles per cell, 8 * 2^k elements, the example's time step
(1e-4 s) and shape functions. Mid-span deflection u(t) over t0 = sqrt(2 d / g) (the end of the 0.75 m free fall) to
5 s, sampled every 1 ms. Each level against the finest (NRMS = RMS(u - u_ref) / max|u_ref|, peak error), the observed
order of the NRMS of successive differences, and each level against the pointwise Richardson value of the three
finest (Roache 1994). Each run: `damimpact simulate FILE -o DIR -q -t 1`.
"""
import argparse, json, os, subprocess
import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "damimpact")


def run(level, out):
    with open(os.path.join(ROOT, "examples", "paper_a5_block_on_beam.json")) as f:
        s = json.load(f)
    s["grid"]["cell_size"] = 0.25 / 2 ** level
    s["structure"]["members"][0]["elements"] = 8 * 2 ** level
    s["output"]["snapshot_interval"] = 5.0
    s["output"]["vtk"] = False
    d = os.path.join(out, "level_%d" % level)
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, "scenario.json")
    with open(path, "w") as f:
        json.dump(s, f)
    subprocess.run([EXE, "simulate", path, "-o", d, "-q", "-t", "1"], check=True)
    f = h5py.File(os.path.join(d, "results.h5"), "r")
    t = f["history/time"][:]
    u = f["history/probes/midspan/displacement"][:, 1]
    return t, u, float(f["run"].attrs["wall_seconds"])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--levels", type=int, default=4)
    ap.add_argument("--out", default="/tmp/a5_refinement")
    a = ap.parse_args()
    t0 = np.sqrt(2 * 0.75 / 10.0)
    tg = np.arange(t0, 5.0, 1e-3)
    U, W = [], []
    for k in range(a.levels):
        t, u, w = run(k, a.out)
        U.append(np.interp(tg, t, u))
        W.append(w)
        print("level %d done (%.1f s)" % (k, w), flush=True)
    ref = U[-1]
    scale = np.abs(ref).max()
    nrms = lambda x, y: np.sqrt(np.mean((x - y) ** 2)) / scale
    print("\n| cell (m) | elements | NRMS vs finest | peak vs finest | NRMS vs Richardson | peak vs Richardson | wall s |")
    print("|---|---|---|---|---|---|---|")
    # Pointwise Richardson value from the three finest (ratio 2), order from the NRMS of successive differences.
    d1, d2 = nrms(U[-2], U[-3]), nrms(U[-1], U[-2])
    p = np.log2(d1 / d2) if d2 > 0 else float("nan")
    rich = U[-1] + (U[-1] - U[-2]) / (2 ** p - 1) if np.isfinite(p) and p > 0 else None
    for k in range(a.levels):
        pk = np.abs(U[k]).max() / scale - 1
        nr = nrms(U[k], rich) if rich is not None else float("nan")
        pr = np.abs(U[k]).max() / np.abs(rich).max() - 1 if rich is not None else float("nan")
        print("| %g | %d | %.4f | %+.4f | %.4f | %+.4f | %.1f |" % (0.25 / 2 ** k, 8 * 2 ** k, nrms(U[k], ref), pk, nr, pr, W[k]))
    print("\nNRMS of successive differences:", ", ".join("%.4f" % nrms(U[k + 1], U[k]) for k in range(a.levels - 1)))
    print("observed order (three finest): %.2f" % p)


if __name__ == "__main__":
    main()
