#!/usr/bin/env bash
# Benchmark (not a test) of the transfer stage's wave air side (issue 20) on the glass pour at its
# own cell: simulate once, then time `fluidsound transfer` with the rigid-surface air side and
# with the wave air side ("air": "wave", both listeners), and print the fluid stage's time, the
# air solves (count, seconds per solve, memory they hold), the transfer stage's time with each
# air side and its share of the fluid stage (the goal: ≤ 100 % with the wave air side).
#   usage: tools/bench_air.sh [SCENE]   (after tools/setup.sh; default scenes/glass_pour.scene.json)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
fluidsound=$here/build/tools/fluidsound
scene=${1:-$here/scenes/glass_pour.scene.json}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The scene with the wave air side, beside the original so that its mesh paths still resolve.
wave=$(dirname "$scene")/.bench_air.$$.scene.json
trap 'rm -rf "$work" "$wave"' EXIT
/usr/bin/python3 - "$scene" "$wave" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["transfer"] = dict(scene.get("transfer", {}), model="geometric", air="wave")
json.dump(scene, open(sys.argv[2], "w"), indent=1)
PY
"$fluidsound" simulate "$wave" -o "$work" --quiet
"$fluidsound" transfer "$wave" -o "$work" --transfer geometric --quiet
cp "$work/transfer.report.json" "$work/wave.report.json"
/usr/bin/python3 - "$wave" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["transfer"]["air"] = "rigid_surface"
json.dump(scene, open(sys.argv[1], "w"), indent=1)
PY
"$fluidsound" transfer "$wave" -o "$work" --transfer geometric --quiet
/usr/bin/python3 - "$work" "$(basename "$scene")" <<'PY'
import json, sys
work, name = sys.argv[1], sys.argv[2]
sim = json.load(open(f"{work}/report.json"))
wave = json.load(open(f"{work}/wave.report.json"))
rigid = json.load(open(f"{work}/transfer.report.json"))
fluid = sim["stages"]["simulation"]["seconds"]
g = wave["results"]["geometric"]
wave_s = wave["stages"]["transfer"]["seconds"]
rigid_s = rigid["stages"]["transfer"]["seconds"]
solves = max(g["air_solves"], 1)
print(f"{'scene':24s} {'fluid_s':>8s} {'air_solves':>10s} {'s/solve':>8s} {'air_s':>7s} {'air_MB':>7s} "
      f"{'air_samples':>11s} {'rigid_s':>8s} {'wave_s':>7s} {'share':>6s}")
print(f"{name:24s} {fluid:8.2f} {g['air_solves']:10d} {g['air_seconds'] / solves:8.3f} "
      f"{g['air_seconds']:7.2f} {g['air_megabytes']:7.1f} {g['air_samples']:11d} {rigid_s:8.2f} "
      f"{wave_s:7.2f} {100 * wave_s / fluid:5.0f}%")
PY
