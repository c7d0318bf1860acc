#!/usr/bin/python3
"""Planar granular column collapse: Drucker-Prager MPM run-out vs Lube et al. (2005).

Study (not a test): runs the variants through the CLI into /tmp and prints a Markdown table.

    /usr/bin/python3 bench/granular_collapse.py [--quick] [--only a=1] [--keep]

Set-up (2D plane strain): a column L0 wide and H0 = a L0 high rests against a frictionless
symmetry wall at x = 0 (roller, on a grid line) on a horizontal base at y = 0 (a wall on a grid
line: Coulomb friction mu = tan(phi), stick or slip). Gravity releases it at t = 0 (no gate, no
initial K0 stress state). It runs until the kinetic energy is gone, then the run-out
L_inf and final height H_inf are taken from the last snapshot:

  - front: the farthest particle still connected to the pile (walking along x, a gap larger than
    one cell ends the pile), plus half a particle spacing (particles are sub-cell centres);
    the 99.5th percentile of x is printed as a cross-check;
  - the same front where the deposit is still 5 % and 10 % of L0 thick (bins 0.05 L0 wide,
    contiguous from the wall): the bulk of the deposit, without the thin distal sheet, whose
    length grows with resolution (see the report in the study's output);
  - H_inf: the highest particle plus half a particle spacing.

Reference (Lube, Huppert, Sparks & Freundt 2005, Phys. Rev. E 72, 041301, 2D channel, 1-2 %
scatter across materials):  (L_inf - L0)/L0 = 1.2 a for a < 1.8 and 1.9 a^(2/3) for a > 2.8;
between 1.8 and 2.8 (the transition) the two are interpolated linearly here (marked '~').
Final height H_inf/L0 = a for a < 1.15 and about a^(2/5) above (Lube 2005) - printed only.

Requires /usr/bin/python3 with h5py and numpy, and build/app/damimpact.
"""
import argparse
import math
import os

import h5py
import numpy as np

from simrun import simulate

TMP = "/tmp/granular_collapse"

# Sand defaults (the recommended set-up, examples/granular_collapse.json)
L0 = 0.5          # column width (m)
RHO = 2000.0      # kg/m3
E = 5e6           # Pa: rho g H0 / E ~ 2e-3 for a = 1
NU = 0.3
G = 9.81


def lube(a):
    """Normalised run-out of Lube et al. (2005), planar; linear blend across 1.8 < a < 2.8."""
    lo, hi = 1.2 * a, 1.9 * a ** (2.0 / 3.0)
    if a <= 1.8:
        return lo, ""
    if a >= 2.8:
        return hi, ""
    w = (a - 1.8) / 1.0
    return (1 - w) * 1.2 * a + w * hi, "~"


def scenario(a, n, base, phi, ppc=2, shape="bspline2", end_time=None, transfer="apic",
             flip_blend=1.0, stress_update=None, mu=None, psi=0.0, left="roller", xfac=1.6):
    """Scenario dict for one variant. n = cells across L0."""
    h = L0 / n
    H0 = a * L0
    runout = lube(a)[0]
    xmax = L0 * (1 + xfac * runout) + 0.2 * L0
    ymax = H0 + 2 * h if base != "stick" else 3 * H0
    if end_time is None:
        # Lube: the front stops at about 3 (H0/g)^0.5; leave ample time for the pile to settle
        end_time = round(max(0.8, 6.0 * math.sqrt(H0 / G)), 2)
    walls = [{"name": "symmetry", "type": "plane", "point": [0, 0], "normal": [1, 0], "condition": left}]
    basewall = {"name": "base", "type": "plane", "point": [0, 0], "normal": [0, 1]}
    if base == "friction":
        basewall.update(condition="friction", friction=round(math.tan(math.radians(phi)) if mu is None else mu, 4))
    else:
        basewall["condition"] = base
    walls.append(basewall)
    mpm = {"shape_function": shape, "transfer": transfer}
    if transfer == "flip":
        mpm["flip_blend"] = flip_blend
    if stress_update:
        mpm["stress_update"] = stress_update
    return {
        "schema_version": 1,
        "name": f"Granular column collapse a={a} n={n} base={base} phi={phi}",
        "analysis": {"dimension": 2, "plane": "strain", "end_time": end_time, "cfl": 0.5, "gravity": [0, -G]},
        "mpm": mpm,
        "grid": {"origin": [-2 * h, -2 * h], "size": [xmax + 2 * h, ymax + 2 * h], "cell_size": h},
        "materials": [{"name": "sand", "model": "drucker_prager", "density": RHO, "youngs_modulus": E,
                       "poisson_ratio": NU, "cohesion": 0.0, "friction_angle": phi, "dilation_angle": psi}],
        "bodies": [{"name": "column", "material": "sand", "particles_per_cell": ppc,
                    "shape": {"type": "box", "min": [0, 0], "max": [L0, H0]}}],
        "walls": walls,
        "output": {"vtk": False, "snapshot_interval": round(end_time / 20, 4), "history_interval": 0.01,
                   "probes": [{"name": "column", "type": "body", "body": "column", "quantities": ["kinetic_energy"]}]},
    }


def thickness_front(x, dx, thr, bin_width):
    """Right edge of the last bin, contiguous from the wall, whose deposit top is >= thr."""
    nb = int(np.ceil(x[:, 0].max() / bin_width)) + 1
    idx = np.clip((x[:, 0] / bin_width).astype(int), 0, nb - 1)
    top = np.full(nb, -1.0)
    np.maximum.at(top, idx, x[:, 1] + dx / 2)
    bad = np.nonzero(top < thr)[0]
    return (bad[0] if len(bad) else nb) * bin_width


def measure(h5path, h, dx):
    """Run-out, final height and diagnostics from results.h5."""
    with h5py.File(h5path, "r") as f:
        snaps = sorted(f["snapshots"].keys())

        def front(key):
            x = f["snapshots"][key]["position"][:]
            xs = np.sort(x[:, 0])
            gaps = np.nonzero(np.diff(xs) > h)[0]
            return (xs[gaps[0]] if len(gaps) else xs[-1]), x

        xc, x = front(snaps[-1])
        xprev, _ = front(snaps[-2])
        tstop = None  # front arrest: first snapshot whose connected front is within one spacing of the final one
        for key in snaps:
            if abs(front(key)[0] - xc) < dx:
                tstop = float(f["snapshots"][key].attrs["time"])
                break
        t_end = float(f["snapshots"][snaps[-1]].attrs["time"])
    return {"front": xc + dx / 2, "front5": thickness_front(x, dx, 0.05 * L0, max(dx, 0.05 * L0)),
            "front10": thickness_front(x, dx, 0.10 * L0, max(dx, 0.05 * L0)),
            "p995": np.percentile(x[:, 0], 99.5) + dx / 2, "hmax": x[:, 1].max() + dx / 2,
            "moving": abs(xc - xprev) > 0.01 * L0, "detached": int(np.sum(x[:, 0] > xc)), "tstop": tstop,
            "t_end": t_end}


def run(a, n, base, phi, tag="", **kw):
    kw.setdefault("transfer", "apic")
    sc = scenario(a, n, base, phi, **kw)
    tr = sc["mpm"]["transfer"] + (f" {sc['mpm']['flip_blend']:g}" if sc["mpm"]["transfer"] == "flip" else "")
    name = f"a{a}_n{n}_{base}_phi{phi}_{tr.replace(' ', '')}{tag}"
    out = os.path.join(TMP, name)
    r, wall = simulate(sc, out, 1)
    m = dict(a=a, n=n, base=base, phi=phi, tag=tag, transfer=tr, wall=wall, failed=None)
    if r.returncode != 0:
        msg = r.stderr.strip()
        i = msg.find("run stopped at")
        m["failed"] = msg[i:i + 60].split(":")[0] if i >= 0 else msg[-120:]
        return m
    h = sc["grid"]["cell_size"]
    m.update(measure(os.path.join(out, "results.h5"), h, h / sc["bodies"][0]["particles_per_cell"]))
    return m


def row(m):
    a = m["a"]
    ref, mark = lube(a)
    lead = f"| {a:g} | {m['n']} | {m['base']}{m['tag'] and ' ' + m['tag']} | {m['phi']:g} | {m['transfer']} |"
    if m["failed"]:
        return lead + f" did not stop: particles left the grid ({m['failed']}) | | | {mark}{ref:.2f} | | | | | {m['wall']:.0f} |"
    r = (m["front"] - L0) / L0
    r5 = (m["front5"] - L0) / L0
    r10 = (m["front10"] - L0) / L0
    mv = " (moving)" if m["moving"] else ""
    ts = f"{m['tstop']:.2f}" if m["tstop"] is not None else "-"
    return (lead + f" {r:.2f}{mv} | {r5:.2f} | {r10:.2f} | {mark}{ref:.2f} | {100 * (r - ref) / ref:+.0f} % | {100 * (r5 - ref) / ref:+.0f} % | "
            f"{m['hmax'] / L0:.2f} | {ts} | {m['wall']:.0f} |")


HEADER = ("| a | cells across L0 | base | phi (deg) | transfer | (L_inf-L0)/L0 tip | 5 % L0 thick | 10 % L0 thick | Lube | error tip | error 5 % | "
          "H_inf/L0 | t_stop (s) | wall (s) |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")


def variants(quick):
    v = []
    # (1) resolution, a = 1, Coulomb base mu = tan(phi), phi = 30, APIC
    for n in ([10, 20] if quick else [10, 20, 40]):
        v.append(dict(a=1, n=n, base="friction", phi=30))
    for n in ([] if quick else [10, 20, 40]):
        v.append(dict(a=1, n=n, base="friction", phi=35))
    # (2) base condition
    v.append(dict(a=1, n=20, base="stick", phi=30, xfac=3))
    v.append(dict(a=1, n=20, base="slip", phi=30, xfac=3))
    # (3) friction angle
    for phi in [25]:
        v.append(dict(a=1, n=20, base="friction", phi=phi))
    # (4) aspect ratio
    for a in ([0.5, 2] if quick else [0.5, 2, 3]):
        v.append(dict(a=a, n=20, base="friction", phi=30))
    for a in ([] if quick else [0.5, 2, 3]):
        v.append(dict(a=a, n=20, base="friction", phi=35))
    # (5) particle-grid transfer: FLIP without / with a PIC fraction (numerical dissipation per step)
    for fb, n in ([(1.0, 20), (0.95, 20)] if quick else [(1.0, 20), (1.0, 40), (0.99, 20), (0.95, 10), (0.95, 20), (0.95, 40)]):
        v.append(dict(a=1, n=n, base="friction", phi=30, transfer="flip", flip_blend=fb))
    return v


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="skip the 40-cell and a = 3 runs")
    args = ap.parse_args()
    print(HEADER)
    for v in variants(args.quick):
        m = run(**v)
        if m:
            print(row(m), flush=True)


if __name__ == "__main__":
    main()
