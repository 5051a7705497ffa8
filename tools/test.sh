#!/usr/bin/env bash
# Quick start 2 (and CI): installs what is missing, builds everything, runs the whole test suite.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh"
ctest --test-dir "$here/build" --output-on-failure -j"$(nproc)"
