# Fig. 6: time to the limit cycle against the decay base a, with the linearized growth rate
# sigma(a) = ln(a) (mu_s - mu_k) a^-(v_b - v_s) g / 2 and its maximum a* = exp(1/(v_b - v_s)).
# gnuplot -e "data='results.csv'; out='fig6.png'" fig6.gp
set terminal pngcairo size 760, 620 font ",9"
set output out
set datafile separator ","
set datafile columnheaders
vb = 1.5; vs = 0.01; dmu = 0.05; g = 9.81
sigma(a) = log(a) * dmu * a**(-(vb - vs)) * g / 2
astar = exp(1 / (vb - vs))
set xrange [1:4]
set lmargin 10
set rmargin 10
set multiplot layout 2, 1 title "Fig. 6: decay base a (v_b = 1.5 m/s, mu_s = 0.35, mu_k = 0.3)" font ",11"
set arrow 1 from astar, graph 0 to astar, graph 1 nohead dt 2 lc rgb "#888888"
set label 1 sprintf(" a* = exp(1/(v_b - v_s)) = %.3f", astar) at astar, graph 0.93 font ",8"
set ylabel "time to 98% of the amplitude [s]"
set y2label "linearized growth rate sigma [1/s]"
set y2tics
set ytics nomirror
set key top right opaque box font ",8"
set format x ""
plot data using (column("a")):(column("rise_time")) with linespoints pt 7 ps 0.5 lc rgb "#1f5fa8" title "rise time (interpolated)", \
     data using (column("a")):(column("time_to_98")) with steps lc rgb "#9bbbe0" title "time to 98% (end of cycle)", \
     sigma(x) axes x1y2 with lines dt 3 lw 1.5 lc rgb "#c0392b" title "sigma(a)"
unset y2tics; unset y2label; unset label 1
set ytics mirror
set key off
set format x "%g"
set xlabel "a"
set ylabel "limit-cycle amplitude p-p [m]"
set yrange [0.5:0.6]
plot data using (column("a")):(column("amplitude_pp")) with linespoints pt 7 ps 0.5 lc rgb "#1f5fa8" notitle
unset multiplot
