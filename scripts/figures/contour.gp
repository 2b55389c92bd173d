# Contour map of a sweep figure over two parameters (Figs. 10-12): a colour map on a
# logarithmic scale and labelled contour lines at 1-2-3-5 steps.
# gnuplot -e "data='X_Y_Z.dat'; out='OUT.png'; xl='X'; yl='Y'; ttl='TITLE'" contour.gp
# data: "x y z" lines, one block per x (scripts/figures/contour_data.sh).
levels = "0.1,0.15,0.2,0.3,0.5,0.75,1,1.5,2,3,5,7.5,10,15,20"
contours = data.".contours"
# Pass 1: the contour lines as data.
set contour base
unset surface
set cntrparam linear
eval "set cntrparam levels discrete ".levels
set table contours
splot data using 1:2:3
unset table
# One label per contour piece, at its middle point.
labels = data.".labels"
system(sprintf("awk '/^# Contour/ {flush(); v = $NF; n = 0; next} NF == 3 {n++; x[n] = $1; y[n] = $2} function flush() {if (n > 4) print x[int(n/2)], y[int(n/2)], v} END {flush()}' '%s' > '%s'", contours, labels))
# Pass 2: the map.
unset contour
set surface
set terminal pngcairo size 720, 560 font ",9"
set output out
set title ttl font ",11"
set xlabel xl
set ylabel yl
set view map
set pm3d map corners2color c1
set palette defined (0 "#0d0887", 1 "#6a00a8", 2 "#b12a90", 3 "#e16462", 4 "#fca636", 5 "#f0f921")
set logscale cb
set cbtics ("0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20)
set style textbox opaque fillcolor rgb "#ffffff" noborder margins 1, 1
set cblabel "amplitude p-p [m] (log scale)"
set autoscale xfix
set autoscale yfix
set key off
splot data using 1:2:3 with pm3d, \
      contours using 1:2:3 with lines lc rgb "#ffffff" lw 1, \
      labels using 1:2:3:3 with labels font ",8" tc rgb "#000000" boxed
