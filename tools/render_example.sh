#!/usr/bin/env bash
# Quick start 1: installs what is missing, builds, and renders the default example — water poured
# from a nozzle into a drinking glass on a table, scenes/glass_pour.scene.json — through the whole
# pipeline (simulate → transfer → synth) to out/glass_pour/glass_pour.wav, spectrogram.png and
# report.json. Any other scene renders the same way (docs/scenes.md).
#   usage: tools/render_example.sh [SCENE.json | BUBBLES.json] [OUTDIR]
# A bubble-track file (*.bubbles.json, e.g. scenes/pour.bubbles.json) is rendered by synth alone.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh" --target fluidsound
input=${1:-"$here/scenes/glass_pour.scene.json"}
name=$(basename "$input" .json)
fluidsound="$here/build/tools/fluidsound"
if [[ "$name" == *.bubbles ]]; then
  name=${name%.bubbles}
  outdir=${2:-"$here/out"}
  mkdir -p "$outdir"
  "$fluidsound" synth "$input" -o "$outdir/$name.wav" --spectrogram "$outdir/$name.png"
  echo "listen: $outdir/$name.wav   look: $outdir/$name.png   report: $outdir/$name.wav.report.json"
else
  name=${name%.scene}
  outdir=${2:-"$here/out/$name"}
  "$fluidsound" run "$input" -o "$outdir"
  echo "listen: $outdir/$name.wav   look: $outdir/spectrogram.png   report: $outdir/report.json"
fi
