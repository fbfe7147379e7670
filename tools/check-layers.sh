#!/bin/sh
# Checks the layering of docs/architecture.md, as CI runs it (ctest `layers`). Exit 1 with every
# offending line listed, 0 when it holds. Three rules:
# 1. No file includes a header from a layer above its own. Layers, lowest first: base exec io
#    model sim analysis experiment campaign api; render and export sit on sim beside analysis; app/
#    (the command) and tests/ may include anything. A file's layer is its folder (src/LAYER/,
#    include/footsim/LAYER/, render/); a footsim header's layer is its folder under include/footsim/.
# 2. Only the sim layer (src/sim/, include/footsim/sim/) calls ODE or includes its headers: no
#    call of a d[A-Z]... function and no #include <ode/...> elsewhere in src/, include/, render/
#    or app/ (comments and string literals aside); what the command needs of ODE (its build
#    configuration, its error path for the tests) it asks through include/footsim/sim/fs_ode.h.
# 3. A header beside its sources is private to its folder: src/LAYER/*.h to src/LAYER/,
#    render/*.h to render/, app/*.h to app/ (and app/bench/). No file elsewhere includes one;
#    tests/ may.
set -eu
cd "$(dirname "$0")/.."
rank() {
  case "$1" in
    base) echo 0 ;; exec) echo 1 ;; io) echo 2 ;; model) echo 3 ;; sim) echo 4 ;; analysis) echo 5 ;;
    render) echo 5 ;; export) echo 5 ;; experiment) echo 6 ;; campaign) echo 7 ;; api) echo 8 ;; *) echo 99 ;;
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
  [ "$own" -eq 99 ] && { echo "$f: not in a layer folder (base exec io model sim analysis export experiment campaign api render)"; bad=1; continue; }
  grep -n '#include "footsim/' "$f" | while IFS= read -r line; do
    inc=$(echo "$line" | sed 's|.*#include "footsim/\([^/]*\)/.*|\1|')
    r=$(rank "$inc")
    # render, export and analysis share a rank but do not see each other; only render includes
    # render (export may be included from above: the command, campaign, api)
    if [ "$r" -gt "$own" ] || { [ "$r" -eq "$own" ] && [ "$inc" != "$layer" ]; } ||
       { [ "$inc" = render ] && [ "$layer" != render ]; }; then
      echo "$f:${line%%:*}: includes a header of layer '$inc' from layer '$layer'; a layer may include only its own and those below it"
      exit 1
    fi
  done || bad=1
done

# C with its comments and string and character literals blanked, line numbers kept.
code_only() {
  awk '
    BEGIN { inc = 0 }
    {
      out = ""; n = length($0); i = 1
      while (i <= n) {
        c = substr($0, i, 1); d = substr($0, i, 2)
        if (inc) { if (d == "*/") { inc = 0; i += 2 } else i++; continue }
        if (d == "/*") { inc = 1; i += 2; continue }
        if (d == "//") break
        if (c == "\"" || c == "\047") {
          q = c; i++
          while (i <= n && substr($0, i, 1) != q) i += (substr($0, i, 1) == "\\") ? 2 : 1
          i++; out = out q q; continue
        }
        out = out c; i++
      }
      print out
    }' "$1"
}

# 2. ODE only in the sim layer
for f in $(find src include/footsim render app -name '*.c' -o -name '*.h' | sort); do
  case "$f" in src/sim/* | include/footsim/sim/*) continue ;; esac
  hits=$(code_only "$f" | grep -nE '(^|[^A-Za-z0-9_])d[A-Z][A-Za-z0-9_]*[[:space:]]*\(|#[[:space:]]*include[[:space:]]*<ode/' || true)
  if [ -n "$hits" ]; then
    echo "$hits" | while IFS= read -r line; do
      echo "$f:${line%%:*}: calls ODE or includes its header outside the sim layer; only src/sim/ may (add a function to include/footsim/sim/)"
    done
    bad=1
  fi
done

# 3. private headers stay in their folder
owner() {
  case "$1" in
    src/*) echo "$1" | cut -d/ -f1-2 ;;
    render/*) echo render ;;
    app/*) echo app ;;
    *) echo public ;;
  esac
}
private=$(find src render app -name '*.h' | sort)
for f in $(find src include/footsim render app -name '*.c' -o -name '*.h' | sort); do
  mine=$(owner "$f")
  for inc in $(sed -n 's|^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]\([^">]*\)[">].*|\1|p' "$f"); do
    base=${inc##*/}
    for h in $private; do
      [ "${h##*/}" = "$base" ] || continue
      theirs=$(owner "$h")
      if [ "$theirs" != "$mine" ]; then
        echo "$f: includes $inc, a header private to $theirs/; use a public header of include/footsim/ instead"
        bad=1
      fi
    done
  done
done

[ "$bad" -eq 0 ] && echo "layers: every include points down or sideways within its own layer; only the sim layer calls ODE; private headers stay in their folders"
exit "$bad"
