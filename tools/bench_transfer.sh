#!/usr/bin/env bash
# Benchmark (not a test) of the transfer stage's geometric model against the fluid stage: for each
# scene and cell size, simulate once, then time `fluidsound transfer` with each model and print
# seconds per frame, bands per reciprocal frame, water modes per frame that found them,
# factorisations, solves (Lanczos steps included), the largest frame's liquid cells and the
# geometric transfer's share of the fluid stage's time (issue 19's goal: ≤ 25 % with both
# listeners).
#   usage: tools/bench_transfer.sh [SCENE[@CELL] ...]   (after tools/setup.sh)
#   default: glass_pour and dam_break at their own cells and one finer.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
fluidsound=$here/build/tools/fluidsound
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cases=("$@")
((${#cases[@]})) || cases=(glass_pour glass_pour@0.0025 dam_break dam_break@0.00625)

printf '%-22s %7s %9s %9s %9s %7s %8s %6s %8s %8s %8s %7s\n' scene frames fluid_s image_s geom_s \
  s/frame bands/fr modes factors solves unknowns share
for c in "${cases[@]}"; do
  scene=${c%@*}
  cell=()
  [[ $c == *@* ]] && cell=(--cell "${c#*@}")
  out=$work/$scene${cell[1]:-}
  file=$here/scenes/$scene.scene.json
  "$fluidsound" simulate "$file" -o "$out" "${cell[@]}" --quiet
  "$fluidsound" transfer "$file" -o "$out" --transfer image --quiet
  cp "$out/transfer.report.json" "$out/image.report.json"
  "$fluidsound" transfer "$file" -o "$out" --transfer geometric --quiet
  /usr/bin/python3 - "$out" "$c" <<'PY'
import json, sys
out, name = sys.argv[1], sys.argv[2]
sim = json.load(open(f"{out}/report.json"))
img = json.load(open(f"{out}/image.report.json"))
geo = json.load(open(f"{out}/transfer.report.json"))
fluid = sim["stages"]["simulation"]["seconds"]
r = geo["results"]["geometric"]
frames = int(geo["results"]["frames_read"])
seconds = geo["stages"]["transfer"]["seconds"]
recip = max(r["reciprocal_frames"], 1)
modal = max(r["reciprocal_frames"] + r["adjoint_frames"] - r["mode_limited_frames"], 1)
print(f'{name:22s} {frames:7d} {fluid:9.2f} {img["stages"]["transfer"]["seconds"]:9.2f} '
      f'{seconds:9.2f} {seconds / max(frames, 1):7.3f} {r["bands"] / recip:8.1f} '
      f'{r["modes"] / modal:6.1f} {r["factorisations"]:8d} {r["solves"]:8d} '
      f'{r["max_unknowns"]:8d} {100 * seconds / fluid:6.1f}%')
PY
done
