#!/usr/bin/env bash
# Quick start 1: installs what is missing, builds, and renders the default example (a pour of
# ~400 bubbles, scenes/pour.bubbles.json) to out/pour.wav, out/pour.png and out/pour.report.json.
#   usage: tools/render_example.sh [BUBBLES.json] [OUTDIR]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh"
input=${1:-"$here/scenes/pour.bubbles.json"}
outdir=${2:-"$here/out"}
mkdir -p "$outdir"
name=$(basename "$input" .json)
name=${name%.bubbles}
"$here/build/tools/fluidsound" synth "$input" -o "$outdir/$name.wav" --spectrogram "$outdir/$name.png"
echo "listen: $outdir/$name.wav   look: $outdir/$name.png   report: $outdir/$name.report.json"
