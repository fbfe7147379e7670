#!/bin/sh
# mujoco-trial (tools/mujoco_trial.c): a landing trial exported with its drawn pose, run in MuJoCo
# and judged by footsim's rules. Where the pitch-stiffness law is sharp both engines must agree:
# the Table I foot under single_tall (K = 12.8 N m/rad against m g h = 76.5) topples past 45 deg;
# under drop_weight (5.1 against 12.8) it lands, and so does the flat foot under single_tall. The
# drawn pose reaches the export: MuJoCo's touchdown lies within three steps (the step MuJoCo finds
# the contact in, read a step late) of footsim's for the same seed, and the seeds' touchdowns differ
# by more than that. Bad options are refused with exit 2.
# Usage: cli_mujoco_trial.sh path/to/mujoco-trial|none path/to/footsim
mj=$1
if [ "$mj" = none ]; then
    echo "skipped: built without FS_MUJOCO (libmujoco-dev)"
    exit 77
fi
shift
. "$(dirname "$0")/cli_check.sh"
trial=scenarios/landing_trial.ini
field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" "$2" | head -n 1; }

# refusals: nothing run
"$mj" $trial --cone round >/dev/null 2>"$tmp/err"
st=$?
check '[ $st -eq 2 ] && grep -q "pyramidal or elliptic" "$tmp/err"'
"$mj" $trial --timeconst -1 >/dev/null 2>&1
st=$?
check '[ $st -eq 2 ]'
"$mj" scenarios/static_load.ini >/dev/null 2>"$tmp/err"
st=$?
check '[ $st -eq 2 ] && grep -q "trial" "$tmp/err"'
"$mj" $trial --set sole.stiffness_N_per_m=-1 >/dev/null 2>"$tmp/err"
st=$?
check '[ $st -eq 2 ] && grep -q "stiffness_N_per_m" "$tmp/err"'

# the law's sharp cases
"$mj" $trial --seed 1 >"$tmp/tall" 2>&1
check 'grep -q "seed=1 outcome=fell rule=leaned" "$tmp/tall"'
"$mj" $trial --seed 1 --set robot.design=robots/drop_weight.ini >"$tmp/weight" 2>&1
check 'grep -q "seed=1 outcome=landed" "$tmp/weight"'
"$mj" $trial --seed 2 --set scenario.design=feet/flat.ini >"$tmp/flat" 2>&1
check 'grep -q "seed=2 outcome=landed" "$tmp/flat"'

# the drawn pose: MuJoCo's lean at the start is the tilt footsim's trial drew (pitch and roll),
# and its touchdown lies within three steps of footsim's, for two seeds whose tilts differ
json() { tr -d ' \t\n' <"$2" | sed -n "s/.*\"$1\":\([^,}]*\).*/\1/p"; }
pose() { tr -d ' \t\n' <"$1" | sed -n 's/.*"pose_x_y_m_yaw_pitch_roll_deg":\[\([^]]*\)\].*/\1/p'; }
start_lean() { sed -n 's/.*t=0.0000 lean_deg=\([^ ]*\).*/\1/p' "$1"; }
for s in 1 8; do
    "$mj" $trial --seed $s --set robot.design=robots/drop_weight.ini --set run.duration_s=0.06 --trace 1 >"$tmp/mj$s" 2>&1
    "$fs" trial $trial --seed $s --set robot.design=robots/drop_weight.ini --set run.duration_s=0.06 --json >"$tmp/fs$s" 2>&1
done
t_mj1=$(field touchdown_s "$tmp/mj1") t_mj8=$(field touchdown_s "$tmp/mj8")
t_fs1=$(json touchdown_s "$tmp/fs1") t_fs8=$(json touchdown_s "$tmp/fs8")
lean_mj1=$(start_lean "$tmp/mj1") lean_mj8=$(start_lean "$tmp/mj8")
pose_fs1=$(pose "$tmp/fs1") pose_fs8=$(pose "$tmp/fs8")
echo "seed 1: touchdown MuJoCo $t_mj1 s, footsim $t_fs1 s; lean at the start $lean_mj1 deg, pose $pose_fs1"
echo "seed 8: touchdown MuJoCo $t_mj8 s, footsim $t_fs8 s; lean at the start $lean_mj8 deg, pose $pose_fs8"
near() { awk -v a="$1" -v b="$2" -v tol="$3" 'BEGIN { d = a - b; exit !(a != "" && b != "" && d < tol && d > -tol) }'; }
# the lean of a body pitched p and rolled r: acos(cos p cos r)
tilt() { echo "$1" | awk -F, '{ d = atan2(0, -1) / 180; print acos(cos($4 * d) * cos($5 * d)) / d }
                              function acos(x) { return atan2(sqrt(1 - x * x), x) }'; }
check 'near "$t_mj1" "$t_fs1" 3e-4 && near "$t_mj8" "$t_fs8" 3e-4'
check 'near "$lean_mj1" "$(tilt "$pose_fs1")" 0.002 && near "$lean_mj8" "$(tilt "$pose_fs8")" 0.002'
check '! near "$(tilt "$pose_fs1")" "$(tilt "$pose_fs8")" 0.05'
finish mujoco_trial
