#!/bin/sh
# Checks that no two of the library's source files need each other, directly or round a longer
# circle (docs/architecture.md): each file's calls go one way, so a file can be read, tested and
# replaced knowing only what it calls. Reads the built objects' symbols (nm), so it needs a build:
# usage: check-circles.sh BUILD_DIR. Exit 1 listing the files left in a circle and what each takes
# from the others, 0 when there is none.
set -eu
build=${1:?usage: check-circles.sh BUILD_DIR}
objs=$(find "$build/CMakeFiles" -path '*/footsim_*.dir/src/*' -name '*.o' | sort)
[ -n "$objs" ] || { echo "check-circles: no objects of the library under $build/CMakeFiles: build first"; exit 1; }
# shellcheck disable=SC2086
nm -A $objs | awk '
  {
    # "OBJ:ADDRESS T name" for a definition, "OBJ: U name" for a use
    split($1, p, "/src/"); f = p[2]; sub(/\.o:.*$/, "", f)
    if (NF == 3 && $2 ~ /^[TDBR]$/) def[$3] = f
    else if (NF == 3 && $2 == "U") use[f, $3] = 1
    files[f] = 1
  }
  END {
    for (k in use) {
      split(k, q, SUBSEP); s = q[2]
      if ((s in def) && def[s] != q[1]) { edge[q[1], def[s]] = 1; why[q[1], def[s]] = why[q[1], def[s]] " " s }
    }
    # peel off the files that need no file left, and those no file left needs (Kahn, both ways):
    # what remains sits on a circle
    do {
      changed = 0
      for (f in files) {
        out = 0; inn = 0
        for (g in files) { if ((f, g) in edge) out = 1; if ((g, f) in edge) inn = 1 }
        if (!out || !inn) { delete files[f]; changed = 1 }
      }
    } while (changed)
    n = 0
    for (f in files) n++
    if (n == 0) { print "no circles among the library'"'"'s files"; exit 0 }
    print "files on a circle (each needs another of them):"
    for (f in files) for (g in files) if ((f, g) in edge) print "  " f " -> " g ":" why[f, g]
    exit 1
  }'
