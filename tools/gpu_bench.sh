#!/usr/bin/env bash
# Every benchmark of issue 16 in one call, for a machine with a GPU (README.md, "On a GPU"):
#
#   tools/gpu_bench.sh [options] OUTDIR
#     --quick         shrink every step (a smoke test: seconds on llvmpipe, figures meaningless)
#     --setup-gl      first make OpenGL through EGL reach NVIDIA's driver (below)
#     --relocate      make a carried build/ work in this copy of the repository (below)
#     --build         configure and build build/ (Release) first; by default build/ must exist
#     --skip S,...    leave steps out: gl_info, train, train_per_net, render, tables_4_5_4_7,
#                     table_4_1, ctest
#     --libs DIR      prepend DIR to LD_LIBRARY_PATH (runtime libraries carried to the machine:
#                     tools/pack_runtime.sh packs them; with stand-ins, OpenImageIO reads a
#                     file with the reader of its extension alone)
#     --shared DIR    the shared meshes folder (../shared) when it is not beside the repository
#
# Steps, each with a time limit, timed, its output in OUTDIR/NAME.log; one failing or running out
# of time is recorded and the next one runs:
#   machine         nvidia-smi, CPU, load, commit
#   gl_info         build/shadenet --gl-info, on the auto and device EGL platforms
#   train           bench/train_throughput.lua gl with 1, 2, 8, 32, 360, 1440 and 5760 networks per
#                   job (SHADENET_BENCH_COUNTS overrides the list), the device's kernel
#   train_per_net   the same with the per-network kernel (SHADENET_GL_KERNEL=per_net), 4x6 and 8x8
#   render          bench/render_throughput.lua, 640x480 .. 1920x1080, gl and cpu backends
#   tables_4_5_4_7  scripts/tables_4_5_4_7_performance.lua, full mode, into OUTDIR/results/
#   table_4_1       scripts/table_4_1_phong.lua --backend gl, full mode, into OUTDIR/results/
#                   (its wall time is in the summary and in its run.json)
#   ctest           the whole test suite (without the windowed tests when xvfb-run is missing),
#                   JUnit XML beside the log; the failed tests then again one at a time with the
#                   driver's debug messages (SHADENET_GL_DEBUG=1) into ctest_rerun.log
# then OUTDIR/summary.txt (one line per step: status, seconds, limit) and OUTDIR.tar.gz, all of it
# in one file (a device run returns at most 8 files, each at most 16 MiB, 2 folders deep).
# Without gnuplot the scripts leave their plots as gnuplot scripts (SHADENET_PLOTS=later):
# unpack the tarball where gnuplot is and run tools/draw_plots.sh OUTDIR.
# Benchmarks run one at a time, before the test suite, so that nothing else loads the machine.
# The limits (SHADENET_LIMIT_<STEP> seconds overrides one) add up to 630 s, more than one 10-minute
# device call allows: split the steps over two calls with --skip, or lower limits.
#
# --setup-gl, for a machine whose image has NVIDIA's driver but no glvnd loader (the lent H100 and
# H200 machines): unpack the glvnd packages carried in .gl/ (here: `apt-get download libegl1
# libglvnd0 libopengl0 libgl1 libglx0 libgles2` into .gl/, and carry .gl) into /, run ldconfig,
# and point glvnd at NVIDIA's EGL vendor file (__EGL_VENDOR_LIBRARY_FILENAMES).
# --relocate: a build/ made elsewhere knows the absolute path it was configured at (CTest files,
# the shader folder compiled into shadenet); when that path does not exist here it becomes a link
# to this copy, and the shared folder beside it (../shared) a link to --shared.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

quick=0 setup=0 relocate=0 build=0 skip="" libs="" shared=""
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --quick) quick=1 ;;
    --setup-gl) setup=1 ;;
    --relocate) relocate=1 ;;
    --build) build=1 ;;
    --skip) skip=${2:?--skip needs a list such as ctest,table_4_1}; shift ;;
    --libs) libs=${2:?--libs needs a folder}; shift ;;
    --shared) shared=${2:?--shared needs a folder}; shift ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "gpu_bench.sh: unknown option '$1' (valid: --quick, --setup-gl, --relocate, --build, --skip S,..., --libs DIR, --shared DIR, --help)" >&2; exit 2 ;;
    *) break ;;
  esac
  shift
done
[ $# -eq 1 ] || { echo "gpu_bench.sh: expected one OUTDIR after the options (got $#)" >&2; usage >&2; exit 2; }
steps="gl_info train train_per_net render tables_4_5_4_7 table_4_1 ctest"
for s in ${skip//,/ }; do
  [[ " $steps " == *" $s "* ]] || { echo "gpu_bench.sh: --skip: unknown step '$s' (valid: ${steps// /, })" >&2; exit 2; }
done
mkdir -p "$1"
out=$(cd "$1" && pwd)
summary=$out/summary.txt
shadenet=$root/build/shadenet

if [ -n "$libs" ]; then
  export LD_LIBRARY_PATH=$(cd "$libs" && pwd)${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  # Stood-in readers (tools/pack_runtime.sh) are offered no file the reader of its extension refused;
  # gnuplot, which would load the stand-ins through LD_LIBRARY_PATH too, is left for later.
  if [ -s "$libs/stand-ins.txt" ]; then
    export OPENIMAGEIO_OPTIONS=try_all_readers=0${OPENIMAGEIO_OPTIONS:+,$OPENIMAGEIO_OPTIONS}
    export SHADENET_PLOTS=later
  fi
fi

if [ $setup = 1 ]; then
  shopt -s nullglob
  debs=(.gl/*.deb)
  [ ${#debs[@]} -gt 0 ] || { echo "gpu_bench.sh: --setup-gl: no .gl/*.deb (download them here and carry .gl)" >&2; exit 2; }
  for f in "${debs[@]}"; do dpkg -x "$f" /; done
  ldconfig
  vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  if [ -f $vendor ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; fi
fi
if [ $relocate = 1 ]; then
  configured=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' build/CMakeCache.txt 2>/dev/null || true)
  if [ -n "$configured" ] && [ "$configured" != "$root" ] && [ ! -e "$configured" ]; then
    mkdir -p "$(dirname "$configured")" && ln -s "$root" "$configured"
    echo "--relocate: $configured -> $root"
  fi
  # The error tests run CMake by the path it had where the build was configured.
  cmake_used=$(sed -n 's/^CMAKE_COMMAND:INTERNAL=//p' build/CMakeCache.txt 2>/dev/null || true)
  if [ -n "$cmake_used" ] && [ ! -e "$cmake_used" ] && command -v cmake > /dev/null; then
    mkdir -p "$(dirname "$cmake_used")" && ln -s "$(command -v cmake)" "$cmake_used" && echo "--relocate: $cmake_used -> $(command -v cmake)"
  fi
  if [ -n "$shared" ]; then
    for d in "$root/.." "$(dirname "${configured:-$root}")"; do
      [ -e "$d/shared" ] || { ln -s "$(cd "$shared" && pwd)" "$d/shared" && echo "--relocate: $d/shared -> $shared"; }
    done
  fi
fi

: > "$summary"
note() { echo "$*" | tee -a "$summary"; }
note "tools/gpu_bench.sh$([ $quick = 1 ] && echo " --quick"): $(date -u +%Y-%m-%dT%H:%M:%SZ), commit $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
failed=0
if [ "${SHADENET_PLOTS:-}" != later ] && ! command -v gnuplot > /dev/null; then
  export SHADENET_PLOTS=later
fi
[ "${SHADENET_PLOTS:-}" = later ] && note "plots: left as gnuplot scripts (SHADENET_PLOTS=later); draw them with tools/draw_plots.sh"

# step NAME LIMIT COMMAND...: runs COMMAND with output in OUTDIR/NAME.log, within LIMIT seconds.
step() {
  local name=$1 limit=$2
  shift 2
  local var=SHADENET_LIMIT_${name^^}
  limit=${!var:-$limit}
  if [[ ",$skip," == *",$name,"* ]]; then
    printf '%-16s %-22s\n' "$name" "skipped" >> "$summary"
    return
  fi
  local log=$out/$name.log rc=0 t0 t1 status
  echo "== $name (limit ${limit} s): $*"
  { echo "\$ $*"; echo "load before: $(cat /proc/loadavg)"; } > "$log"
  t0=$(date +%s%N)
  # Line-buffered, so that a step stopped at its limit keeps every line it printed.
  timeout --kill-after=10 "$limit" stdbuf -oL -eL bash -eo pipefail -c '"$@"' step "$@" >> "$log" 2>&1 || rc=$?
  t1=$(date +%s%N)
  case $rc in
    0) status=ok ;;
    124|137) status="timed out"; failed=$((failed + 1)) ;;
    *) status="failed (exit $rc)"; failed=$((failed + 1)) ;;
  esac
  printf '%-16s %-22s %8.1f s  (limit %d s)  %s\n' "$name" "$status" "$(awk "BEGIN { print ($t1 - $t0) / 1e9 }")" "$limit" "$name.log" \
    | tee -a "$summary"
}

machine() {
  if command -v nvidia-smi > /dev/null; then
    nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv 2>&1 || true
  else
    echo "no nvidia-smi"
  fi
  echo "cpu: $(nproc) threads, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
  echo "kernel: $(uname -r)"
  echo "load: $(cat /proc/loadavg)"
  echo "LD_LIBRARY_PATH=${LD_LIBRARY_PATH:-}"
  echo "__EGL_VENDOR_LIBRARY_FILENAMES=${__EGL_VENDOR_LIBRARY_FILENAMES:-}"
  echo "OPENIMAGEIO_OPTIONS=${OPENIMAGEIO_OPTIONS:-}"
}
gl_info() {
  "$shadenet" --gl-info
  echo
  echo "SHADENET_EGL_PLATFORM=device:"
  SHADENET_EGL_PLATFORM=device "$shadenet" --gl-info
}
run_ctest() {
  local args=(--test-dir build --output-on-failure -j "$(nproc)" --output-junit "$out/ctest.xml")
  command -v xvfb-run > /dev/null || args+=(-LE window)
  [ $quick = 1 ] && args+=(-R '^(lua\.test_egl_platforms|error\.egl_platform_unknown|error\.cli_unknown_option)$')
  ctest "${args[@]}" && return
  # Failures again, one test at a time and with the driver's debug messages (OUTDIR/ctest_rerun.log):
  # what fails only beside other tests, and why the driver refused a call.
  local rc=$?
  echo "== the failed tests again, one at a time, SHADENET_GL_DEBUG=1 (ctest_rerun.log)"
  SHADENET_GL_DEBUG=1 ctest --test-dir build --rerun-failed --output-on-failure -j 1 > "$out/ctest_rerun.log" 2>&1 || true
  grep -E "tests passed|tests failed" "$out/ctest_rerun.log" || true
  return $rc
}

export out quick shadenet
export -f machine gl_info run_ctest  # steps run them in a child bash, under timeout
step machine 15 machine
if [ $build = 1 ]; then
  step build 300 bash -c "cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j $(nproc)"
fi
results=$out/results
if [ $quick = 1 ]; then
  step gl_info 30 gl_info
  step train 60 "$shadenet" bench/train_throughput.lua gl "${SHADENET_BENCH_COUNTS:-1,2}" 1 tanh 4x6
  step train_per_net 60 env SHADENET_GL_KERNEL=per_net "$shadenet" bench/train_throughput.lua gl "${SHADENET_BENCH_COUNTS:-1,2}" 1 tanh 4x6
  step render 60 "$shadenet" bench/render_throughput.lua 1 gl auto 4x4 160x120,320x240
  step tables_4_5_4_7 60 "$shadenet" scripts/tables_4_5_4_7_performance.lua --quick --backend gl \
    --out "$results/tables_4_5_4_7_performance"
  step table_4_1 60 "$shadenet" scripts/table_4_1_phong.lua --quick --shard 1/24 --backend gl --out "$results/table_4_1_phong"
  step ctest 60 run_ctest
else
  step gl_info 15 gl_info
  step train 120 "$shadenet" bench/train_throughput.lua gl "${SHADENET_BENCH_COUNTS:-1,2,8,32,360,1440,5760}"
  step train_per_net 60 env SHADENET_GL_KERNEL=per_net "$shadenet" bench/train_throughput.lua gl \
    "${SHADENET_BENCH_COUNTS:-1,2,8,32,360,1440,5760}" 1 tanh 4x6,8x8
  step render 90 "$shadenet" bench/render_throughput.lua 3 gl,cpu
  step tables_4_5_4_7 90 "$shadenet" scripts/tables_4_5_4_7_performance.lua --out "$results/tables_4_5_4_7_performance"
  step table_4_1 105 "$shadenet" scripts/table_4_1_phong.lua --backend gl --out "$results/table_4_1_phong"
  step ctest 135 run_ctest
fi

note "steps failed: $failed"
tar -czf "$out.tar.gz" -C "$(dirname "$out")" "$(basename "$out")"
note "everything: $out.tar.gz ($(du -h "$out.tar.gz" | cut -f1))"
exit $((failed > 0))
