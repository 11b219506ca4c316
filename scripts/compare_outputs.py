#!/usr/bin/env python3
"""Runs the five apps of two builds on the same inputs and compares what they write.

A restructuring must not change results. This script runs pcd-to-map (with a route),
furniture-extract, plan-route, scene-sim and map-eval from OLD_BIN and from NEW_BIN on the default
cloud, the Jacobs scan (when ../shared/data or $INDOORMAP_DATA has it) and three random scenes,
then compares every file the two runs wrote:
  - JSON files after dropping what differs between any two runs (timings, the version / source
    revision, and the run's own output directory inside paths),
  - every other file byte for byte (PNG pictures are listed apart: a picture may change while the
    data does not).
Numbers in JSON are compared exactly unless --rel-tol is given.

Usage: scripts/compare_outputs.py OLD_BIN NEW_BIN [--work DIR] [--rel-tol X] [--new-params-ok]
Exit 0 when every output matches, 1 otherwise (each difference printed).
"""
import argparse
import json
import re
import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VOLATILE_KEYS = ("time", "timing", "seconds", "_ms", "version", "revision", "duration",
                 "per_second")
SPEED = re.compile(r"[0-9.]+ M points/s")


def data_dir():
    d = Path(os.environ.get("INDOORMAP_DATA", ROOT.parent / "shared" / "data"))
    return d if d.is_dir() else None


def cases():
    """(name, [(app, args)]) with {out} standing for the case's output directory."""
    office = str(ROOT / "clouds/office/cloud.pcd")
    truth = str(ROOT / "clouds/office/ground_truth.json")
    out = [("office", [
        ("pcd-to-map", [office, "-o", "{out}/map", "--start", "1,1,0", "--goal", "4,3"]),
        ("furniture-extract", [office, "-o", "{out}/objects"]),
        ("plan-route", ["--map", "{out}/map/map.yaml", "--start", "1,1,0", "--goal", "4,3,90",
                        "-o", "{out}/route"]),
        ("map-eval", ["--truth", truth, "--result", "{out}/map", "-o", "{out}/eval"]),
    ])]
    for seed in (3, 11, 22):
        scene = "{out}/scene"
        out.append((f"random{seed}", [
            ("scene-sim", ["--random", "--seed", str(seed), "-o", scene, "--3dtk"]),
            ("pcd-to-map", [scene + "/cloud.pcd", "-o", "{out}/map"]),
            ("furniture-extract", [scene + "/cloud.pcd", "-o", "{out}/objects"]),
            ("map-eval", ["--truth", scene + "/ground_truth.json", "--result", "{out}/map",
                          "-o", "{out}/eval"]),
        ]))
    d = data_dir()
    if d and (d / "jacobs-thermocolorlab").is_dir():
        jac = str(d / "jacobs-thermocolorlab")
        out.append(("jacobs", [
            ("pcd-to-map", [jac, "--scans", "0-8", "-o", "{out}/map"]),
            ("furniture-extract", [jac, "-o", "{out}/objects"]),
        ]))
    if d and (d / "room-segmentation-maps").is_dir():
        pngs = sorted((d / "room-segmentation-maps").rglob("*.png"))
        if pngs:
            out.append(("plainmap", [
                ("plan-route", ["--map", str(pngs[0]), "--resolution", "0.05", "--start", "1.575,1.925",
                                "--goal", "10,10", "-o", "{out}/route"]),
            ]))
    return out


def run_all(bin_dir, work):
    """Runs every case; returns {case/app: exit code}."""
    codes = {}
    for name, steps in cases():
        out = work / name
        out.mkdir(parents=True, exist_ok=True)
        for i, (app, args) in enumerate(steps):
            argv = [str(bin_dir / app)] + [a.replace("{out}", str(out)) for a in args]
            r = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            codes[f"{name}/{i}:{app}"] = r.returncode
            (out / f"stderr_{i}_{app}.txt").write_text(
                SPEED.sub("SPEED", r.stderr.replace(str(work), "WORK")))
    return codes


def scrub(v, work):
    if isinstance(v, dict):
        return {k: scrub(x, work) for k, x in v.items()
                if not any(s in k.lower() for s in VOLATILE_KEYS)}
    if isinstance(v, list):
        return [scrub(x, work) for x in v]
    if isinstance(v, str):
        return v.replace(str(work), "WORK")
    return v


def drop_new_parameters(a, b):
    """Removes from b's "parameters" the keys a does not have (new parameters whose defaults keep
    the old behaviour; listed, not hidden)."""
    added = []
    def walk(x, y, path):
        if isinstance(x, dict) and isinstance(y, dict):
            for k in list(y):
                if k not in x:
                    added.append(path + k)
                    del y[k]
                else:
                    walk(x[k], y[k], path + k + ".")
    if isinstance(a, dict) and isinstance(b, dict) and "parameters" in a and "parameters" in b:
        walk(a["parameters"], b["parameters"], "parameters.")
    return added


def same(a, b, rel_tol):
    if isinstance(a, float) and isinstance(b, (int, float)) or isinstance(b, float) and isinstance(a, int):
        return a == b or abs(a - b) <= rel_tol * max(abs(a), abs(b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k], rel_tol) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y, rel_tol) for x, y in zip(a, b))
    return a == b


def compare(old, new, rel_tol, new_params_ok):
    problems, pictures, added = [], [], set()
    files = sorted({p.relative_to(old) for p in old.rglob("*") if p.is_file()} |
                   {p.relative_to(new) for p in new.rglob("*") if p.is_file()})
    for rel in files:
        a, b = old / rel, new / rel
        if not a.exists() or not b.exists():
            problems.append(f"{rel}: only in {'new' if b.exists() else 'old'}")
            continue
        if rel.suffix in (".json", ".geojson"):
            try:
                ja, jb = (scrub(json.loads(p.read_text()), w) for p, w in ((a, old), (b, new)))
            except json.JSONDecodeError as e:
                problems.append(f"{rel}: not JSON ({e})")
                continue
            for k in drop_new_parameters(ja, jb) if new_params_ok else []:
                added.add(k)
            if not same(ja, jb, rel_tol):
                problems.append(f"{rel}: JSON differs")
        elif rel.name.startswith("stderr_"):
            if a.read_text() != b.read_text():
                problems.append(f"{rel}: messages differ")
        elif a.read_bytes() != b.read_bytes():
            (pictures if rel.suffix == ".png" else problems).append(f"{rel}: bytes differ")
    return files, problems, pictures, sorted(added)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old_bin", type=Path)
    ap.add_argument("new_bin", type=Path)
    ap.add_argument("--work", type=Path, default=Path("/tmp/indoormap-compare"))
    ap.add_argument("--rel-tol", type=float, default=0.0)
    ap.add_argument("--new-params-ok", action="store_true",
                    help="accept parameters that only the new build records (listed)")
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    runs = {}
    for side, b in (("old", a.old_bin), ("new", a.new_bin)):
        print(f"compare_outputs: running {b} ...", file=sys.stderr)
        runs[side] = run_all(b.resolve(), a.work / side)
    problems = [f"{k}: exit {runs['old'][k]} (old) vs {runs['new'][k]} (new)"
                for k in runs["old"] if runs["old"][k] != runs["new"][k]]
    files, diffs, pictures, added = compare(a.work / "old", a.work / "new", a.rel_tol,
                                            a.new_params_ok)
    for k in added:
        print(f"  new parameter (accepted): {k}")
    problems += diffs
    print(f"compare_outputs: {len(runs['old'])} runs, {len(files)} files compared")
    for p in pictures:
        print(f"  picture changed: {p}")
    for p in problems:
        print(f"  DIFFERENT: {p}")
    print("compare_outputs: " + ("every output matches" if not problems else
                                 f"{len(problems)} differences"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
