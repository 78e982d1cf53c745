#!/usr/bin/env bash
# Fuzzes shadenet's file loaders with libFuzzer (tests/fuzz/; docs/reliability.md, "Fuzzing").
#
#   tools/fuzz.sh [SECONDS [TARGET...]]    SECONDS per target (default 60), all targets by default
#
# Builds build-fuzz/ with clang (coverage instrumentation + ASan + UBSan) and runs each target for
# SECONDS, starting from its committed seeds and crash inputs. Inputs that reach new code collect
# in build-fuzz/corpus/TARGET (kept between runs, not committed); each run's log is
# build-fuzz/logs/TARGET.log. A crash, hang (30 s) or memory blow-up (8 GiB) saves the input under
# build-fuzz/crashes/TARGET/ and makes the script fail: once fixed, commit that file under
# tests/fuzz/crashes/TARGET/, where every build replays it as the test fuzz.TARGET.
# SHADENET_FUZZ_SEED=N fixes libFuzzer's random seed (CI does, so a failure there reproduces);
# unset, each run explores differently.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gltf image checkpoint dataset run_file include activation)

CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADENET_FUZZ=ON \
  -DBUILD_TESTING=OFF >/dev/null
cmake --build build-fuzz -j2 --target "${targets[@]/#/fuzz_}"

failed=()
for t in "${targets[@]}"; do
  work=build-fuzz/corpus/$t crashes=build-fuzz/crashes/$t log=build-fuzz/logs/$t.log
  mkdir -p "$work" "$crashes" build-fuzz/logs
  inputs=("$work" "tests/fuzz/corpus/$t")
  [ -d "tests/fuzz/crashes/$t" ] && inputs+=("tests/fuzz/crashes/$t")
  echo "== fuzz_$t: ${seconds} s =="
  # Leaks are not what this looks for (OpenImageIO and LuaJIT keep process-wide caches).
  if ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
     "build-fuzz/tests/fuzz/fuzz_$t" -seed="${SHADENET_FUZZ_SEED:-0}" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=8192 \
       -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$crashes/" "${inputs[@]}" >"$log" 2>&1; then
    grep -E "^#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units|stat::peak_rss_mb" "$log" || tail -3 "$log"
  else
    echo "fuzz_$t FAILED (log: $log, input under $crashes/):"
    grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$log" | head -20 || tail -30 "$log"
    failed+=("$t")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzzing found problems in: ${failed[*]}"
  exit 1
fi
echo "fuzzing: no crash in ${targets[*]} (${seconds} s each)"
