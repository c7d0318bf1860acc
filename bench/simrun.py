"""Shared by the study scripts: write a scenario into its output folder and run `damimpact simulate` on it."""
import json
import os
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "app", "damimpact")


def simulate(scenario, out, threads=1):
    """Writes out/scenario.json, runs `damimpact simulate FILE -o out -q -t threads`; returns (process, wall seconds)."""
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "scenario.json")
    with open(path, "w") as fh:
        json.dump(scenario, fh, indent=1)
    t0 = time.time()
    r = subprocess.run([EXE, "simulate", path, "-o", out, "-q", "-t", str(threads)], capture_output=True, text=True)
    return r, time.time() - t0
