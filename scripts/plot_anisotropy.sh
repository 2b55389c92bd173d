#!/usr/bin/env bash
# The figure of direction-dependent friction (docs/contact.md; contact/anisotropy.hpp):
# docs/figures/anisotropic-friction.png, three panels from the engine's runs of
# scenes/experiments/ against references computed here:
#   anisotropic_slider: the block's path launched at three angles to its grain, against the
#     particle's equation u' = -mu g tanh(|R u| / v_eps) R^2 u / |R u| integrated by RK4
#     (awk, below; dashed);
#   ratchet_drive: x(t) under a symmetric push at three amplitudes, against the block's
#     equation u' = r0 mu g sin(2 pi f t) - r mu g tanh(r u / v_eps) (awk, RK4), and the
#     symmetric sole that stays;
#   ski_on_slope: the grooved ski's heading against time, turning to the fall line, and the
#     plain ski's;
#   ball_on_slope: the ball's x at 0.9 and 1.5 of its rolling threshold, against the rolling
#     ball's x = a t^2 / 2 with the moment held at mu_r F_n (a with the contact's lever r_e)
#     and rest.
# Usage: scripts/plot_anisotropy.sh [OUT_DIR]   (default docs/figures)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/figures}
tribo=${TRIBO:-build/apps/tribo}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

col() { head -1 "$work/$1/trajectory.csv" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }

for b in 0.6 2.0 -1.0; do
  "$tribo" run scenes/experiments/anisotropic_slider.yaml --set beta=$b \
    --out "$work/slider_$b" --quiet > /dev/null
  # The particle: ratios 0.5 forward, 3 backward along x, 1.5 across; mu 0.3, v_eps 1e-3.
  awk -v b=$b 'function th(x,   e) { if (x > 20) return 1; if (x < -20) return -1; e = exp(2 * x); return (e - 1) / (e + 1) }
    function ax(u, v,   r1, w1, w2, s, t) {
      r1 = u >= 0 ? 0.5 : 3.0; w1 = r1 * u; w2 = 1.5 * v; s = sqrt(w1 * w1 + w2 * w2);
      if (s == 0) { A = 0; B = 0; return }
      t = -0.3 * 9.81 * th(s / 1e-3) / s; A = t * r1 * w1; B = t * 1.5 * w2 }
    BEGIN { h = 1e-4; x = 0; y = 0; u = cos(b); v = sin(b);
      for (i = 0; i <= 20000; i++) {
        if (i % 50 == 0) print x "," y;
        ax(u, v); a1 = A; b1 = B; ax(u + h / 2 * a1, v + h / 2 * b1); a2 = A; b2 = B;
        ax(u + h / 2 * a2, v + h / 2 * b2); a3 = A; b3 = B; ax(u + h * a3, v + h * b3); a4 = A; b4 = B;
        x += h * (u + h / 6 * (a1 + a2 + a3)); y += h * (v + h / 6 * (b1 + b2 + b3));
        u += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4); v += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4) } }' \
    > "$work/particle_$b.csv"
done
for r in 0.8 1.0 1.4; do
  "$tribo" run scenes/experiments/ratchet_drive.yaml --set ratio=$r \
    --out "$work/ratchet_$r" --quiet > /dev/null
  awk -v r0=$r 'function th(x,   e) { if (x > 20) return 1; if (x < -20) return -1; e = exp(2 * x); return (e - 1) / (e + 1) }
    function acc(t, u,   r) { r = u >= 0 ? 0.5 : 1.5;
      return r0 * 0.3 * 9.81 * sin(2 * 3.141592653589793 * 2 * t) - r * 0.3 * 9.81 * th(r * u / 1e-3) }
    BEGIN { h = 1e-4; x = 0; u = 0;
      for (i = 0; i <= 20000; i++) { t = i * h; if (i % 100 == 0) print t "," x;
        k1 = acc(t, u); k2 = acc(t + h / 2, u + h / 2 * k1); k3 = acc(t + h / 2, u + h / 2 * k2);
        k4 = acc(t + h, u + h * k3); x += h * (u + h / 6 * (k1 + k2 + k3)); u += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4) } }' \
    > "$work/ratchet_ref_$r.csv"
done
"$tribo" run scenes/experiments/ratchet_drive.yaml --set backward=0.5 \
  --out "$work/ratchet_sym" --quiet > /dev/null
"$tribo" run scenes/experiments/ski_on_slope.yaml --out "$work/ski" --quiet > /dev/null
for r in 0.9 1.5; do
  "$tribo" run scenes/experiments/ball_on_slope.yaml --set ratio=$r --out "$work/ball_$r" \
    --quiet > /dev/null
done
# a = g (sin(alpha) - mu_r cos(alpha) / r_e) / (1 + 0.4 r^2 / r_e^2) at ratio 1.5 (r = 0.05,
# mu_r = 0.002, r_e = r - m g cos(alpha) / (2 k), k = 1e5 N/m).
accel=$(awk 'BEGIN { r = 0.05; mu = 0.002; al = atan2(1.5 * mu / r, 1);
  re = r - 9.81 * cos(al) / 2e5; print 9.81 * (sin(al) - mu * cos(al) / re) / (1 + 0.4 * r * r / (re * re)) }')
"$tribo" run scenes/experiments/ski_on_slope.yaml --set across=1 \
  --out "$work/ski_plain" --quiet > /dev/null

gnuplot <<GP
set terminal pngcairo noenhanced size 2000,480 font 'Helvetica,10'
set output '$out/anisotropic-friction.png'
set datafile separator ','
set grid
set key top left
set multiplot layout 1,4
set title 'anisotropic_slider: launched at 1 m/s, grain along x (0.5 / 3 along, 1.5 across)'
set xlabel 'x [m]'
set ylabel 'y [m]'
set size ratio -1
plot for [b in '0.6 2.0 -1.0'] '$work/slider_'.b.'/trajectory.csv' every ::1 using $(col slider_0.6 block.x):$(col slider_0.6 block.y) with lines lw 3 title 'beta = '.b, \
     for [b in '0.6 2.0 -1.0'] '$work/particle_'.b.'.csv' using 1:2 with lines dt 2 lc 'black' notitle
set size noratio
set title 'ratchet_drive: push F0 sin(2 pi 2 t), sole 0.5 forward / 1.5 backward'
set xlabel 't [s]'
set ylabel 'block x [mm]'
plot for [r in '0.8 1.0 1.4'] '$work/ratchet_'.r.'/trajectory.csv' every ::1 using 1:(1e3*\$$(col ratchet_0.8 block.x)) with lines lw 3 title 'F0 = '.r.' mu m g', \
     for [r in '0.8 1.0 1.4'] '$work/ratchet_ref_'.r.'.csv' using 1:(1e3*\$2) with lines dt 2 lc 'black' notitle, \
     '$work/ratchet_sym/trajectory.csv' every ::1 using 1:(1e3*\$$(col ratchet_sym block.x)) with lines lw 2 title 'symmetric sole, F0 = mu m g'
set title 'ski_on_slope: heading from the fall line (15 degree slope)'
set ylabel 'yaw [deg]'
plot '$work/ski/trajectory.csv' every ::1 using 1:(2*atan2(\$$(col ski ski.qz),\$$(col ski ski.qw))*180/pi) with lines lw 3 title 'grooved tail (8x across)', \
     '$work/ski_plain/trajectory.csv' every ::1 using 1:(2*atan2(\$$(col ski_plain ski.qz),\$$(col ski_plain ski.qw))*180/pi) with lines lw 3 title 'plain base'
set title 'ball_on_slope: mu_r = 2 mm, r = 5 cm (dashed: rolling ball)'
set ylabel 'ball x [mm]'
set logscale y
set yrange [1e-3:1e3]
plot '$work/ball_0.9/trajectory.csv' every ::1 using 1:(1e3*abs(\$$(col ball_0.9 ball.x))) with lines lw 3 title 'tan(alpha) = 0.9 mu_r / r_e: holds', \
     '$work/ball_1.5/trajectory.csv' every ::1 using 1:(1e3*\$$(col ball_1.5 ball.x)) with lines lw 3 title '1.5: rolls', \
     1e3*0.5*$accel*x*x with lines dt 2 lc 'black' notitle
unset multiplot
GP
echo "wrote $out/anisotropic-friction.png"
