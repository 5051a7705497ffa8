#!/usr/bin/env bash
# The fuzzing step of tools/test.sh (tests/fuzz/README.md): builds the libFuzzer harnesses in
# build-fuzz/ (clang 14, AddressSanitizer + UndefinedBehaviorSanitizer), runs each over its
# committed corpus (ctest: Fuzz.<name>.Corpus), then fuzzes each for a bounded time, as many at
# once as there are cores, and prints one line per harness: seconds, executions per second,
# coverage (libFuzzer's `cov:` edges), crashes. Exits non-zero if any step fails or finds a crash.
#   usage: tools/fuzz.sh [SECONDS]   (per harness; default $FUZZ_SECONDS, else 60; 0: corpus only)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-${FUZZ_SECONDS:-60}}
build="$here/build-fuzz"
harnesses=(scene bubble_tracks bubble_tracks_fast obj_mesh ply_mesh frame_vdb contact_log)
# The limits of tests/fuzz/CMakeLists.txt: an input slower than 10 s, a process above 2 GiB or
# one allocation above 1 GiB is a bug.
limits=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024)
export LSAN_OPTIONS="suppressions=$here/tests/fuzz/lsan.supp"   # leaks inside OpenVDB are not ours

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ ! -f "$build/CMakeCache.txt" ]; then
  CXX=clang++-14 cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Fuzz -DFLUIDSOUND_FUZZ=ON \
    "${launcher[@]}" >&2
fi
cmake --build "$build" -j"$(nproc)" --target fuzz_harnesses >&2
ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
[ "$seconds" -gt 0 ] || exit 0

# One bounded run: new inputs go to build-fuzz/fuzz/NAME/corpus (the committed corpus is only
# read), a crashing input to build-fuzz/fuzz/NAME/crash-…, the output to build-fuzz/fuzz/NAME.log.
fuzz_one() {
  local name=$1 work="$build/fuzz/$1"
  rm -rf "$work" && mkdir -p "$work/corpus" "$work/tmp"
  TMPDIR="$work/tmp" "$build/tests/fuzz/${name}_fuzz" "${limits[@]}" -max_total_time="$seconds" \
    -print_final_stats=1 -artifact_prefix="$work/" "$work/corpus" "$here/tests/fuzz/corpus/$name" \
    >"$build/fuzz/$name.log" 2>&1
}

# NAME: seconds, exec/s, edges and crashes from its log (the last `cov:` and the final stats).
summary() {
  local name=$1 log="$build/fuzz/$1.log" started=$2 ended=$3
  local rate edges crashes
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  edges=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  crashes=$(find "$build/fuzz/$name" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' \
    -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  printf 'fuzz %-20s %4d s  %8s exec/s  %6s edges  %d crashes\n' "$name" $((ended - started)) \
    "${rate:-?}" "${edges:-?}" "$crashes"
}

mkdir -p "$build/fuzz"
declare -A pid_of started_at
failed=()
running=0
finish() {  # waits for any one run, prints its line
  local done_pid status=0 name
  wait -n -p done_pid || status=$?
  for name in "${!pid_of[@]}"; do
    if [ "${pid_of[$name]}" = "$done_pid" ]; then
      summary "$name" "${started_at[$name]}" "$(date +%s)"
      if [ "$status" -ne 0 ]; then
        failed+=("$name")
        echo "fuzz $name: exit $status; the end of build-fuzz/fuzz/$name.log:" >&2
        tail -n 30 "$build/fuzz/$name.log" >&2
      fi
      unset "pid_of[$name]"
    fi
  done
  running=$((running - 1))
}
for name in "${harnesses[@]}"; do
  ((running < $(nproc))) || finish
  started_at[$name]=$(date +%s)
  fuzz_one "$name" &
  pid_of[$name]=$!
  running=$((running + 1))
done
while ((running > 0)); do finish; done
if ((${#failed[@]})); then
  echo "fuzz: crashes in ${failed[*]}: add each crash-* input to tests/fuzz/corpus/NAME/ with the fix" >&2
  exit 1
fi
