#!/usr/bin/env bash
# The figure of docs/experiments.md (gnuplot; build/apps/tribo runs each scene of
# scenes/experiments/): docs/figures/experiments.png, six panels from the engine's runs:
#   break_away_ramp: the push F = rate t and the block's x (millimetres) against time;
#   servo_stick_slip: the slide's x, the servo's target and its effort against time;
#   arm_hold_pose: the shoulder's and elbow's angles and targets against time;
#   belt_modulated: the box's x and the belt's speed against time;
#   presliding_drift: the block's x (micrometres) under lugre and under elasto_plastic;
#   velocity_steps: the friction coefficient under the aging and the slip law, and the speed.
#   vibration_slip: the block's x on the shaken plate at three pushes, against the averaged
#     Coulomb law's creep V sin(pi r / 2) t.
# Usage: scripts/plot_experiments.sh [OUT_DIR]   (default docs/figures)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/figures}
tribo=${TRIBO:-build/apps/tribo}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

run() {  # NAME [--set ...]: runs scenes/experiments/NAME.yaml into $work/NAME
  local name=$1
  shift
  "$tribo" run "scenes/experiments/$name.yaml" --out "$work/$name" --quiet "$@" > /dev/null
}
# Column numbers of trajectory.csv by name, for gnuplot's `using`.
col() { head -1 "$work/$1/trajectory.csv" | tr ',' '\n' | grep -nx "$2" | cut -d: -f1; }

run break_away_ramp
run servo_stick_slip --set duration=25
run arm_hold_pose
run belt_modulated --set duration=20 --set 'output.channels=[position, velocity]'
run presliding_drift
"$tribo" run scenes/experiments/presliding_drift.yaml --set friction=elasto_plastic \
  --out "$work/presliding_drift_ep" --quiet > /dev/null
run velocity_steps
"$tribo" run scenes/experiments/velocity_steps.yaml --set evolution=slip \
  --out "$work/velocity_steps_slip" --quiet > /dev/null
for r in 0.1 0.3 0.6; do
  "$tribo" run scenes/experiments/vibration_slip.yaml --set ratio=$r \
    --out "$work/vibration_slip_$r" --quiet > /dev/null
done

gnuplot <<GP
set terminal pngcairo noenhanced size 1200,1680 font 'Helvetica,10'
set output '$out/experiments.png'
set datafile separator ','
set key top left
set grid
set multiplot layout 4,2
set title 'break_away_ramp: push F = t N/s, block x'
set xlabel 't [s]'
set ylabel 'F [N]'
set y2label 'x [mm]'
set y2tics
set ytics nomirror
plot '$work/break_away_ramp/trajectory.csv' every ::1 using 1:$(col break_away_ramp push.fx) with lines lw 2 title 'push.fx', \
     '' every ::1 using 1:(1e3*\$$(col break_away_ramp block.x)) axes x1y2 with lines lw 2 title 'block.x'
set title 'servo_stick_slip: LuGre guide, servo target at 0.1 m/s'
set ylabel 'x [m]'
set y2label 'effort [N]'
plot '$work/servo_stick_slip/trajectory.csv' every ::1 using 1:$(col servo_stick_slip slide.x) with lines lw 2 title 'slide.x', \
     '' every ::1 using 1:$(col servo_stick_slip servo.target) with lines dt 2 title 'servo.target', \
     '' every ::1 using 1:$(col servo_stick_slip servo.effort) axes x1y2 with lines title 'servo.effort'
set title 'arm_hold_pose: PD servos against gravity'
set ylabel 'angle [rad]'
set y2label 'effort [N m]'
plot '$work/arm_hold_pose/trajectory.csv' every ::1 using 1:$(col arm_hold_pose shoulder.q) with lines lw 2 title 'shoulder.q', \
     '' every ::1 using 1:$(col arm_hold_pose shoulder_servo.target) with lines dt 2 title 'shoulder target', \
     '' every ::1 using 1:$(col arm_hold_pose elbow.q) with lines lw 2 title 'elbow.q', \
     '' every ::1 using 1:$(col arm_hold_pose elbow_servo.target) with lines dt 2 title 'elbow target', \
     '' every ::1 using 1:$(col arm_hold_pose shoulder_servo.effort) axes x1y2 with lines title 'shoulder effort'
set title 'belt_modulated: belt speed 1.5 + 0.5 sin(2 pi 0.4 t) m/s'
set ylabel 'x [m]'
set y2label 'speed [m/s]'
plot '$work/belt_modulated/trajectory.csv' every ::1 using 1:$(col belt_modulated box.x) with lines lw 2 title 'box.x', \
     '' every ::1 using 1:$(col belt_modulated box.vx) axes x1y2 with lines title 'box.vx', \
     '' every ::1 using 1:(1.5 + 0.5*sin(2*pi*0.4*\$1)) axes x1y2 with lines dt 2 title 'belt speed'
set title 'presliding_drift: push 0.35 + 0.3 sin(2 pi 2 t) N, mu_c F_n = 1 N'
set ylabel 'x [um]'
unset y2label
unset y2tics
set ytics mirror
plot '$work/presliding_drift/trajectory.csv' every ::1 using 1:(1e6*\$$(col presliding_drift block.x)) with lines lw 2 title 'lugre: walks', \
     '$work/presliding_drift_ep/trajectory.csv' every ::1 using 1:(1e6*\$$(col presliding_drift block.x)) with lines lw 2 title 'elasto_plastic: stays'
set title 'velocity_steps: rate-and-state, speed 1e-5 -> 1e-4 -> 1e-5 m/s'
set ylabel 'mu = friction / normal force'
set y2label 'speed [mm/s]'
set y2range [0:0.2]
set y2tics
set ytics nomirror
plot '$work/velocity_steps/trajectory.csv' every ::1 using 1:(\$$(col velocity_steps block.friction_force)/\$$(col velocity_steps block.normal_force)) with lines lw 2 title 'aging law', \
     '$work/velocity_steps_slip/trajectory.csv' every ::1 using 1:(\$$(col velocity_steps block.friction_force)/\$$(col velocity_steps block.normal_force)) with lines lw 2 title 'slip law', \
     '$work/velocity_steps/trajectory.csv' every ::1 using 1:(1e3*\$$(col velocity_steps block.vx)) axes x1y2 with lines dt 2 title 'speed'
set title 'vibration_slip: plate shaken at 0.1 m/s, 200 Hz; push r mu m g (dashed: V sin(pi r / 2) t)'
set ylabel 'block x [mm]'
unset y2label
unset y2tics
set autoscale y2
set ytics mirror
plot for [r in '0.1 0.3 0.6'] '$work/vibration_slip_'.r.'/trajectory.csv' every ::1 using 1:(1e3*\$$(col vibration_slip_0.1 block.x)) with lines lw 2 title 'r = '.r, \
     for [r in '0.1 0.3 0.6'] 1e3*0.1*sin(pi*r/2)*x with lines dt 2 lc 'black' notitle
unset multiplot
GP
echo "wrote $out/experiments.png"
