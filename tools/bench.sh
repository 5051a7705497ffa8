#!/usr/bin/env bash
# Benchmarks (not tests): synthesis throughput in oscillator-samples/s for 1 k, 10 k and 100 k
# moving bubbles, through the kernel this CPU gets and through each kernel it can run, with the
# two baselines and their ratios, then the peak memory and time of a 60-second render of
# ~120 000 bubbles through `fluidsound synth`.
#   usage: tools/bench.sh            (after tools/setup.sh)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$here/build
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Only the synthesis benchmarks: the others (fluid, bubble model, Martin & Moyce) simulate whole
# scenes and report in their own units; run them by name (build/tests/fluidsound_bench --help).
# Each synthesis row names the oscillator kernel that ran: BM_Synthesize the one this CPU gets,
# BM_SynthesizeWithKernel/…/kernel:0|1|2 the baseline, AVX2 and AVX-512 kernels (a kernel this
# CPU cannot run is reported as skipped). "per core" is items over the CPU time of all threads,
# which a shared machine depresses far less than the real-time figure.
"$build/tests/fluidsound_bench" --benchmark_filter='BM_Synthesize|BM_Baseline' --benchmark_min_time=1 \
  --benchmark_repetitions=3 --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null |
  tee "$work/all.csv" | grep '_median' > "$work/bench.csv" || true
awk -F, '$9 == "true" { gsub(/"/, "", $1); gsub(/"/, "", $10); printf "%-56s skipped: %s\n", $1, $10 }' "$work/all.csv" |
  sort -u
# (The baselines run on one thread and count per CPU second already.)
awk -F, '{ gsub(/"/, "", $1); gsub(/"/, "", $8); sub(/_median$/, "", $1)
  perCore = $8 == "" ? $7 : $7 * $3 / $4
  printf "%-70s %9.2f %s %9.3g oscillator-samples/s (per core %9.3g)  %s\n", $1, $3, $5, $7, perCore, $8 }' \
  "$work/bench.csv"
awk -F, '
  { gsub(/"/, "", $1); gsub(/"/, "", $8) }
  $1 ~ /^BM_Synthesize(WithKernel)?\/(bubbles:)?100000\// { rate[$1] = $7; core[$1] = $7 * $3 / $4; label[$1] = $8 }
  $1 ~ /BM_BaselineComplexRotation/ { r = $7 }
  $1 ~ /BM_BaselineSinExp/ { e = $7 }
  END { for (k in rate) printf "100 k bubbles, %s: all cores vs one-core complex rotation %.2fx, vs one-core sin/exp %.1fx; per busy core vs complex rotation %.2fx\n", label[k], rate[k] / r, rate[k] / e, core[k] / r }' \
  "$work/bench.csv" | sort

/usr/bin/python3 "$here/tools/make_example_bubbles.py" --pour-file "$work/long.bubbles.json" \
  --pour-end 60 --peak-rate 2000 >/dev/null
/usr/bin/time -f "60 s render: %e s wall, peak resident memory %M KiB" \
  "$build/tools/fluidsound" synth "$work/long.bubbles.json" -o "$work/long.wav" --quiet
grep -E '"(read|synthesis|write)"' -A1 "$work/long.wav.report.json" | tr -d '\n{} ' | sed 's/--/ /g; s/$/\n/'
