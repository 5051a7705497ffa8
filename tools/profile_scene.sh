#!/usr/bin/env bash
# Benchmark (not a test): simulates a scene under `perf record` and prints its seconds per frame
# and substep, the solver's stage split from report.json, the share of the profile spent in the
# thin-wall ray queries (Embree, sim/fluid/solid_mesh_rays.h, sim/fluid/thin_wall_faces.h) and the top
# functions. Issue 5 asks for this figure for the glass pour, the default scene.
#   usage: tools/profile_scene.sh [SCENE.json]     (after tools/setup.sh; needs perf: linux-perf)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scene=${1:-"$here/scenes/glass_pour.scene.json"}
command -v perf >/dev/null || { echo "profile_scene: perf not found (apt-get install linux-perf)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

perf record -q -e cpu-clock -g -o "$work/perf.data" \
  "$here/build/tools/fluidsound" simulate "$scene" -o "$work/out" --quiet 2>/dev/null
/usr/bin/python3 - "$work/out/report.json" <<'EOF'
import json, sys
report = json.load(open(sys.argv[1]))
frames = [f for f in report["results"]["frames"] if f["frame"] > 0]
seconds = sum(f["seconds"] for f in frames)
substeps = sum(f["substeps"] for f in frames)
print(f"{report['settings']['scene']}: {len(frames)} frames, {seconds / len(frames):.3f} s/frame, "
      f"{seconds / max(substeps, 1) * 1e3:.1f} ms/substep ({substeps / len(frames):.1f} substeps/frame), "
      f"{frames[-1]['particles']} particles at the end")
stages = report["stages"]
total = sum(s["seconds"] for s in stages.values())
print("stages: " + ", ".join(f"{name} {s['seconds']:.2f} s ({100 * s['seconds'] / total:.0f} %)"
                               for name, s in stages.items()))
EOF
perf report -i "$work/perf.data" --no-children --sort dso,sym --stdio -g none 2>/dev/null |
  awk '/%/ { share = $1; sub(/%/, "", share); total += share
             if ($0 ~ /libembree3|SolidMeshRays|closeFacesAcrossThinWalls|rtcIntersect/) rays += share }
       END { printf "profile share of the thin-wall ray queries (Embree + SolidMeshRays + thin-wall faces): %.1f %%\n", rays }'
echo "top functions (self time):"
perf report -i "$work/perf.data" --no-children --sort sym --stdio -g none 2>/dev/null |
  grep '%' | head -12 | cut -c1-150
