#!/usr/bin/env bash
# The library's folders are layers, each using only those below it:
#
#   timing < fem < linalg < interface < contact < study
#
# (the clocks; one body; sparse solvers; what lives on Gamma_c; two bodies in contact; the
# studies and figures of the chapters). An #include from a lower folder of common/ to a higher
# one fails this check, with the file and the line.
#
#   check_layers.sh COMMON_DIR
set -u
common=${1:?usage: check_layers.sh COMMON_DIR}
layers=(timing fem linalg interface contact study)
rank_of() {
  local k
  for k in "${!layers[@]}"; do [ "${layers[$k]}" = "$1" ] && { echo "$k"; return; }; done
  echo -1
}
failures=0
for folder in "${layers[@]}"; do
  [ -d "$common/$folder" ] || { echo "check_layers: no folder $common/$folder" >&2; exit 1; }
  own=$(rank_of "$folder")
  while IFS=: read -r file line text; do
    [ -n "$file" ] || continue
    target=$(printf '%s' "$text" | sed -n 's|.*#include "common/\([a-z_]*\)/.*|\1|p')
    used=$(rank_of "$target")
    if [ "$used" -lt 0 ] || [ "$used" -gt "$own" ]; then
      echo "$file:$line: $folder/ includes common/$target/, a higher layer (order: ${layers[*]})" >&2
      failures=$((failures + 1))
    fi
  done < <(grep -rn '#include "common/' "$common/$folder" --include='*.hpp' --include='*.cpp')
done
# every folder of common/ is a layer
for dir in "$common"/*/; do
  name=$(basename "$dir")
  [ "$(rank_of "$name")" -ge 0 ] || { echo "check_layers: $name/ is not in the layer order" >&2; failures=$((failures + 1)); }
done
[ "$failures" -eq 0 ] || exit 1
echo "check_layers: every include of common/ points to the same layer or one below (${layers[*]})"
