#!/usr/bin/env bash
# Draws the plots a run with SHADENET_PLOTS=later left as gnuplot scripts (scripts/lib/plot.lua):
# every NAME.gp under DIR whose NAME.png is missing or older, in its own folder.
#   tools/draw_plots.sh DIR...
set -euo pipefail
[ $# -gt 0 ] || { echo "usage: tools/draw_plots.sh DIR..." >&2; exit 2; }
drawn=0
while IFS= read -r -d '' gp; do
  png=${gp%.gp}.png
  [ -f "$png" ] && [ "$png" -nt "$gp" ] && continue
  # Drawn to a temporary name and renamed, so a failure never leaves a half-written PNG.
  tmp=".$(basename "$png").tmp$$"
  (cd "$(dirname "$gp")" && gnuplot -e "out = '$tmp'" "$(basename "$gp")" && mv "$tmp" "$(basename "$png")") ||
    { echo "draw_plots.sh: gnuplot failed on $gp" >&2; exit 1; }
  echo "$png"
  drawn=$((drawn + 1))
done < <(find "$@" -name '*.gp' -print0 | sort -z)
echo "draw_plots.sh: $drawn plot(s) drawn"
