#!/usr/bin/env bash
# Draws the plots a run with SHADENET_PLOTS=later left as gnuplot scripts (scripts/lib/plot.lua):
# every NAME.gp under DIR whose NAME.png is missing or older, in its own folder.
#   tools/draw_plots.sh DIR...
set -euo pipefail
[ $# -gt 0 ] || { echo "usage: tools/draw_plots.sh DIR..." >&2; exit 2; }
# gnuplot draws into a scratch folder of ours, so a failure leaves nothing beside the plot; the
# PNG replaces the old one only when whole (cairo reports success on a full disk and leaves it
# cut short), through a temporary beside it that is flushed, then renamed (docs/reliability.md).
scratch=$(mktemp -d)
trap 'rm -rf -- "$scratch"' EXIT
out_name=$(printf '%s' "$scratch/plot.png" | sed "s/'/''/g")  # for gnuplot's single quotes
dirs=()
for d in "$@"; do case $d in -*) dirs+=("./$d") ;; *) dirs+=("$d") ;; esac; done  # find reads -x as a test
drawn=0
while IFS= read -r -d '' gp; do
  png=${gp%.gp}.png
  [ -f "$png" ] && [ "$png" -nt "$gp" ] && continue
  rm -f -- "$scratch/plot.png"
  # ./NAME: gnuplot reads a name starting with "-" as an option.
  if ! said=$(cd -- "$(dirname -- "$gp")" && gnuplot -e "out = '$out_name'" "./$(basename -- "$gp")" 2>&1); then
    printf 'draw_plots.sh: gnuplot failed on %s:\n%s\n' "$gp" "$said" >&2
    exit 1
  fi
  end=$(tail -c 12 "$scratch/plot.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')
  if [ "$end" != 0000000049454e44ae426082 ]; then
    echo "draw_plots.sh: gnuplot's PNG for $gp is not whole (no IEND chunk at its end: is $scratch full?)" >&2
    exit 1
  fi
  tmp="$(dirname -- "$png")/.$(basename -- "$png").tmp$$"
  if ! { cp -- "$scratch/plot.png" "$tmp" && sync -- "$tmp" && mv -f -- "$tmp" "$png"; }; then
    rm -f -- "$tmp"
    echo "draw_plots.sh: cannot write $png (the old one is untouched)" >&2
    exit 1
  fi
  echo "$png"
  drawn=$((drawn + 1))
done < <(find "${dirs[@]}" -name '*.gp' -print0 | sort -z)
echo "draw_plots.sh: $drawn plot(s) drawn"
