# Stacked displacement histories of the box (one panel per sweep point).
# gnuplot -e "list='LIST'; out='OUT.png'; ttl='TITLE'" history.gp
# LIST lines (history_data.sh): TRAJECTORY_CSV <tab> COLUMN_OF_box.x <tab> LABEL
n = int(system("wc -l < '".list."'"))
field(i, k) = system(sprintf("awk -F'\t' 'NR==%d{print $%d}' '%s'", i, k, list))
set terminal pngcairo size 680, (90 * n + 70) font ",8"
set output out
set datafile separator ","
set multiplot layout n, 1 title ttl font ",11" margins 0.10, 0.98, 0.07, 0.90 spacing 0, 0.012
set key top left opaque box samplen 0 font ",8"
set offsets 0, 0, graph 0.12, graph 0.05
set ytics font ",8"
set grid ytics lc rgb "#dddddd"
do for [i = 1:n] {
  f = field(i, 1)
  c = int(field(i, 2))
  set ylabel "x [m]" offset 1, 0
  if (i < n) { set format x ""; unset xlabel } else { set format x "%g"; set xlabel "t [s]" }
  plot f using 1:c with lines lw 1 lc rgb "#1f5fa8" title field(i, 3) noenhanced
}
unset multiplot
