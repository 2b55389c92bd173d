#!/usr/bin/env bash
# Lists the displacement histories of a sweep run with --keep-trajectories, one line per
# complete point in point order: "TRAJECTORY_CSV<TAB>COLUMN_OF_box.x<TAB>LABEL".
#   [WHERE=AWK_CONDITION] history_data.sh SWEEP_DIR LABEL_COLUMN...
# WHERE selects points by column values, e.g. 'v("mu_s") - v("mu_k") < 0.051'.
set -euo pipefail
dir=$1; shift
labels="$*"
head='
function v(name) { return $col[name] + 0 }
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; n = split(labels, names, " "); next }
$col["status"] == "complete" && ('
tail=') {
  label = ""
  for (k = 1; k <= n; k++) label = label (k > 1 ? ", " : "") names[k] " = " $col[names[k]]
  label = label sprintf("  (p-p %.3f m)", $col["amplitude_pp"])
  print $1, label
}'
awk -F, -v labels="$labels" "$head${WHERE:-1}$tail" "$dir/results.csv" |
  while read -r point label; do
    pad=$(ls "$dir/points" | head -1 | awk '{print length($0)}')
    file=$(printf "%s/points/%0${pad}d/trajectory.csv" "$dir" "$point")
    xcol=$(head -1 "$file" | tr ',' '\n' | grep -nx 'box.x' | cut -d: -f1)
    printf "%s\t%s\t%s\n" "$file" "$xcol" "$label"
  done
