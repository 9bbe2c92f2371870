#!/usr/bin/env python3
"""Runs mrolr-mission over a range of seeds and prints one line per seed and a summary.

  scripts/mission-seeds.py --seeds 1-10 [--jobs 2] [--config config/mission_sim.ini]
                           [--world W.ini] [--plan P.ini] [--set SECTION.KEY=VALUE ...]
                           [--out DIR] [--bin build/bin] [--json]

Every run gets --set mission.seed=N (the simulator's draws follow it too). The figures are the
report's: success (the robot's claim confirmed by eval), eval's true home error, the robot's own
estimate error there, where eval found the target (on the deck, in the gripper or neither), the
true grasp error, a collision, the fraction of
NIS inside its 95 % bounds, and the robot's compute. Exit 0 when every run succeeded, 3 otherwise.
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys


def seed_list(text):
    out = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            out.extend(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


def run(args, seed):
    out = os.path.join(args.out, "seed%d" % seed)
    cmd = [os.path.join(args.bin, "mrolr-mission"), "--config", args.config, "--out", out,
           "--quiet", "--json", "--set", "mission.seed=%d" % seed]
    if args.world:
        cmd += ["--world", args.world]
    if args.plan:
        cmd += ["--plan", args.plan]
    for s in args.set or []:
        cmd += ["--set", s]
    p = subprocess.run(cmd, capture_output=True, text=True)
    try:
        return seed, json.loads(p.stdout)
    except json.JSONDecodeError:
        return seed, {"error": (p.stderr or p.stdout).strip().splitlines()[-1:] or ["?"]}


def fmt(v, f="%.3f"):
    return "n/a" if v is None else f % v


def line(seed, r):
    if "error" in r:
        return "%4d  ERROR %s" % (seed, r["error"][0])
    e = r.get("eval") or {}
    col = e.get("collision")
    has = "deck" if e.get("object_on_board") else "grip" if e.get("object_held") else "no"
    grasp = (r.get("retrieval") or {}).get("grasp_error_mm")
    return "%4d  %-4s  home %6s m  estimate %6s m  has %-4s  grasp %5s mm  %-22s  NIS %5s  compute %6s s  %s" % (
        seed, "ok" if r["success"] else "FAIL", fmt(r.get("final_position_error_m")),
        fmt(r.get("final_estimate_error_m")), has, fmt(grasp, "%.1f"),
        ("hit " + col["what"]) if col else "no collision",
        fmt(r["nis"].get("fraction_inside_95"), "%.2f"), fmt(r["compute_seconds"], "%.2f"),
        r["failure"][:70])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="1-10")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--config", default="config/mission_sim.ini")
    ap.add_argument("--world")
    ap.add_argument("--plan")
    ap.add_argument("--set", action="append")
    ap.add_argument("--out", default="out/seeds")
    ap.add_argument("--bin", default="build/bin")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    seeds = seed_list(args.seeds)
    results = {}
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for seed, r in pool.map(lambda s: run(args, s), seeds):
            results[seed] = r
            if not args.json:
                print(line(seed, r), flush=True)
    ok = [s for s in seeds if results[s].get("success")]
    homes = [results[s]["final_position_error_m"] for s in seeds
             if results[s].get("final_position_error_m") is not None]
    if args.json:
        print(json.dumps({"seeds": seeds, "succeeded": ok, "runs": results}, indent=1))
    else:
        print("%d/%d succeeded; true home error %s" % (
            len(ok), len(seeds),
            "%.3f-%.3f m" % (min(homes), max(homes)) if homes else "n/a"))
    return 0 if len(ok) == len(seeds) else 3


if __name__ == "__main__":
    sys.exit(main())
