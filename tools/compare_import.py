#!/usr/bin/python3
"""Compares the bubble model at a cache's frame rate with the in-solver one (issue 21; docs/import.md).

For each scene: `fluidsound run SCENE -o OUT/NAME/run` (the in-solver bubble model, its frames a
cache), a cache file beside those frames naming the scene's solids, listeners, seed and its domain
as the container, then `fluidsound from-cache` of it to OUT/NAME/import. Prints per scene the
bubble counts, the slopes of the radius histograms (report.json's 10 log-spaced bins, least squares
of log10(count) on log10(radius) weighted by count), the rendered spectral centroids per listener,
and the seconds per frame of the in-solver bubble model against the import's (reading and bubble
model), with the differences the issue bounds (count 15 %, slope 0.2, centroid 10 %, speed 2x).

usage: tools/compare_import.py [--build DIR] [--out DIR] [SCENE ...]
  default scenes: scenes/glass_pour.scene.json scenes/dam_break.scene.json
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def slope(histogram):
    sx = sy = sxx = sxy = n = 0.0
    for b in histogram:
        if b["bubbles"] == 0:
            continue
        x = math.log10(math.sqrt(b["radius_from_m"] * b["radius_to_m"]))
        y, w = math.log10(b["bubbles"]), b["bubbles"]
        sx, sy, sxx, sxy, n = sx + w * x, sy + w * y, sxx + w * x * x, sxy + w * x * y, n + w
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)


def cache_for(scene_path, run_dir):
    scene = json.loads(scene_path.read_text())
    solids = scene.get("solids", [])
    for solid in solids:
        if "mesh" in solid:
            solid["mesh"] = str((scene_path.parent / solid["mesh"]).resolve())
    domain = scene["domain"]
    cache = {"format": "fluidsound.cache/1", "frames": "frames/%04d.vdb", "fps": scene["time"].get("fps", 30),
             "container": {"min": domain["min"], "max": domain["max"], "open": domain.get("open", [])},
             "seed": scene.get("seed", 0)}
    for key in ("solids", "listeners", "audio", "bubbles", "transfer"):
        if key in scene:
            cache[key] = scene[key]
    (run_dir / "cache.json").write_text(json.dumps(cache, indent=2))
    return run_dir / "cache.json"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--out", default="/tmp/fluidsound-compare-import")
    parser.add_argument("scenes", nargs="*", default=[str(ROOT / "scenes/glass_pour.scene.json"),
                                                      str(ROOT / "scenes/dam_break.scene.json")])
    args = parser.parse_args()
    exe = pathlib.Path(args.build) / "tools" / "fluidsound"
    out = pathlib.Path(args.out)
    ok = True
    for s in args.scenes:
        scene_path = pathlib.Path(s).resolve()
        name = scene_path.name.split(".")[0]
        run_dir, import_dir = out / name / "run", out / name / "import"
        subprocess.run([str(exe), "run", str(scene_path), "-o", str(run_dir), "-q", "--fresh"], check=True)
        cache = cache_for(scene_path, run_dir)
        subprocess.run([str(exe), "from-cache", str(cache), "-o", str(import_dir), "-q"], check=True)
        a = json.loads((run_dir / "report.json").read_text())
        b = json.loads((import_dir / "report.json").read_text())
        frames = len(a["results"]["frames"])
        count_a = sum(x["bubbles"] for x in a["run"]["radius_histogram"])
        count_b = sum(x["bubbles"] for x in b["run"]["radius_histogram"])
        slope_a, slope_b = slope(a["run"]["radius_histogram"]), slope(b["run"]["radius_histogram"])
        centroids = [(x["centroid_measured_hz"], y["centroid_measured_hz"])
                     for x, y in zip(a["run"]["spectrum"]["channels"], b["run"]["spectrum"]["channels"])]
        solver_bubbles = a["stages"]["bubbles"]["seconds"] / frames
        imported = (b["stages"]["read"]["seconds"] + b["stages"]["bubbles"]["seconds"]) / frames
        count_change = count_b / count_a - 1
        print(f"{name}: {frames} frames")
        print(f"  bubbles      in-solver {count_a:6.0f}   import {count_b:6.0f}   {100 * count_change:+.1f} %  (bound 15 %)")
        print(f"  slope        in-solver {slope_a:6.3f}   import {slope_b:6.3f}   {slope_b - slope_a:+.3f}  (bound 0.2)")
        for i, (x, y) in enumerate(centroids):
            print(f"  centroid {i}   in-solver {x:6.0f} Hz import {y:6.0f} Hz {100 * (y / x - 1):+.1f} %  (bound 10 %)")
        print(f"  s per frame  in-solver bubble model {1000 * solver_bubbles:.2f} ms   import (read + bubbles)"
              f" {1000 * imported:.2f} ms   x{imported / solver_bubbles:.2f}  (bound 2)"
              f"   [check pass {1000 * b['stages']['check']['seconds'] / frames:.2f} ms/frame]")
        ok &= abs(count_change) <= 0.15 and abs(slope_b - slope_a) <= 0.2 and imported <= 2 * solver_bubbles
        ok &= all(abs(y / x - 1) <= 0.10 for x, y in centroids)
    print("within the issue's bounds" if ok else "NOT within the issue's bounds")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
