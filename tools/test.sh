#!/usr/bin/env bash
# Quick start 2 (and CI): installs what is missing, builds everything, runs the whole test suite,
# then the fuzzing step (tools/fuzz.sh: the libFuzzer harnesses over their committed corpus, then
# each for $FUZZ_SECONDS, default 60 s; tests/fuzz/README.md).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh"
ctest --test-dir "$here/build" --output-on-failure -j"$(nproc)"
"$here/tools/fuzz.sh"
