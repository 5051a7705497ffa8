#!/usr/bin/env bash
# Benchmarks (not tests): synthesis throughput in oscillator-samples/s for 1 k, 10 k and 100 k
# moving bubbles with the two baselines and their ratios, then the peak memory and time of a
# 60-second render of ~120 000 bubbles through `fluidsound synth`.
#   usage: tools/bench.sh            (after tools/setup.sh)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$here/build
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Only the synthesis benchmarks: the others (fluid, bubble model, Martin & Moyce) simulate whole
# scenes and report in their own units; run them by name (build/tests/fluidsound_bench --help).
"$build/tests/fluidsound_bench" --benchmark_filter='BM_Synthesize|BM_Baseline' --benchmark_min_time=1 \
  --benchmark_repetitions=3 --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null |
  grep '_median' | tee "$work/bench.csv" |
  awk -F, '{gsub(/"/, "", $1); printf "%-40s %10.2f %s  %8.3g oscillator-samples/s\n", $1, $3, $5, $7}'
awk -F, '
  /BM_Synthesize\/100000/ { s = $7 }
  /BM_BaselineComplexRotation/ { r = $7 }
  /BM_BaselineSinExp/ { e = $7 }
  END { printf "100 k bubbles on all cores vs one-core complex rotation: %.2fx; vs one-core sin/exp: %.1fx\n", s / r, s / e }' \
  "$work/bench.csv"

/usr/bin/python3 "$here/tools/make_example_bubbles.py" --pour-file "$work/long.bubbles.json" \
  --pour-end 60 --peak-rate 2000 >/dev/null
/usr/bin/time -f "60 s render: %e s wall, peak resident memory %M KiB" \
  "$build/tools/fluidsound" synth "$work/long.bubbles.json" -o "$work/long.wav" --quiet
grep -E '"(read|synthesis|write)"' -A1 "$work/long.wav.report.json" | tr -d '\n{} ' | sed 's/--/ /g; s/$/\n/'
