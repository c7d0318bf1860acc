#!/usr/bin/python3
"""Cell-size convergence of the tyre-buffer comparison (examples/concrete_dam_boulder_buffer.json).

Study (not a test): runs the example through the CLI at several background-grid cell sizes h
into /tmp/buffer_conv/h_<h>/{with_buffer,without_buffer} and prints Markdown tables.

    /usr/bin/python3 bench/buffer_convergence.py [--cells 0.08 0.04 0.02] [--fine auto|yes|no]
                                                 [--reuse] [--solid-check all|none|H]

Set-up: the preset scenario is copied with a low-level "grid": {"cell_size": h} beside the presets,
which re-derives the grid at that cell size (the expansion also puts the boulder 2 h in front of
the face, so its approach time and end_time change slightly with h; every time measure below is
taken relative to the impact, not to t = 0). Each scenario runs with
`damimpact simulate FILE -o /tmp/buffer_conv/h_<h> -q -t 1`, one at a time.
Default cell sizes 0.08, 0.04, 0.02 m; 0.01 m is added (--fine auto) only if the 0.02 m run took
less than 4 min per variant (run/wall_seconds).

Measured per variant (from results.h5):
  - window: the first impact, i.e. the whole history, or, if the boulder touches the upstream end
    of the grid (history/walls/upstream_end/force > 1 N), the history up to the sample before.
    With the 2 h placement the rebounding boulder can reach that slip wall before end_time, bounce
    back off it and hit the dam a second time (seen at h <= 0.04 m); a note is printed if any
    whole-run peak exceeds the first-impact peak;
  - peak base shear / moment: max over the window of |history/supports/base/reaction[:, 0]| / [:, 2];
  - peak contact force: max over the window of |history/frame/contact_force| (interval means);
  - contact impulse: the integral of history/frame/contact_force x over the window (the force is
    an interval mean, so the sum is exact), and impulse / peak force, an equivalent pulse width;
  - rebound velocity: x velocity of the boulder probe at the end of the window (used for the
    convergence), and at the last history row (as recorded; printed only);
  - impact duration: from the first time the boulder's x velocity drops below 0.98 v0 until it
    stays within 0.02 v0 of its final value (the rebound above; both crossings interpolated
    linearly in time);
  - energy balance: history/energy/balance_error at the end of the window (also as % of the
    boulder's initial kinetic energy, nominally 12.5 kJ) and its extreme there; member contact is
    internal, so its losses show there as a negative value; history/energy/dissipated (material
    damping, the buffer's) at the end of the window;
  - solid check (JSON /documents/solid_check, if present): per load case the Gauss-point peaks of
    von Mises and of the max principal stress;
  - run/wall_seconds and run/steps.
Then the ratio with/without buffer for each quantity, and the convergence between successive
resolutions: differences, observed order p = log2(|d_coarse| / |d_fine|) for each triple of
successive resolutions halving h, and the Richardson-extrapolated value q_fine + d_fine / (2^p - 1)
from the finest triple where it is monotone and contracting.

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
SCENARIO = os.path.join(ROOT, "examples", "concrete_dam_boulder_buffer.json")
TMP = "/tmp/buffer_conv"
VARIANTS = ("with_buffer", "without_buffer")
FINE_H = 0.01
SETTLED = 0.01                # last change below 1 % of the value: settled
MIN_ORDER = 0.5               # no Richardson extrapolation below this observed order
FINE_LIMIT_S = 240.0          # add FINE_H only if the 0.02 m run took less than this per variant


def hname(h):
    return "h_%g" % h


# ----------------------------------------------------------------------------------------------
# running
# ----------------------------------------------------------------------------------------------
def write_scenario(h, keep_solid_check):
    with open(SCENARIO) as f:
        d = json.load(f)
    d["grid"] = {"cell_size": h}
    if not keep_solid_check:
        d.pop("solid_check", None)
    os.makedirs(TMP, exist_ok=True)
    path = os.path.join(TMP, "scenario_%s.json" % hname(h))
    text = json.dumps(d, indent=1)
    return path, text


def run_complete(out, h):
    """True when both variants of a previous run at cell size h are complete."""
    for v in VARIANTS:
        p = os.path.join(out, v, "results.h5")
        if not os.path.exists(p):
            return False
        try:
            with h5py.File(p, "r") as f:
                if int(f.attrs.get("complete", 0)) != 1:
                    return False
                if abs(float(f["run"].attrs["cell_size"]) - h) > 1e-12:
                    return False
        except (OSError, KeyError):
            return False
    return True


def simulate(h, keep_solid_check, reuse):
    path, text = write_scenario(h, keep_solid_check)
    out = os.path.join(TMP, hname(h))
    same_file = os.path.exists(path) and open(path).read() == text
    if reuse and same_file and run_complete(out, h):
        print("h = %g m: reusing %s" % (h, out), file=sys.stderr)
        return out, None
    with open(path, "w") as f:
        f.write(text)
    cmd = [EXE, "simulate", path, "-o", out, "-q", "-t", "1"]
    print("h = %g m: %s" % (h, " ".join(cmd)), file=sys.stderr, flush=True)
    t0 = time.time()
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    dt = time.time() - t0
    if r.returncode != 0:
        sys.exit("damimpact failed (h = %g, rc %d):\n%s\n%s" % (h, r.returncode, r.stdout, r.stderr))
    print("h = %g m: done in %.1f s" % (h, dt), file=sys.stderr, flush=True)
    return out, dt


# ----------------------------------------------------------------------------------------------
# measuring
# ----------------------------------------------------------------------------------------------
def crossing(t, y, i, level):
    """Time where y crosses level between samples i-1 and i (linear interpolation)."""
    if i <= 0:
        return float(t[0])
    y0, y1 = y[i - 1], y[i]
    if y1 == y0:
        return float(t[i])
    return float(t[i - 1] + (level - y0) / (y1 - y0) * (t[i] - t[i - 1]))


def impact_duration(t, vx, v0):
    start_level = 0.98 * v0
    below = np.nonzero(vx < start_level)[0]
    if len(below) == 0:
        return float("nan"), float("nan"), float("nan")
    i0 = below[0]
    t_start = crossing(t, vx, i0, start_level)
    vf = vx[-1]
    tol = 0.02 * abs(v0)
    outside = np.nonzero(np.abs(vx - vf) > tol)[0]
    i1 = outside[-1] + 1 if len(outside) else 0     # first sample from which it stays inside
    if i1 >= len(t):
        return t_start, float("nan"), float("nan")
    # interpolate the crossing of the tolerance band edge on the side it came from
    level = vf + tol if vx[i1 - 1] > vf else vf - tol
    t_end = crossing(t, vx, i1, level)
    return t_start, t_end, t_end - t_start


def measure(path):
    m = {}
    with h5py.File(path, "r") as f:
        run = f["run"].attrs
        m["wall_s"] = float(run["wall_seconds"])
        m["steps"] = int(run["steps"])
        m["particles"] = int(run["particles"])
        m["status"] = run["status"].decode() if isinstance(run["status"], bytes) else str(run["status"])
        if "solid_check_seconds" in run:
            m["solid_check_s"] = float(run["solid_check_seconds"])
        t = f["history/time"][:]
        # The rebounding boulder may reach the upstream end of the grid (a slip wall placed a few
        # cells behind its start) before end_time, bounce back off it and hit the dam a second
        # time; the last row then is not the rebound from the dam. Everything below except the
        # whole-run peaks check is measured up to the first force on that wall (the first impact).
        n = len(t)
        m["t_wall_hit_s"] = float("nan")
        if "history/walls/upstream_end/force" in f:
            wf = np.linalg.norm(f["history/walls/upstream_end/force"][:], axis=1)
            hit = np.nonzero(wf > 1.0)[0]
            if len(hit):
                n = max(int(hit[0]) - 1, 1)
                m["t_wall_hit_s"] = float(t[hit[0]])
        reac = f["history/supports/base/reaction"][:]
        cf = f["history/frame/contact_force"][:]
        cfn = np.linalg.norm(cf, axis=1)
        m["base_shear_N"] = float(np.max(np.abs(reac[:n, 0])))
        m["base_moment_Nm"] = float(np.max(np.abs(reac[:n, 2])))
        m["contact_force_N"] = float(np.max(cfn[:n]))
        m["t_contact_peak_s"] = float(t[np.argmax(cfn[:n])])
        # contact_force is the mean over each history interval, so this sum is the impulse
        dtk = np.diff(t[:n], prepend=0.0)
        m["impulse_Ns"] = float(np.sum(cf[:n, 0] * dtk))
        m["pulse_ms"] = 1e3 * m["impulse_Ns"] / m["contact_force_N"] if m["contact_force_N"] else float("nan")
        whole = (np.max(np.abs(reac[:, 0])), np.max(np.abs(reac[:, 2])), np.max(cfn))
        m["whole_run_peaks_differ"] = bool(
            whole[0] > m["base_shear_N"] or whole[1] > m["base_moment_Nm"] or whole[2] > m["contact_force_N"])
        vel = f["history/probes/boulder/velocity"][:]
        vx = vel[:, 0]
        v0 = float(vx[0])
        m["rebound_last_mps"] = float(vx[-1])
        m["rebound_mps"] = float(vx[n - 1])
        ts, te, dur = impact_duration(t[:n], vx[:n], v0)
        m["t_impact_s"] = ts
        m["duration_ms"] = 1e3 * dur
        ke0 = float(f["history/probes/boulder/kinetic_energy"][0, 0])
        m["ke0_J"] = ke0
        be = f["history/energy/balance_error"][:n, 0]
        m["balance_end_J"] = float(be[-1])
        m["balance_max_J"] = float(be[np.argmax(np.abs(be))])
        m["balance_end_pct"] = 100.0 * be[-1] / ke0 if ke0 else float("nan")
        if "history/energy/dissipated" in f:
            m["dissipated_J"] = float(f["history/energy/dissipated"][n - 1, 0])
        if "documents/solid_check" in f:
            sc = json.loads(f["documents/solid_check"][()])
            for k, case in enumerate(sc.get("cases", [])):
                tag = "patch" if "patch" in case.get("name", "") else ("uniform" if "uniform" in case.get("name", "") else "case%d" % k)
                pk = case["peaks"]
                m["sc_%s_vm_MPa" % tag] = pk["von_mises"]["gauss"]["value_Pa"] / 1e6
                m["sc_%s_p1_MPa" % tag] = pk["max_principal"]["gauss"]["value_Pa"] / 1e6
    return m


# ----------------------------------------------------------------------------------------------
# convergence
# ----------------------------------------------------------------------------------------------
def triple(hs, qs):
    """Observed order and Richardson value of three successive resolutions (coarse -> fine)."""
    if any(not math.isfinite(q) for q in qs):
        return float("nan"), float("nan"), "-"
    d1, d2 = qs[1] - qs[0], qs[2] - qs[1]
    r = hs[1] / hs[2]
    if d1 == 0 and d2 == 0:
        return float("inf"), qs[2], "exact"
    settled = abs(d2) <= SETTLED * abs(qs[2])
    if d1 * d2 < 0:
        return float("nan"), float("nan"), "settled, |Δ| < 1 %" if settled else "oscillating"
    if abs(d2) >= abs(d1):
        return float("nan"), float("nan"), "diverging" if abs(d2) > abs(d1) else "not contracting"
    p = math.log(abs(d1) / abs(d2)) / math.log(r)
    if p < MIN_ORDER:
        return p, float("nan"), "monotone, p < %g: not extrapolated" % MIN_ORDER
    ext = qs[2] + d2 / (r ** p - 1.0)
    if ext * qs[2] < 0:
        return p, float("nan"), "monotone, extrapolation changes sign: not used"
    return p, ext, "monotone"


def convergence(hs, qs):
    """hs descending (coarse -> fine, each half of the previous), qs the values.

    Returns (diffs, orders of each successive triple, extrapolated and note of the finest one)."""
    diffs = [qs[i + 1] - qs[i] for i in range(len(qs) - 1)]
    orders, ext, note = [], float("nan"), "-"
    for i in range(len(qs) - 2):
        p, ext, note = triple(hs[i:i + 3], qs[i:i + 3])
        orders.append(p)
    return diffs, orders, ext, note


def fmt(x, q):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    if q in ("steps", "particles"):
        return "%d" % x
    a = abs(x)
    if q.endswith("_N") or q.endswith("_Nm"):
        return "%.4g k" % (x / 1e3)
    if a >= 100:
        return "%.0f" % x
    if a >= 10:
        return "%.1f" % x
    if a >= 1:
        return "%.3f" % x
    return "%.3g" % x


LABELS = [
    ("base_shear_N", "peak base shear (kN)"),
    ("base_moment_Nm", "peak base moment (kN m)"),
    ("contact_force_N", "peak contact force (kN)"),
    ("impulse_Ns", "contact impulse ∫F_x dt (N s)"),
    ("pulse_ms", "equivalent pulse width impulse / peak force (ms)"),
    ("rebound_mps", "rebound velocity v_x, before any upstream-wall hit (m/s)"),
    ("rebound_last_mps", "v_x at the last history row (m/s)"),
    ("duration_ms", "impact duration (ms)"),
    ("ke0_J", "boulder initial KE (J; 12 500 nominal)"),
    ("balance_end_J", "energy balance error, end of first impact (J)"),
    ("balance_max_J", "energy balance error, extreme (J)"),
    ("balance_end_pct", "balance error / initial KE (%)"),
    ("dissipated_J", "dissipated by material damping (J)"),
    ("sc_uniform_vm_MPa", "solid check, uniform: von Mises (MPa)"),
    ("sc_uniform_p1_MPa", "solid check, uniform: max principal (MPa)"),
    ("sc_patch_vm_MPa", "solid check, patch: von Mises (MPa)"),
    ("sc_patch_p1_MPa", "solid check, patch: max principal (MPa)"),
    ("t_impact_s", "impact start time (s)"),
    ("t_wall_hit_s", "boulder hits the upstream grid end at (s)"),
    ("wall_s", "wall time (s)"),
    ("steps", "steps"),
    ("particles", "particles"),
]
RATIO_KEYS = ["base_shear_N", "base_moment_Nm", "contact_force_N", "impulse_Ns", "duration_ms",
              "sc_uniform_vm_MPa", "sc_uniform_p1_MPa", "sc_patch_vm_MPa", "sc_patch_p1_MPa"]
CONV_SKIP = ("wall_s", "steps", "particles", "t_impact_s", "t_wall_hit_s", "rebound_last_mps")


def table(title, hs, rows, conv=True):
    """rows: list of (label, key, values per h[, reason not to extrapolate])."""
    print("\n### %s\n" % title)
    head = ["quantity"] + ["h = %g" % h for h in hs]
    if conv:
        head += ["Δ %g→%g" % (hs[i], hs[i + 1]) for i in range(len(hs) - 1)]
        head += ["p (%g-%g-%g)" % tuple(hs[i:i + 3]) for i in range(len(hs) - 2)]
        head += ["Richardson", "finest triple"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for row in rows:
        label, key, vals = row[:3]
        veto = row[3] if len(row) > 3 else None
        cells = [label] + [fmt(v, key) for v in vals]
        if conv:
            if key in CONV_SKIP or key.endswith("_s"):
                cells += [""] * (len(hs) - 1) + [""] * (len(hs) - 2) + ["", ""]
            else:
                diffs, ps, ext, note = convergence(hs, vals)
                for i, d in enumerate(diffs):
                    base = vals[i]
                    if math.isfinite(d) and base and math.isfinite(base) and abs(base) > 1e-12:
                        cells.append("%+.1f %%" % (100.0 * d / abs(base)))
                    else:
                        cells.append(fmt(d, key))
                cells += ["-" if not math.isfinite(p) else ("%.2f" % p) for p in ps]
                if veto:
                    ext, note = float("nan"), veto
                cells += [fmt(ext, key), note]
        print("| " + " | ".join(cells) + " |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cells", type=float, nargs="+", default=[0.08, 0.04, 0.02],
                    help="cell sizes, coarse to fine, each half of the previous (default 0.08 0.04 0.02)")
    ap.add_argument("--fine", choices=["auto", "yes", "no"], default="auto",
                    help="add h = 0.01 m: auto = only if the 0.02 m run took < 4 min per variant")
    ap.add_argument("--solid-check", default="all",
                    help="'all' (default, ~1 s per run), 'none', or one cell size to keep it at")
    ap.add_argument("--reuse", action="store_true",
                    help="reuse complete results of an identical scenario in /tmp/buffer_conv")
    args = ap.parse_args()

    hs = sorted(args.cells, reverse=True)

    def keep_sc(h):
        if args.solid_check == "all":
            return True
        if args.solid_check == "none":
            return False
        return abs(float(args.solid_check) - h) < 1e-12

    results = {}
    cli_seconds = {}
    for h in hs:
        out, dt = simulate(h, keep_sc(h), args.reuse)
        cli_seconds[h] = dt
        results[h] = {v: measure(os.path.join(out, v, "results.h5")) for v in VARIANTS}

    if args.fine != "no" and FINE_H not in hs:
        ref = results.get(0.02)
        per_variant = max(ref[v]["wall_s"] for v in VARIANTS) if ref else float("inf")
        if args.fine == "yes" or per_variant < FINE_LIMIT_S:
            print("adding h = %g m (0.02 m run: %.0f s per variant)" % (FINE_H, per_variant),
                  file=sys.stderr)
            out, dt = simulate(FINE_H, keep_sc(FINE_H), args.reuse)
            cli_seconds[FINE_H] = dt
            results[FINE_H] = {v: measure(os.path.join(out, v, "results.h5")) for v in VARIANTS}
            hs.append(FINE_H)
        else:
            print("not adding h = %g m: the 0.02 m run took %.0f s per variant (limit %.0f s)"
                  % (FINE_H, per_variant, FINE_LIMIT_S), file=sys.stderr)

    print("## Cell-size convergence: %s\n" % os.path.relpath(SCENARIO, ROOT))
    print("Cell sizes h (m): %s; `damimpact simulate -q -t 1`; Δ columns are relative changes to "
          "the next finer h; p = observed order of each triple of successive h; Richardson from "
          "the finest triple (only where monotone and contracting). Peaks, rebound, duration and "
          "energies are for the first impact (see the notes below the tables)." % ", ".join("%g" % h for h in hs))

    for v in VARIANTS:
        rows = []
        for key, label in LABELS:
            vals = [results[h][v].get(key, float("nan")) for h in hs]
            if all(isinstance(x, float) and not math.isfinite(x) for x in vals):
                continue
            rows.append((label, key, vals))
        table("Variant %s" % v, hs, rows)

    rows = []
    for key in RATIO_KEYS:
        label = dict(LABELS)[key]
        vals = []
        veto = []
        for v in VARIANTS:
            comp = [results[h][v].get(key, float("nan")) for h in hs]
            if len(comp) >= 3:
                note = triple(hs[-3:], comp[-3:])[2]
                if note in ("diverging", "not contracting", "oscillating") or note.startswith("monotone, p <"):
                    veto.append("%s: %s" % (v, note.split(":")[0]))
        for h in hs:
            a = results[h]["with_buffer"].get(key, float("nan"))
            b = results[h]["without_buffer"].get(key, float("nan"))
            vals.append(a / b if b else float("nan"))
        if all(not math.isfinite(x) for x in vals):
            continue
        rows.append((label.replace(" (kN)", "").replace(" (kN m)", "").replace(" (ms)", "")
                     .replace(" (MPa)", ""), "ratio", vals,
                     ("not extrapolated (%s)" % "; ".join(veto)) if veto else None))
    table("Ratio with / without buffer", hs, rows)

    for h in hs:
        for v in VARIANTS:
            m = results[h][v]
            if math.isfinite(m["t_wall_hit_s"]):
                print("\nNote: h = %g, %s: the boulder reaches the upstream end of the grid at t = %.4f s "
                      "and bounces back; first-impact window used.%s" % (
                          h, v, m["t_wall_hit_s"],
                          " A whole-run peak exceeds the first-impact peak." if m["whole_run_peaks_differ"] else
                          " Whole-run peaks equal the first-impact peaks."))
    print("\n### Cost\n")
    print("| h (m) | particles with / without | steps with / without | wall s with / without "
          "(run/wall_seconds) | CLI wall s (both variants) |")
    print("|---|---|---|---|---|")
    for h in hs:
        w, o = results[h]["with_buffer"], results[h]["without_buffer"]
        c = cli_seconds.get(h)
        print("| %g | %d / %d | %d / %d | %.1f / %.1f | %s |" % (
            h, w["particles"], o["particles"], w["steps"], o["steps"], w["wall_s"], o["wall_s"],
            "%.1f" % c if c is not None else "(reused)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
