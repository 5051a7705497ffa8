#!/usr/bin/env bash
# Renders every example scene at each finer cell docs/scenes.md suggests for it (every `--cell X`
# in the scene's section, "## `NAME.scene.json` …"), through the whole pipeline to its end, and
# prints one line per run: scene, cell, exit code, wall time, bubbles. Hours in all on 2 cores
# (the glass pour at 2.5 mm alone takes about 10 min): not part of the tests.
#   usage: tools/render_finer.sh [--threads N] [--out DIR] [SCENE_NAME …]
#   e.g.   tools/render_finer.sh --threads 2 glass_pour pour_tank
# With names, only those scenes, in that order (glass_pour, not scenes/glass_pour.scene.json). Uses the built
# build/tools/fluidsound; each run goes to DIR/NAME_CELL (default DIR: out/finer), its log beside.
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
fluidsound="$here/build/tools/fluidsound"
threads=2
outdir="$here/out/finer"
names=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --threads) threads=$2; shift 2 ;;
    --out) outdir=$2; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) names+=("$1"); shift ;;
  esac
done
[[ -x "$fluidsound" ]] || { echo "render_finer: $fluidsound not built (tools/setup.sh)" >&2; exit 2; }
mkdir -p "$outdir"

# "NAME CELL" for each finer cell the documentation names, in the order of docs/scenes.md.
finer_cells() {
  awk '
    /^## `[a-z_]+\.scene\.json`/ { name = $2; gsub(/`|\.scene\.json/, "", name); next }
    /^## / { name = ""; next }
    name != "" {
      line = $0
      while (match(line, /--cell [0-9.]+/)) {
        cell = substr(line, RSTART + 7, RLENGTH - 7)
        if (!seen[name " " cell]++) print name, cell
        line = substr(line, RSTART + RLENGTH)
      }
    }' "$here/docs/scenes.md"
}

# The runs to make: all, in the documentation's order, or those of the named scenes in the
# order named.
runs() {
  if [[ ${#names[@]} -eq 0 ]]; then
    finer_cells
    return
  fi
  local all n
  all=$(finer_cells)
  for n in "${names[@]}"; do awk -v n="$n" '$1 == n' <<<"$all"; done
}

printf '%-14s %-8s %-4s %-10s %s\n' scene cell exit wall bubbles
runs | while read -r name cell; do
  run="$outdir/${name}_$cell"
  start=$(date +%s.%N)
  "$fluidsound" run "$here/scenes/$name.scene.json" -o "$run" --cell "$cell" --threads "$threads" \
    --fresh >"$run.log" 2>&1
  code=$?
  wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.0f s", e - s }')
  bubbles=$(/usr/bin/python3 -c 'import json, sys
try: print(int(json.load(open(sys.argv[1]))["run"]["bubbles"]))
except Exception: print("-")' "$run/report.json")
  [[ $code -ne 0 ]] && bubbles="- ($(tail -n 1 "$run.log"))"
  printf '%-14s %-8s %-4s %-10s %s\n' "$name" "$cell" "$code" "$wall" "$bubbles"
done
