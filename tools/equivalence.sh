#!/bin/sh
# Campaign equivalence (docs/bench.md): runs a campaign at a reference step and at each step to
# judge, with the same seeds, and judges each against the reference with
# `footsim compare --equivalence`. Writes OUT/reference/ (the reference campaign's files),
# OUT/h<STEP>.md (each comparison) and OUT/equivalence.md (one row per step: verdict, cells that
# differ, wall time of the campaign and its speed-up on the reference's).
# Usage: tools/equivalence.sh [CAMPAIGN] [OUT] [REFERENCE_STEP] [STEP...]
# Default: scenarios/equivalence_flat.ini into build/equivalence, reference 1e-5 s, steps 1e-4 s
# (the default) to 1e-2 s. Every campaign runs with the same workers, FS_JOBS (default 1), so that
# wall times compare.
set -eu
fs=${FOOTSIM:-build/footsim}
campaign=${1:-scenarios/equivalence_flat.ini}
out=${2:-build/equivalence}
ref=${3:-1e-5}
jobs=${FS_JOBS:-1}
[ $# -gt 3 ] && shift 3 || set -- 1e-4 2e-4 5e-4 1e-3 2e-3 5e-3 1e-2
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }
run() { # STEP DIR: the campaign at STEP into DIR; prints its wall time in seconds
    t0=$(now)
    "$fs" campaign "$campaign" --set run.step_s="$1" --out "$2" --replace -j "$jobs" >/dev/null 2>"$tmp/err" || {
        st=$?; [ $st -eq 1 ] || { cat "$tmp/err" >&2; exit $st; }; } # 1: an expectation of the file failed
    t1=$(now)
    echo "$t0 $t1" | awk '{ printf "%.1f", $2 - $1 }'
}
echo "footsim equivalence: the reference at h = $ref s ..." >&2
ref_wall=$(run "$ref" "$tmp/reference")
rm -rf "$out/reference"
cp -r "$tmp/reference" "$out/reference"
{
    echo "# Campaign equivalence: \`$campaign\`"
    echo
    echo "\`tools/equivalence.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'); $(uname -m), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg) at the start; $jobs worker(s) (-j $jobs). Reference: h = $ref s, $ref_wall s of wall time. A step is *equivalent* when every cell's success intervals overlap the reference's and its medians of impulse, final lean, ankle drop, settle time and contacts lie within 5 % or a floor (\`footsim compare --equivalence\`; each step's table in \`h<STEP>.md\`)."
    echo
    echo "| step h (s) | verdict | quantities that differ | wall time (s) | speed-up on the reference |"
    echo "|--:|---|--:|--:|--:|"
} >"$tmp/equivalence.md"
for h in "$@"; do
    echo "footsim equivalence: h = $h s ..." >&2
    wall=$(run "$h" "$tmp/h$h")
    set +e
    "$fs" compare "$tmp/h$h/summary.json" "$tmp/reference/summary.json" --equivalence >"$out/h$h.md"
    st=$?
    set -e
    [ $st -le 1 ] || exit $st
    differ=$(grep -c '\*\*differs\*\*' "$out/h$h.md" || true)
    verdict=$([ $st -eq 0 ] && echo equivalent || echo "**not equivalent**")
    echo "| $h | $verdict | $differ | $wall | $(echo "$ref_wall $wall" | awk '{ printf "%.1f", $1 / $2 }') |" \
        >>"$tmp/equivalence.md"
done
cp "$tmp/equivalence.md" "$out/equivalence.md"
cat "$out/equivalence.md"
