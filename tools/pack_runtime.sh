#!/usr/bin/env bash
# What a machine without shadenet's dependencies needs to run it (the lent GPU machines: README.md,
# "On a GPU"), packed small enough for one device call (a call carries at most 64 MiB, the
# repository's 16 MiB included): the shared libraries build/shadenet, build/tests/shadenet_unit
# and the image module load beyond the C runtime and the GL loaders, and the build's programs and
# test files (build/ without CMake's objects and the core library).
#
# OpenImageIO links the readers of formats shadenet never reads or writes (movies through FFmpeg
# and OpenCV, DICOM, OpenVDB, camera raw, HEIF): 95% of the bytes of the libraries it loads. Those
# are packed as stand-ins (tools/stub_library.sh: the same names and symbols, no code), listed in
# lib/stand-ins.txt; their own dependencies are left out. tools/gpu_bench.sh --libs then sets
# OPENIMAGEIO_OPTIONS=try_all_readers=0, so that a file the reader of its extension refuses is not
# offered to the stood-in readers (a call into one aborts, naming it).
#
#   tools/pack_runtime.sh [--part-mib N] [--level L] [--all] [--list] OUTDIR
#     --part-mib N   each part at most N MiB (default 40)
#     --level L      xz level (default 6; 0 packs in seconds, larger)
#     --all          pack every library, no stand-ins (about 95 MB at level 6: 3 parts, 3 calls)
#     --list         print the libraries that would be packed, and "stand-in NAME" for the others;
#                    pack nothing
#
# writes OUTDIR/runtime.tar.xz.part-aa (-ab, ...) and OUTDIR/MANIFEST (each library, its size,
# each part's sha256). Left out, because the other machine has its own and a foreign copy would
# break it: glibc's libraries and the loader, libstdc++ and libgcc_s (newer there), and the
# GL/EGL loaders (glvnd: NVIDIA's driver or the carried .gl packages). xz, because Python's lzma
# unpacks it where no xz command is. On the other machine, with every part in one folder DIR:
#
#   cat DIR/runtime.tar.xz.part-* | xz -d | tar -x -C /opt/shadenet   # lib/ and build/
#   ln -s /opt/shadenet/build build
#   tools/gpu_bench.sh --relocate --libs /opt/shadenet/lib OUTDIR
set -euo pipefail
cd "$(dirname "$0")/.."

part_mib=40 level=6 list=0 all=0
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --part-mib) part_mib=${2:?--part-mib needs a number of MiB}; shift ;;
    --level) level=${2:?--level needs an xz level, 0-9}; shift ;;
    --list) list=1 ;;
    --all) all=1 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "pack_runtime.sh: unknown option '$1' (valid: --part-mib N, --level L, --all, --list, --help)" >&2; exit 2 ;;
    *) break ;;
  esac
  shift
done
[[ $part_mib =~ ^[1-9][0-9]*$ ]] || { echo "pack_runtime.sh: --part-mib must be a whole number of MiB, got '$part_mib'" >&2; exit 2; }
[[ $level =~ ^[0-9]$ ]] || { echo "pack_runtime.sh: --level must be 0-9, got '$level'" >&2; exit 2; }
if [ $list = 0 ]; then
  [ $# -eq 1 ] || { echo "pack_runtime.sh: expected one OUTDIR after the options (got $#)" >&2; usage >&2; exit 2; }
fi

# The image module (OpenImageIO, loaded on first use) brings most of the libraries.
programs=(build/shadenet build/tests/shadenet_unit build/libshadenet_image.so)
for p in "${programs[@]}"; do
  [ -x "$p" ] || { echo "pack_runtime.sh: $p is missing: build first (README.md)" >&2; exit 1; }
done

# Every library the programs need, found by following each file's NEEDED entries (paths as ldd
# resolves them here), less the ones the other machine brings; a stood-in library's own needs are
# not followed. "name path" lines in $libs, "name importer..." lines in $stand_ins.
keep='^(linux-vdso|ld-linux|libc|libm|libmvec|libpthread|libdl|librt|libresolv|libutil|libanl|libstdc\+\+|libgcc_s|libGL|libEGL|libGLX|libGLdispatch|libOpenGL|libGLES)[.-]'
stand_in='^lib(av(codec|format|util)|swscale|opencv_[a-z]+|dcm[a-z]+|oflog|ofstd|openvdb|raw_r|heif)[.]so'
[ $all = 1 ] && stand_in='^$'
missing=$(ldd "${programs[@]}" | awk '/not found/ { print $1 }' | sort -u)
[ -z "$missing" ] || { echo "pack_runtime.sh: ldd finds no $missing here" >&2; exit 1; }
declare -A path=() packed=() importers=()
while read -r name p; do path[$name]=$p; done < <(ldd "${programs[@]}" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }' | sort -u)
queue=("${programs[@]}")
while [ ${#queue[@]} -gt 0 ]; do
  file=${queue[0]}
  queue=("${queue[@]:1}")
  for name in $(readelf -d "$file" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
    [[ $name =~ $keep ]] && continue
    if [[ $name =~ $stand_in ]]; then
      importers[$name]+=" $file"
    elif [ -z "${packed[$name]:-}" ]; then
      packed[$name]=${path[$name]:?pack_runtime.sh: ldd did not resolve $name}
      queue+=("${packed[$name]}")
    fi
  done
done
libs=$(for name in "${!packed[@]}"; do echo "$name ${packed[$name]}"; done | sort)
stand_ins=$(for name in "${!importers[@]}"; do echo "$name${importers[$name]}"; done | sort)
if [ $list = 1 ]; then
  echo "$libs" | cut -d' ' -f2
  [ -z "$stand_ins" ] || echo "$stand_ins" | awk '{ print "stand-in", $1 }'
  exit 0
fi

out=$1
mkdir -p "$out"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir "$stage/lib"
# Each library's file under the name the programs ask for.
echo "$libs" | while read -r name file; do cp -L "$file" "$stage/lib/$name"; done
if [ -n "$stand_ins" ]; then
  echo "$stand_ins" | while read -r name imps; do
    tools/stub_library.sh "${path[$name]}" "$stage/lib" $imps > /dev/null
  done
  echo "$stand_ins" | cut -d' ' -f1 > "$stage/lib/stand-ins.txt"
fi
count=$(echo "$libs" | wc -l)
stood_in=$(echo -n "$stand_ins" | grep -c . || true)
rm -f "$out"/runtime.tar.xz.part-* "$out/MANIFEST"
# With the libraries, the build's programs and CTest files (the test suite runs from build/),
# not its objects and the core library.
skip=(--exclude=CMakeFiles --exclude='*.a' --exclude='*.o')
tar -c -C "$stage" lib -C "$PWD" "${skip[@]}" build | xz -T0 -"$level" | split -b "${part_mib}M" - "$out/runtime.tar.xz.part-"
bytes=$(du -scb "$stage/lib" "${skip[@]}" build | tail -1 | cut -f1)
{
  echo "# tools/pack_runtime.sh: $count libraries, $stood_in stand-ins and build/, $bytes bytes unpacked, xz -$level, parts of at most $part_mib MiB"
  (cd "$stage/lib" && ls -l --time-style=+ | awk 'NR > 1 { print $5, "lib/" $NF }')
  [ -z "$stand_ins" ] || echo "$stand_ins" | awk '{ printf "stand-in lib/%s for", $1; for (i = 2; i <= NF; i++) printf " %s", $i; print "" }'
  (cd "$out" && sha256sum runtime.tar.xz.part-*)
} >"$out/MANIFEST"
echo "pack_runtime.sh: $count libraries, $stood_in stand-ins and build/ ($((bytes / 1048576)) MiB) in $(ls "$out"/runtime.tar.xz.part-* | wc -l) parts under $out/"
