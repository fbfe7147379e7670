#!/bin/sh
# Checks that no file includes a header from a layer above its own (docs/architecture.md).
# Layers, lowest first: base exec io model sim analysis experiment campaign; render sits on sim beside
# analysis and above; app/ (the command) and tests/ may include anything. A file's layer is its
# folder (src/LAYER/, include/footsim/LAYER/, render/); a footsim header's layer is its folder under
# include/footsim/. Exit 1 with every offending line listed, 0 when the layering holds.
set -eu
cd "$(dirname "$0")/.."
rank() {
  case "$1" in
    base) echo 0 ;; exec) echo 1 ;; io) echo 2 ;; model) echo 3 ;; sim) echo 4 ;; analysis) echo 5 ;;
    render) echo 5 ;; experiment) echo 6 ;; campaign) echo 7 ;; *) echo 99 ;;
  esac
}
bad=0
for f in $(find src include/footsim render -name '*.c' -o -name '*.h' | sort); do
  case "$f" in
    src/*) layer=$(echo "$f" | cut -d/ -f2) ;;
    include/footsim/*) layer=$(echo "$f" | cut -d/ -f3) ;;
    render/*) layer=render ;;
  esac
  own=$(rank "$layer")
  [ "$own" -eq 99 ] && { echo "$f: not in a layer folder (base exec io model sim analysis experiment campaign render)"; bad=1; continue; }
  grep -n '#include "footsim/' "$f" | while IFS= read -r line; do
    inc=$(echo "$line" | sed 's|.*#include "footsim/\([^/]*\)/.*|\1|')
    r=$(rank "$inc")
    # render and analysis share a rank but do not see each other; only render includes render
    if [ "$r" -gt "$own" ] || { [ "$r" -eq "$own" ] && [ "$inc" != "$layer" ]; } ||
       { [ "$inc" = render ] && [ "$layer" != render ]; }; then
      echo "$f:${line%%:*}: includes a header of layer '$inc' from layer '$layer'; a layer may include only its own and those below it"
      exit 1
    fi
  done || bad=1
done
[ "$bad" -eq 0 ] && echo "layers: every include points down or sideways within its own layer"
exit "$bad"
