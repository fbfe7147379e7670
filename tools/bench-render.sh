#!/usr/bin/env bash
# Times the renderer: `footsim run` from a build without it (FS_RENDER=OFF) and one with it, both
# without --frames (the renderer must cost nothing when off), and frames per second of rendering
# with --frames (drawing and PNG writing; the run's own time subtracted) at 640x480 and 1280x720.
# Writes results/bench/render.csv; each time is the median of REPEAT runs (default 5).
set -euo pipefail
cd "$(dirname "$0")/.."
repeat=${REPEAT:-5}
scenario=scenarios/static_load.ini
fps=1000 # frames per simulated second: about 200 frames over the 0.2 s run
make -s build >/dev/null
make -s build BUILD=build-norender CMAKE_FLAGS="-DFS_RENDER=OFF" >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# seconds FOOTSIM ARGS...: the wall time of one run, s
seconds() {
    start=$(date +%s.%N)
    "$@" --out "$tmp/out" >/dev/null
    end=$(date +%s.%N)
    awk -v s="$start" -v e="$end" 'BEGIN {print e - s}'
}

# median: of the numbers on stdin
median() { sort -g | awk '{t[NR] = $1} END {printf "%.4f", t[int((NR + 1) / 2)]}'; }

# median_seconds FOOTSIM ARGS...: the median wall time of repeat runs, s
median_seconds() {
    for _ in $(seq "$repeat"); do seconds "$@"; done | median
}

# without frames, the two builds taking turns, so that other load on the machine hits both alike
for _ in $(seq "$repeat"); do
    seconds build-norender/footsim run $scenario >>"$tmp/off"
    seconds build/footsim run $scenario >>"$tmp/on"
done
off=$(median <"$tmp/off")
on=$(median <"$tmp/on")
out=results/bench/render.csv
{
    echo "case,build,size,frames,seconds,render_seconds,fps"
    echo "run without frames,FS_RENDER=OFF,,0,$off,,"
    echo "run without frames,FS_RENDER=ON,,0,$on,,"
    for size in 640x480 1280x720; do
        t=$(median_seconds build/footsim run $scenario --frames --fps $fps --size $size)
        n=$(ls "$tmp/out/frames" | wc -l)
        awk -v t="$t" -v on="$on" -v n="$n" -v size="$size" \
            'BEGIN {printf "run --frames,FS_RENDER=ON,%s,%d,%.4f,%.4f,%.1f\n", size, n, t, t - on, n / (t - on)}'
    done
} >"$out.tmp"
mv "$out.tmp" "$out"
column -s, -t "$out" 2>/dev/null || cat "$out"
echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -1); Mesa $(dpkg-query -W -f '${Version}' libosmesa6 2>/dev/null || echo unknown), llvmpipe"
