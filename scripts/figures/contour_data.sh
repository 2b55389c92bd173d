#!/usr/bin/env bash
# Turns a two-axis sweep's results.csv into gnuplot grid data: "x y z" lines, one block per
# value of the sweep's first (slow) axis, blocks separated by a blank line.
#   contour_data.sh RESULTS XCOL XEXPR YCOL YEXPR ZCOL
# XEXPR/YEXPR are awk expressions of $1, the column's value (e.g. 'sqrt($1/10)', '$1-0.3').
# Points that did not complete give z = NaN (a hole in the map). The leading columns read
# here never hold commas, so splitting on commas is safe for them.
set -euo pipefail
results=$1; xcol=$2; xexpr=$3; ycol=$4; yexpr=$5; zcol=$6
awk -F, -v xc="$xcol" -v yc="$ycol" -v zc="$zcol" "
function fx(v,  r) { \$0 = v; r = $xexpr; return r }
function fy(v,  r) { \$0 = v; r = $yexpr; return r }
NR == 1 { for (i = 1; i <= NF; i++) col[\$i] = i; slow = \$2; next }
{
  x = \$col[xc]; y = \$col[yc]; z = (\$col[\"status\"] == \"complete\") ? \$col[zc] : \"NaN\"
  s = \$2
  if (NR > 2 && s != last) print \"\"
  last = s
  line = sprintf(\"%.10g %.10g %s\", fx(x), fy(y), z)
  print line
}" "$results"
