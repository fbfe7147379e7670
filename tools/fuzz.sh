#!/bin/sh
# Builds the libFuzzer targets with clang (AddressSanitizer and UndefinedBehaviorSanitizer) and runs
# each for SECONDS (default 60) from its seed corpus in tests/fuzz/: design and terrain files
# (config), heightmap PNGs (png), scenario files parsed and compiled (scenario), campaign files with
# the files they name (campaign; both resolve the shipped files from a temporary folder of links),
# campaign journals read as a resume and a merge read them (journal).
# A crash fails the run; its input is left in build-fuzz/ (crash-*): copy it into the corpus as a
# regression test once fixed. Usage: sh tools/fuzz.sh [SECONDS] [TARGET...]
set -eu
seconds=${1:-60}
[ $# -gt 0 ] && shift
targets=${*:-config png scenario campaign journal}
if ! command -v clang >/dev/null 2>&1 || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
    echo "fuzz: installing clang and its libFuzzer runtime" >&2
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q clang libclang-rt-14-dev >/dev/null
fi
CC=clang cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Debug -DFS_FUZZ=ON -DFS_RENDER=OFF \
    -DCMAKE_C_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all" >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target $(for t in $targets; do printf 'fuzz_%s ' "$t"; done) >/dev/null
for t in $targets; do
    mkdir -p "build-fuzz/corpus_$t"
    (cd build-fuzz && tests/fuzz/fuzz_$t -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        "corpus_$t" "../tests/fuzz/corpus_$t" 2>"fuzz_$t.log") || { tail -40 "build-fuzz/fuzz_$t.log"; exit 1; }
    echo "fuzz_$t: $(grep -E '^#[0-9]+.*DONE' "build-fuzz/fuzz_$t.log" | tail -1)"
done
