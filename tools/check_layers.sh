#!/usr/bin/env bash
# The runtime's layers run one way: a file under runtime/<layer>/ includes only files of its own
# layer or of lower ones. Prints every include that runs up and exits 1 if there is one.
#   io < gl < scene < shading < data < nn < lua < live < app
set -euo pipefail
cd "$(dirname "$0")/.."
order=(io gl scene shading data nn lua live app)
rank() {
  local i
  for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && { echo "$i"; return; }; done
  echo -1
}
bad=0
for dir in runtime/*/; do
  layer=$(basename "$dir")
  own=$(rank "$layer")
  if [ "$own" -lt 0 ]; then
    echo "runtime/$layer/ is not a known layer (${order[*]}): add it to tools/check_layers.sh"
    bad=1
    continue
  fi
  while IFS=: read -r file line text; do
    inc=$(sed -E 's/.*#include "([a-z_]+)\/.*/\1/' <<<"$text")
    if [ "$(rank "$inc")" -gt "$own" ]; then
      echo "$file:$line: $layer/ includes $inc/ (a higher layer): ${text#*#include }"
      bad=1
    fi
  done < <(grep -rn '^#include "[a-z_]*/' "$dir" || true)
done
[ "$bad" -eq 0 ] && echo "layers: every include runs down (${order[*]})"
exit "$bad"
