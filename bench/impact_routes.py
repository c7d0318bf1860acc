#!/usr/bin/python3
"""Hard elastic impact by independent routes (docs/verification.md, "Hard impact", "Body-body contact as a wall",
"Hertz sphere"). Study, not a test: the gated subsets are `damimpact validate impact_contact hertz_sphere`.

    /usr/bin/python3 bench/impact_routes.py [--cells 0.04 0.02 0.01 0.005] [--hertz 0.02 0.01 0.005] [--out DIR]

2D: examples/cylinder_on_wall.json and cylinder_on_member.json (rock cylinder R 0.4 m, 5 m/s) with the face on the
grid line y = 0 ("on") and 0.007 m below it ("off"); targets: rigid wall, member with E 3e13 Pa (effectively rigid),
concrete member, concrete member with the paper's decay layer (linear, node distance), and two identical cylinders
meeting head-on through multi-field contact (by symmetry one cylinder on a slip wall; face on the grid line). 3D:
examples/hertz_sphere_on_wall.json at the given cells. Each run: `damimpact simulate FILE -o DIR -q -t 1`.
Prints peak force (per metre in 2D), contact time (force above 1e-3 of its peak; 1 % in 3D), restitution and the
kinetic energy lost.
"""
import argparse, json, os, subprocess
import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "damimpact")


def load(name):
    with open(os.path.join(ROOT, "examples", name)) as f:
        return json.load(f)


def run(s, out):
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "scenario.json")
    with open(path, "w") as f:
        json.dump(s, f)
    subprocess.run([EXE, "simulate", path, "-o", out, "-q", "-t", "1"], check=True)
    return h5py.File(os.path.join(out, "results.h5"), "r")


def cylinder(target, h, off, E=None, decay=None, gap=0.017, end=None):
    s = load("cylinder_on_wall.json" if target in ("wall", "mirror", "block") else "cylinder_on_member.json")
    s["grid"]["cell_size"] = h
    s["bodies"][0]["shape"]["center"] = [0.55, 0.4 + gap - off]
    if end:
        s["analysis"]["end_time"] = end
    if target == "wall":
        s["walls"][0]["point"] = [0.0, -off]
    elif target == "block":  # a resolved concrete block (E of the member's concrete unless E given), base held
        block_E = E or 3e10
        s["materials"].append({"name": "concrete", "model": "linear_elastic", "density": 2400, "youngs_modulus": block_E,
                               "poisson_ratio": 0.2})
        s["bodies"].append({"name": "block", "material": "concrete", "particles_per_cell": 2,
                            "shape": {"type": "box", "min": [0.0, -1.0 - off], "max": [1.1, -off]}, "velocity": [0, 0]})
        s["walls"] = [{"name": "base", "type": "plane", "point": [0, -1.0 - off], "normal": [0, 1], "condition": "stick"}]
        s["contact"] = {"method": "multi_field", "friction": 0.0}
    elif target == "mirror":  # the image cylinder below the plane y = 0, moving up
        del s["walls"]
        image = json.loads(json.dumps(s["bodies"][0]))
        image.update({"name": "image", "velocity": [0, 5.0]})
        image["shape"]["center"] = [0.55, -0.4 - gap]
        s["bodies"].append(image)
        s["contact"] = {"method": "multi_field", "friction": 0.0}
    else:
        s["structure"]["nodes"][0]["position"] = [0.0, -0.5 - off]
        s["structure"]["nodes"][1]["position"] = [1.1, -0.5 - off]
        if E:
            s["materials"][1]["youngs_modulus"] = E
        if decay:
            s["member_contact"].update(decay)
    return s


def impact_2d(f, target, m, v0=5.0):
    H = f["history"]
    t = H["time"][:]
    vy = H["probes/rock/velocity"][:, 1]
    ke = H["probes/rock/kinetic_energy"][:, 0]
    if target in ("mirror", "block"):  # force from the momentum change over 0.02 ms windows
        tg = np.arange(0, t[-1], 2e-5)
        F = m * np.diff(np.interp(tg, t, vy)) / 2e-5
        tF = tg[1:]
    else:
        F = -(H["walls/wall/force"] if target == "wall" else H["frame/contact_force"])[:, 1]
        tF = t
    on = np.where(F > 1e-3 * F.max())[0]
    return F.max(), tF[on[-1]] - tF[max(on[0] - 1, 0)], vy[-1] / v0, 1 - ke[-1] / ke[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", type=float, nargs="*", default=[0.04, 0.02, 0.01, 0.005])
    ap.add_argument("--hertz", type=float, nargs="*", default=[0.02, 0.01, 0.005])
    ap.add_argument("--hertz-mirror", type=float, nargs="*", default=[],
                    help="cells of the 3D sphere meeting its mirror image head-on through multi-field contact")
    ap.add_argument("--out", default="/tmp/impact_routes")
    ap.add_argument("--gap", type=float, default=0.017, help="initial gap of the 2D cylinder (m)")
    ap.add_argument("--end", type=float, default=None, help="end time of the 2D runs (s); default the example's")
    ap.add_argument("--only", nargs="*", default=None, help="run the 2D routes whose label contains one of these")
    a = ap.parse_args()
    m = 2650 * np.pi * 0.4 ** 2
    routes = [("rigid wall, on", "wall", 0.0, {}), ("member E 3e13, on", "member", 0.0, {"E": 3e13}),
              ("concrete member, on", "member", 0.0, {}), ("rigid wall, off", "wall", 0.007, {}),
              ("member E 3e13, off", "member", 0.007, {"E": 3e13}), ("concrete member, off", "member", 0.007, {}),
              ("concrete member, paper decay layer, off", "member", 0.007, {"decay": {"decay": "linear", "distance": "node"}}),
              ("two cylinders (multi-field), on", "mirror", 0.0, {}),
              ("concrete block (continuum, E 30 GPa), on", "block", 0.0, {}),
              ("rigid block (continuum, E 3e13), on", "block", 0.0, {"E": 3e13})]
    print("| target | h (m) | peak (MN/m) | contact time (ms) | restitution | kinetic energy lost |")
    print("|---|---|---|---|---|---|")
    for label, target, off, kw in routes:
        if a.only is not None and not any(o in label for o in a.only):
            continue
        for h in a.cells:
            f = run(cylinder(target, h, off, gap=a.gap, end=a.end, **kw), os.path.join(a.out, "%s_%s_%g" % (target, off, h) + "_".join(kw)))
            peak, tc, e, loss = impact_2d(f, target, m)
            print("| %s | %g | %.1f | %.2f | %.3f | %.1f %% |" % (label, h, peak / 1e6, tc * 1e3, e, 100 * loss), flush=True)
    # 3D Hertz sphere: reference 7.20 kN, 4.25 ms (sdof::hertz_sphere_impact)
    print("\n| target | h (m) | peak (kN) | vs Hertz | vs finite sphere | contact time (ms) | vs Hertz | vs finite sphere "
          "| restitution | wall impulse / m v0 (1 + e) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    R, v0, ms = 0.1, 2.0, 1000 * 4 / 3 * np.pi * 0.1 ** 3
    Es = 1e8 / (1 - 0.09)
    dmax = (15 * ms * v0 ** 2 / (16 * Es * np.sqrt(R))) ** 0.4
    Fh = 4 / 3 * Es * np.sqrt(R) * dmax ** 1.5
    th = 2.94 * dmax / v0 - 2 * 0.01 ** (2 / 3) * dmax / v0  # Hertz's time with the force above 1 % of its peak
    Ffs, tfs = 7871.0, 3.866e-3  # the finite sphere's quasi-static impact: build/bench/hertz_axisym
    for h, mirror in [(h, False) for h in a.hertz] + [(h, True) for h in a.hertz_mirror]:
        s = load("hertz_sphere_on_wall.json")
        s["grid"]["cell_size"] = h
        if mirror:  # by symmetry the plane z = 0 is a frictionless rigid wall
            del s["walls"]
            image = json.loads(json.dumps(s["bodies"][0]))
            image.update({"name": "image", "velocity": [0, 0, 2.0]})
            image["shape"]["center"] = [0, 0, -0.105]
            s["bodies"].append(image)
            s["contact"] = {"method": "multi_field", "friction": 0.0}
            s["grid"]["origin"][2] = -0.29
            s["grid"]["size"][2] = 0.58
        f = run(s, os.path.join(a.out, "hertz_%s%g" % ("mirror_" if mirror else "", h)))
        H = f["history"]
        t = H["time"][:]
        vz = H["probes/ball/velocity"][:, 2]
        if mirror:  # force from the momentum change over 0.02 ms windows
            tg = np.arange(0, t[-1], 2e-5)
            F = ms * np.diff(np.interp(tg, t, vz)) / 2e-5
            t = tg[1:]
            vz = np.interp(t, H["time"][:], vz)
        else:
            F = -H["walls/wall/force"][:, 2]
        on = np.where(F > 0.01 * F.max())[0]
        tc = t[on[-1]] - t[on[0] - 1]
        e = vz[-1] / v0
        imp = (F * np.diff(t, prepend=0)).sum()
        print("| %s | %g | %.2f | %+.1f %% | %+.1f %% | %.2f | %+.1f %% | %+.1f %% | %.3f | %.4f |"
              % ("mirror sphere (multi-field)" if mirror else "rigid wall", h, F.max() / 1e3, 100 * (F.max() / Fh - 1),
                 100 * (F.max() / Ffs - 1), tc * 1e3, 100 * (tc / th - 1), 100 * (tc / tfs - 1), e, imp / (ms * v0 * (1 + e))),
              flush=True)


if __name__ == "__main__":
    main()
