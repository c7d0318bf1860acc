#!/usr/bin/python3
"""Natural frequencies of a concrete gravity check-dam body fixed at its base, with CalculiX (ccx), as an
independent cross-check of the Euler-Bernoulli / Timoshenko beam-column models.

    /usr/bin/python3 bench/ccx_dam_modes.py --dam trial|demo [--levels 3] [--modes 10] [--element C3D20]
                                            [--threads N] [--no-2d] [--keep DIR] [--json]

Geometry: x along the flow, y up, z across the channel. Upstream face vertical at x = 0, downstream face battered:
the thickness tapers linearly from `base` at y = 0 to `crest` at y = H; prismatic across z (width W). All nodes at
y = 0 fixed in x, y, z; every other face free. Linear elastic, isotropic.

Level k (k = 0..levels-1) is a structured mesh of 4*2^k x 8*2^k x 4*2^k quadratic bricks (thickness x height x
width), so h halves per level; the observed order and Richardson value of each labelled mode come from the three
finest levels. The 2D section models (in-plane modes only) use 8-node quads on the same x-y mesh:
  CPS8, thickness W   -- ccx plane stress as ccx builds it: one C3D20 layer of thickness W, in-plane displacements
                          uniform through the layer, uz = 0 on the mid-plane only (manual, "Eight-node plane stress
                          element (CPS8 and CPS8R)"). For a thick section this is NOT textbook plane stress: the
                          layer's free uz adds transverse shear energy and lateral (Poisson) inertia.
  CPS8, thickness W/1000 -- textbook plane stress (sigma_zz = 0). In 2D both K and M scale with the thickness, so
                          the frequencies do not depend on it; only ccx's expansion layer does.
  CPE8                 -- plane strain (uz = 0 everywhere; manual, "Eight-node plane strain element").
Mode shapes come from *NODE PRINT U (one block per mode in jobname.dat). Each mode is labelled from per-level
section-mean displacements: mean ux -> in-plane bending, mean uy -> axial, mean uz -> out-of-plane bending,
rigid section rotation about y -> torsion; the number after the label is 1 + the sign changes of that profile
along the height. `ratio` is the ratio of the node-wise norms |ux| : |uy| : |uz| (max = 1).
Needs ccx on PATH (Debian/Ubuntu: apt-get install calculix-ccx). Standard library only.
"""
import argparse, json, math, os, re, shutil, subprocess, sys, tempfile, time

DAMS = {  # H, crest, base, W [m], E [Pa], nu, rho [kg/m3]
    "trial": dict(H=6.0, crest=1.5, base=3.5, W=3.0, E=25e9, nu=0.2, rho=2400.0),
    "demo": dict(H=4.0, crest=1.0, base=1.6, W=2.0, E=25e9, nu=0.2, rho=2300.0),
}
# Local (xi, eta, zeta) of the 20 nodes of C3D20/C3D20R in ccx order (manual, "Twenty-node brick element (C3D20)",
# figure 20-node brick); -1 -> grid offset 0, 0 -> 1 (mid-side), +1 -> 2.
HEX20 = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2),
         (1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
         (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]
# 8-node quad (CPS8/CPE8) in ccx order: corners counter-clockwise, then mid-sides 1-2, 2-3, 3-4, 4-1.
QUAD8 = [(0, 0), (2, 0), (2, 2), (0, 2), (1, 0), (2, 1), (1, 2), (0, 1)]


def mesh(d, nx, ny, nz):
    """Nodes on the (2nx+1) x (2ny+1) [x (2nz+1)] grid of a serendipity mesh (at most one odd index) and elements.
    The map (xi, eta, zeta) -> (xi t(y), eta H, zeta W) is bilinear in x-y, so mid-side nodes sit exactly on it."""
    two_d = nz == 0
    ids, coords, grid = {}, [], []
    for k in ([0] if two_d else range(2 * nz + 1)):
        for j in range(2 * ny + 1):
            for i in range(2 * nx + 1):
                if (i % 2) + (j % 2) + (k % 2) > 1:
                    continue
                eta = j / (2 * ny)
                y = eta * d["H"]
                t = d["base"] + (d["crest"] - d["base"]) * eta
                ids[(i, j, k)] = len(coords) + 1
                coords.append((i / (2 * nx) * t, y, 0.0 if two_d else k / (2 * nz) * d["W"]))
                grid.append((i, j, k))
    elems = []
    for ek in ([0] if two_d else range(nz)):
        for ej in range(ny):
            for ei in range(nx):
                if two_d:
                    elems.append([ids[(2 * ei + a, 2 * ej + b, 0)] for a, b in QUAD8])
                else:
                    elems.append([ids[(2 * ei + a, 2 * ej + b, 2 * ek + c)] for a, b, c in HEX20])
    return coords, grid, elems


def deck(d, coords, grid, elems, etype, thickness, nmodes):
    """Input deck; keywords as in the ccx User's Manual, section "Input deck format"."""
    out = ["*HEADING", "damimpact check-dam modes, %s" % etype, "*NODE, NSET=NALL"]  # *NODE
    out += ["%d, %.10g, %.10g, %.10g" % (n + 1, x, y, z) for n, (x, y, z) in enumerate(coords)]
    out.append("*ELEMENT, TYPE=%s, ELSET=EALL" % etype)  # *ELEMENT; at most 16 entries on a line, then continue
    for e, conn in enumerate(elems):
        vals = [str(e + 1)] + [str(n) for n in conn]
        if len(vals) > 16:  # C3D20: 21 entries -> two lines, the first ending with a comma
            out += [", ".join(vals[:16]) + ",", ", ".join(vals[16:])]
        else:
            out.append(", ".join(vals))
    base = [str(n + 1) for n, g in enumerate(grid) if g[1] == 0]
    out.append("*NSET, NSET=NBASE")  # *NSET
    out += [", ".join(base[i:i + 16]) for i in range(0, len(base), 16)]
    out += ["*BOUNDARY", "NBASE, 1, %d" % (2 if etype[:2] == "CP" else 3)]  # *BOUNDARY: dofs 1..3 fixed (2D: 1..2)
    out += ["*MATERIAL, NAME=CONC", "*ELASTIC", "%.10g, %.10g" % (d["E"], d["nu"]),  # *MATERIAL, *ELASTIC (isotropic)
            "*DENSITY", "%.10g" % d["rho"]]  # *DENSITY
    out.append("*SOLID SECTION, ELSET=EALL, MATERIAL=CONC")  # *SOLID SECTION; 2nd line = thickness of CPS/CPE
    if thickness:
        out.append("%.10g" % thickness)
    out += ["*STEP", "*FREQUENCY", "%d" % nmodes,  # *FREQUENCY: lowest N eigenpairs (ARPACK, shift-invert)
            "*NODE PRINT, NSET=NALL", "U",  # *NODE PRINT: modal displacements to jobname.dat, one block per mode
            "*END STEP"]
    return "\n".join(out) + "\n"


def run_ccx(text, workdir, job, threads):
    with open(os.path.join(workdir, job + ".inp"), "w") as f:
        f.write(text)
    # Thread counts: manual, "How to perform CalculiX calculations in parallel".
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_EQUATION_SOLVER=str(threads),
               CCX_NPROC_STIFFNESS=str(threads))
    t0 = time.time()
    r = subprocess.run(["ccx", "-i", job], cwd=workdir, env=env, capture_output=True, text=True)
    wall = time.time() - t0
    dat = os.path.join(workdir, job + ".dat")
    if r.returncode != 0 or not os.path.exists(dat) or "*ERROR" in r.stdout:
        raise SystemExit("ccx failed on %s (rc %d):\n%s" % (job, r.returncode, (r.stdout + r.stderr)[-3000:]))
    return dat, wall


def parse_dat(path, nnode):
    """Eigenvalue table ("E I G E N V A L U E   O U T P U T": mode, eigenvalue, omega, f [cycles/time], imag)
    and the *NODE PRINT blocks "displacements (vx,vy,vz) for set NALL and time ..." in mode order."""
    freqs, modes, cur, state = [], [], None, None
    num = re.compile(r"^\s*\d+(\s+[-+0-9.Ee]+){3,}\s*$")
    with open(path) as f:
        for line in f:
            if "E I G E N V A L U E   O U T P U T" in line:
                state, cur = "eig", None
            elif line.lstrip().startswith("displacements"):
                state, cur = "disp", [None] * nnode
                modes.append(cur)
            elif "P A R T I C I P A T I O N" in line or "E F F E C T I V E" in line or "T O T A L" in line:
                state = None
            elif state and num.match(line):
                v = line.split()
                if state == "eig" and len(v) == 5:
                    freqs.append(float(v[3]))
                elif state == "disp" and int(v[0]) <= nnode:
                    cur[int(v[0]) - 1] = tuple(float(x) for x in v[1:4])
    return freqs, modes


def classify(u, grid, coords, two_d):
    """Label one mode from section-mean translations and the rigid rotation about y of each height level."""
    levels = {}
    for n, g in enumerate(grid):
        levels.setdefault(g[1], []).append(n)
    prof = {"x": [], "y": [], "z": [], "t": []}
    part = {"x": 0.0, "y": 0.0, "z": 0.0, "t": 0.0}
    for j in sorted(levels):
        ns = levels[j]
        m = len(ns)
        mean = [sum(u[n][c] for n in ns) / m for c in range(3)]
        xc = sum(coords[n][0] for n in ns) / m
        zc = sum(coords[n][2] for n in ns) / m
        r2 = sum((coords[n][0] - xc) ** 2 + (coords[n][2] - zc) ** 2 for n in ns)
        th = 0.0 if two_d else sum(-(coords[n][2] - zc) * u[n][0] + (coords[n][0] - xc) * u[n][2] for n in ns) / r2
        for c, key in enumerate("xyz"):
            prof[key].append(mean[c])
            part[key] += m * mean[c] ** 2
        prof["t"].append(th)
        part["t"] += th * th * r2
    total = sum(sum(c * c for c in u[n]) for n in range(len(grid)))
    key = max(part, key=part.get)
    p = prof[key]
    big = max(abs(v) for v in p)
    signs = [v > 0 for v in p if abs(v) > 0.05 * big]
    order = 1 + sum(1 for a, b in zip(signs, signs[1:]) if a != b)
    name = {"x": "in-plane bending", "y": "axial", "z": "out-of-plane bending", "t": "torsion"}[key]
    norms = [math.sqrt(sum(u[n][c] ** 2 for n in range(len(grid)))) for c in range(3)]
    share = part[key] / total if total else 0.0
    return {"type": "%s %d" % (name, order) + ("" if share > 0.5 else " (mixed)"), "share": share,
            "ratio": [v / max(norms) for v in norms]}


def solve(d, nx, ny, nz, etype, thickness, nmodes, threads, workdir, job):
    coords, grid, elems = mesh(d, nx, ny, nz)
    dat, wall = run_ccx(deck(d, coords, grid, elems, etype, thickness, nmodes), workdir, job, threads)
    freqs, modes = parse_dat(dat, len(coords))
    if len(freqs) < nmodes or len(modes) < len(freqs):
        raise SystemExit("could not parse %d eigenpairs from %s" % (nmodes, dat))
    out = []
    for f, u in zip(freqs, modes):
        if any(v is None for v in u):
            raise SystemExit("incomplete mode shape in %s" % dat)
        out.append(dict(f_Hz=f, T_ms=1e3 / f, **classify(u, grid, coords, nz == 0)))
    return {"model": etype, "mesh": "%dx%dx%d" % (nx, ny, nz) if nz else "%dx%d" % (nx, ny), "thickness": thickness,
            "nodes": len(coords), "elements": len(elems), "dof": 3 * len(coords), "wall_s": wall, "modes": out}


def richardson(runs, label):
    """Observed order and extrapolated value from the three finest meshes (refinement ratio 2) for `label`,
    if the label names exactly one mode on each of them (Roache 1998, generalised Richardson extrapolation)."""
    fs = []
    for r in runs[-3:]:
        hit = [m["f_Hz"] for m in r["modes"] if m["type"] == label]
        if len(hit) != 1:
            return None
        fs.append(hit[0])
    if (fs[0] - fs[1]) * (fs[1] - fs[2]) <= 0:
        return {"label": label, "f_Hz": fs, "order": None, "f_extrap_Hz": None}
    p = math.log((fs[0] - fs[1]) / (fs[1] - fs[2])) / math.log(2.0)
    return {"label": label, "f_Hz": fs, "order": p, "f_extrap_Hz": fs[2] + (fs[2] - fs[1]) / (2 ** p - 1)}


def table(title, runs):
    print("\n" + title)
    for r in runs:
        print("  mesh %-9s %-6s t=%-7s nodes %6d  dof %7d  ccx %.1f s" % (r["mesh"], r["model"], r["thickness"] or "-",
                                                                       r["nodes"], r["dof"], r["wall_s"]))
        for i, m in enumerate(r["modes"]):
            print("    %2d  f %9.3f Hz  T %8.4f ms  |ux|:|uy|:|uz| = %.2f:%.2f:%.2f  %s (%.2f)" % (
                i + 1, m["f_Hz"], m["T_ms"], *m["ratio"], m["type"], m["share"]))


def report(res, element, nmodes):
    p = res["params"]
    print("dam %s: H %g m, crest %g m, base %g m, W %g m, E %g Pa, nu %g, rho %g kg/m3; %s, %d modes" % (
        res["dam"], p["H"], p["crest"], p["base"], p["W"], p["E"], p["nu"], p["rho"], element, nmodes))
    table("3D solid (%s), base fixed" % element, res["solid"])
    names = {"psW": "CPS8 thickness W (ccx expansion layer)", "ps": "CPS8 thickness W/1000 (plane stress)",
             "pe": "CPE8 (plane strain)"}
    for tag in ("psW", "ps", "pe"):
        runs = [r for r in res["plane"] if r["variant"] == tag]
        if runs:
            table("2D section, " + names[tag], runs)
    for key, rows in res["richardson"].items():
        print("\nRichardson (three finest, ratio 2), %s:" % key)
        for x in rows:
            if x and x["order"] is not None:
                fs = ", ".join("%.4f" % v for v in x["f_Hz"])
                print("  %-28s f = %s  p = %.2f  f_ext = %.4f Hz" % (x["label"], fs, x["order"], x["f_extrap_Hz"]))
            elif x:
                print("  %-28s f = %s  (not monotone)" % (x["label"], ", ".join("%.4f" % v for v in x["f_Hz"])))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dam", choices=sorted(DAMS), required=True)
    ap.add_argument("--levels", type=int, default=3, help="mesh levels 4x8x4 * 2^k, k < N (default 3)")
    ap.add_argument("--modes", type=int, default=10)
    ap.add_argument("--element", default="C3D20", choices=["C3D20", "C3D20R"])
    ap.add_argument("--threads", type=int, default=1,
                    help="ccx threads (default 1: multi-threaded SPOOLES ran 3-4x slower on the test machine)")
    ap.add_argument("--no-2d", action="store_true", help="skip the CPS8/CPE8 section models")
    ap.add_argument("--keep", help="write the decks and ccx output here instead of a temp dir")
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    if shutil.which("ccx") is None:
        sys.exit("ccx (CalculiX CrunchiX) not found on PATH; install it, e.g. `apt-get install calculix-ccx`")
    d = DAMS[a.dam]
    work = a.keep or tempfile.mkdtemp(prefix="ccx_dam_")
    os.makedirs(work, exist_ok=True)
    res = {"dam": a.dam, "params": d, "solid": [], "plane": [], "richardson": {}}
    try:
        for k in range(a.levels):
            nx, ny, nz = 4 * 2 ** k, 8 * 2 ** k, 4 * 2 ** k
            res["solid"].append(solve(d, nx, ny, nz, a.element, None, a.modes, a.threads, work, "solid%d" % k))
            if not a.no_2d:
                for et, th, tag in (("CPS8", d["W"], "psW"), ("CPS8", d["W"] / 1000, "ps"), ("CPE8", d["W"], "pe")):
                    res["plane"].append(dict(solve(d, nx, ny, 0, et, th, a.modes, a.threads, work, "%s%d" % (tag, k)),
                                             variant=tag, level=k))
    finally:
        if not a.keep:
            shutil.rmtree(work, ignore_errors=True)
    if a.levels >= 3:
        labels = [m["type"] for m in res["solid"][-1]["modes"]]  # in frequency order
        res["richardson"]["solid"] = [x for x in (richardson(res["solid"], l) for l in dict.fromkeys(labels)) if x]
        for tag in ("psW", "ps", "pe"):
            runs = [r for r in res["plane"] if r["variant"] == tag]
            if runs:
                labels = [m["type"] for m in runs[-1]["modes"]]
                res["richardson"][tag] = [x for x in (richardson(runs, l) for l in dict.fromkeys(labels)) if x]
    if a.json:
        json.dump(res, sys.stdout, indent=1)
        print()
        return
    report(res, a.element, a.modes)


if __name__ == "__main__":
    main()
