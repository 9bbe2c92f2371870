#!/usr/bin/env python3
"""Where the scene models of the lab table miss edge length (issue 6, docs/model.md).

Renders the table views of docs/model.md (mrolr-sim --snapshot), reconstructs each
(mrolr-model scene) and compares with the truth both cameras see (mrolr-model stats --depth
--depth-right --per-feature). Prints, per view and over all views, the recovered fraction and the
MISSING length of the both-camera truth (--truth left: the left camera's) per object and per kind: line along the image rows
(within --along-deg of them), line across, conic. A truth feature belongs to the object whose
origin (truth.json T_OinL) is nearest to its middle.

Usage: scripts/scene-breakdown.py [--bin BUILD/bin] [--config config/model.ini]
       [--views table|all] [--truth both|left] [--work DIR] [--tag NAME] [--json OUT.json]
"""
import argparse
import json
import os
import subprocess
import sys

VIEWS = [  # (pose z,x,phi_deg ; head pan,tilt,vl,vr deg) as in docs/model.md
    ("0.45,0,0", "0,-20,-8,8"),
    ("0.35,0.1,5", "5,-22,-8,8"),
    ("0.5,-0.2,-10", "0,-18,-7,7"),
    ("0.4,0.05,3", "0,-20,-8,8"),
    ("0.45,-0.1,-5", "-5,-20,-8,8"),
    ("0.3,0,0", "0,-24,-8,8"),
    ("0.5,0.15,8", "3,-19,-7,7"),
    ("0.4,-0.15,-3", "-3,-21,-8,8"),
]


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("failed: " + " ".join(cmd) + "\n" + r.stderr)
    return r.stdout


def view(i, pose, head, a, root):
    d = os.path.join(a.work, "view_%d" % i)
    if not os.path.exists(os.path.join(d, "truth.json")):
        run([os.path.join(a.bin, "mrolr-sim"), "--world", "maps/lab/world.ini", "--snapshot",
             "--pose", pose, "--head", head, "--out", d])
    wf = os.path.join(d, "scene_%s.wf" % a.tag)
    run([os.path.join(a.bin, "mrolr-model"), "scene", "--left", d + "/left.png", "--right",
         d + "/right.png", "--head", head, "--config", a.config, "--out", wf])
    right = ["--depth-right", d + "/depth_right_mm.png"] if a.truth == "both" else []
    st = json.loads(run([os.path.join(a.bin, "mrolr-model"), "stats", wf, "--truth",
                         d + "/truth_left.wf", "--depth", d + "/depth_left_mm.png"] + right +
                        ["--head", head, "--config", a.config, "--per-feature", "--json"]))
    truth = json.load(open(os.path.join(d, "truth.json")))
    origins = [(o["name"], [o["T_OinL"][r][3] * 1000 for r in range(3)])
               for o in truth["objects"]]
    miss = {}
    for f in st["truth_features"]:
        m = f["mid_mm"]
        name = min(origins, key=lambda o: sum((m[k] - o[1][k]) ** 2 for k in range(3)))[0] \
            if origins else "?"
        if f["kind"] == "conic":
            kind = "conic"
        else:
            kind = "along" if f.get("image_angle_deg", 90) <= a.along_deg else "across"
        e = miss.setdefault(name, {}).setdefault(kind, [0.0, 0.0])
        e[0] += f["length_mm"]
        e[1] += f["length_mm"] - f["recovered_mm"]
    q = st["quality"]
    return {"pose": pose, "head": head, "recovered_fraction": q["recovered_fraction"],
            "visible_mm": q["true_length_mm"], "false_segments": q["false_segments"],
            "model_features": q["model_features"],
            "median_endpoint_error_mm": q["median_endpoint_error_mm"], "by_object": miss}


def table(by_object, out):
    kinds = ["along", "across", "conic"]
    out.write("%-16s" % "object" + "".join("%18s" % ("missing " + k) for k in kinds) +
              "%14s\n" % "total")
    tot = {k: [0.0, 0.0] for k in kinds}
    for name in sorted(by_object, key=lambda n: -sum(v[1] for v in by_object[n].values())):
        row = by_object[name]
        out.write("%-16s" % name)
        for k in kinds:
            v = row.get(k, [0.0, 0.0])
            tot[k][0] += v[0]
            tot[k][1] += v[1]
            out.write("%18s" % ("%.0f of %.0f" % (v[1], v[0])))
        out.write("%14.0f\n" % sum(v[1] for v in row.values()))
    out.write("%-16s" % "all" + "".join("%18s" % ("%.0f of %.0f" % (tot[k][1], tot[k][0]))
                                         for k in kinds) +
              "%14.0f\n" % sum(v[1] for v in tot.values()))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bin", default=os.path.join(root, "build", "bin"))
    p.add_argument("--config", default="config/model.ini")
    p.add_argument("--views", choices=["table", "all"], default="all")
    p.add_argument("--work", default="/tmp/mrolr_scene_breakdown")
    p.add_argument("--tag", default="run", help="name of the scene models written in --work")
    p.add_argument("--along-deg", type=float, default=20.0)
    p.add_argument("--truth", choices=["both", "left"], default="both",
                   help="truth seen by both cameras (default) or by the left one")
    p.add_argument("--json", default="")
    a = p.parse_args()
    os.chdir(root)
    views = VIEWS[:1] if a.views == "table" else VIEWS
    res = [view(i, pose, head, a, root) for i, (pose, head) in enumerate(views)]
    total = {}
    for i, r in enumerate(res):
        sys.stdout.write("view %d pose %s head %s: recovered %.1f %% of %.0f mm, false %d of %d, "
                         "median endpoint %.2f mm\n" % (i, r["pose"], r["head"],
                                                       100 * r["recovered_fraction"],
                                                       r["visible_mm"], r["false_segments"],
                                                       r["model_features"],
                                                       r["median_endpoint_error_mm"]))
        for name, kinds in r["by_object"].items():
            for k, v in kinds.items():
                e = total.setdefault(name, {}).setdefault(k, [0.0, 0.0])
                e[0] += v[0]
                e[1] += v[1]
        if i == 0:
            table(r["by_object"], sys.stdout)
    if len(res) > 1:
        sys.stdout.write("mean recovered %.1f %%, false %d of %d; missing mm over the %d views:\n" %
                         (100 * sum(r["recovered_fraction"] for r in res) / len(res),
                          sum(r["false_segments"] for r in res),
                          sum(r["model_features"] for r in res), len(res)))
        table(total, sys.stdout)
    if a.json:
        json.dump({"views": res, "missing_all_views": total}, open(a.json, "w"), indent=1)


if __name__ == "__main__":
    main()
