#!/usr/bin/env bash
# A stand-in for a shared library that a carried program links but never calls: a library of the
# same name (SONAME) and symbol versions that defines just the symbols the importers import from
# it, each function writing which one was called and aborting (but the few that run whether the
# library is used or not: below). tools/pack_runtime.sh uses it for OpenImageIO's readers of
# formats shadenet never reads (movies, DICOM, OpenVDB, camera raw, HEIF), whose libraries are 95%
# of the bytes OpenImageIO loads.
#
#   tools/stub_library.sh LIBRARY OUTDIR IMPORTER...
#     LIBRARY    the real library (its symbols' kinds and sizes, its name)
#     OUTDIR     where the stand-in is written, under the real library's SONAME
#     IMPORTER   the programs and libraries that link it (their imports are what is defined)
set -euo pipefail
export LC_ALL=C  # sort and join alike

[ $# -ge 3 ] || { echo "stub_library.sh: expected LIBRARY OUTDIR IMPORTER... (got $# arguments)" >&2; exit 2; }
lib=$1 out=$2
shift 2
[ -f "$lib" ] || { echo "stub_library.sh: no library '$lib'" >&2; exit 1; }
soname=$(readelf -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ -n "$soname" ] || soname=$(basename "$lib")

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# What the library defines: "name type size" (versions dropped; readelf -W: no truncated names).
readelf -W --dyn-syms "$lib" |
  awk '$7 != "UND" && ($5 == "GLOBAL" || $5 == "WEAK" || $5 == "UNIQUE") && $8 != "" {
         name = $8; sub(/@.*/, "", name); print name, $4, $3 }' | sort -u -k1,1 > "$work/defined"

# What the importers take from it: a versioned import whose version they need from this file, or an
# unversioned one that it defines. "name version" (version "-" when none).
for imp in "$@"; do
  readelf -W -V "$imp" | awk -v f="$soname" '/File:/ { here = ($5 == f) } here && /Name:/ { print $3 }' > "$work/versions"
  readelf -W --dyn-syms "$imp" | awk '$7 == "UND" && $8 != "" { print $8 }' |
    awk -v vfile="$work/versions" 'BEGIN { while ((getline v < vfile) > 0) need[v] = 1 }
         { n = split($1, p, "@"); if (n > 1) { if (p[2] in need) print p[1], p[2] } else print $1, "-" }'
done | sort -u > "$work/imports"
# name version type size; one line a name (a versioned import wins over an unversioned one)
join "$work/imports" "$work/defined" | sort -k1,1 -k2,2r | sort -u -s -k1,1 > "$work/stubbed"
[ -s "$work/stubbed" ] || { echo "stub_library.sh: the importers take nothing from $soname" >&2; exit 1; }
if awk '$3 == "TLS" { bad = 1 } END { exit !bad }' "$work/stubbed"; then
  echo "stub_library.sh: $soname exports thread-local data the importers use; it cannot be stood in for" >&2
  exit 1
fi

# Functions jump to one handler with their name, but what an importer calls whether the format is
# ever read or not returns: constructors and destructors (its global objects, built at load and
# destroyed at exit) and version queries (its list of libraries; the text "stand-in", as a number
# an address). Data is zeroed storage of the real size.
awk '
  BEGIN { print "  .text" }
  $3 != "OBJECT" && $1 ~ /^_ZN.*(C[123]|D[012])E/ {
    printf "  .globl %s\n  .type %s, @function\n%s:\n  ret\n", $1, $1, $1
    next
  }
  $3 != "OBJECT" && tolower($1) ~ /version/ {
    printf "  .globl %s\n  .type %s, @function\n%s:\n  leaq .Lstandin(%%rip), %%rax\n  ret\n", $1, $1, $1
    next
  }
  $3 != "OBJECT" {
    printf "  .globl %s\n  .type %s, @function\n%s:\n  leaq .Lname%d(%%rip), %%rdi\n  jmp sn_stub_called\n", $1, $1, $1, NR
    names[NR] = $1
  }
  $3 == "OBJECT" {
    size = $4 > 0 ? $4 : 1
    data = data sprintf("  .globl %s\n  .type %s, @object\n  .size %s, %d\n  .balign 32\n%s:\n  .zero %d\n", $1, $1, $1, size, $1, size)
  }
  END {
    print "  .section .rodata"
    print ".Lstandin:\n  .asciz \"stand-in\""
    for (i in names) printf ".Lname%d:\n  .asciz \"%s\"\n", i, names[i]
    print "  .data"
    printf "%s", data
    print "  .section .note.GNU-stack,\"\",@progbits"
  }' "$work/stubbed" > "$work/symbols.s"
cat > "$work/handler.c" <<EOF
#include <stdio.h>
#include <stdlib.h>
__attribute__((visibility("hidden"), noreturn)) void sn_stub_called(const char* symbol) {
  fprintf(stderr, "%s: %s was called, but this copy of the library is a stand-in without code "
                  "(tools/pack_runtime.sh); the format it reads is not available here\n", "$soname", symbol);
  abort();
}
EOF
# Each version the importers need, with the symbols imported at it.
flags=()
if awk '$2 != "-" { found = 1 } END { exit !found }' "$work/stubbed"; then
  awk '$2 != "-" { syms[$2] = syms[$2] "    " $1 ";\n" }
       END { for (v in syms) printf "%s {\n  global:\n%s};\n", v, syms[v] }' "$work/stubbed" > "$work/versions.map"
  flags+=(-Wl,--version-script="$work/versions.map")
fi
mkdir -p "$out"
cc -shared -fPIC -o "$out/$soname" -Wl,-soname,"$soname" "${flags[@]}" "$work/handler.c" "$work/symbols.s"
echo "$soname: $(wc -l < "$work/stubbed") symbols stood in for"
