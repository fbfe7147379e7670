#!/bin/sh
# Installs footsim into a temporary prefix and uses it from elsewhere, as a user would (issue 14):
# the files are there, the installed command finds its shipped data by name from another folder and
# writes only there, --data comes first, the man page covers every command, and programs built with
# pkg-config against libfootsim (and libfootsim-render) compile and run; the example steps a sim
# through its accessors, compiled without ODE's flags and with an ode/ode.h that refuses to compile.
# Usage: cli_install.sh CMAKE BUILD_DIR LIBDIR VERSION render|norender (run from the source folder).
cmake=$1 build=$2 libdir=$3 version=$4 renderer=$5
. "$(dirname "$0")/cli_check.sh"
src=$PWD
P=$tmp/prefix
"$cmake" --install "$build" --prefix "$P" >"$tmp/install.txt" 2>&1
check '[ $? -eq 0 ] || { cat "$tmp/install.txt" >&2; false; }'
fs=$P/bin/footsim

# the files
check '[ -x "$fs" ]'
check '[ -L "$P/$libdir/libfootsim.so" ] && [ -L "$P/$libdir/libfootsim.so.1" ] && [ -f "$P/$libdir/libfootsim.so.$version" ]'
check 'objdump -p "$P/$libdir/libfootsim.so.$version" | grep -q "SONAME *libfootsim.so.1$"'
check '[ -f "$P/$libdir/pkgconfig/footsim.pc" ]'
check '[ -f "$P/share/footsim/scenarios/static_load.ini" ] && [ -f "$P/share/footsim/scenarios/feet/biomimetic.ini" ]'
check '[ -f "$P/share/footsim/terrains/heightmaps/dunes.png" ]'
check '[ -f "$P/share/man/man1/footsim.1" ]'
# every public header, and no private one (src/, render/, app/ stay inside)
check 'diff -r -x render "$src/include/footsim" "$P/include/footsim"'
check '[ -z "$(find "$P/include" -name "*_internal.h" -o -name "sim_ground.h" -o -name "cli*.h")" ]'
if [ "$renderer" = render ]; then
    check '[ -f "$P/$libdir/libfootsim-render.so.$version" ] && [ -f "$P/include/footsim/render/fs_render.h" ]'
    check '[ -f "$P/$libdir/pkgconfig/footsim-render.pc" ]'
else
    check '[ ! -e "$P/$libdir/libfootsim-render.so" ] && [ ! -e "$P/include/footsim/render" ]'
fi

# the installed command, from a folder of its own
"$fs" --version >"$tmp/version.txt"
check '[ $? -eq 0 ] && grep -Eq "^footsim $version \(git [^ )]+\)$" "$tmp/version.txt"'
(cd "$P" && find . | sort) >"$tmp/prefix-before.txt"
mkdir "$tmp/work"
(cd "$tmp/work" && "$fs" run static_load.ini >"$tmp/run.txt" 2>&1)
check '[ $? -eq 0 ] && grep -q "^static_load: biomimetic foot" "$tmp/run.txt"'
check '[ -f "$tmp/work/results/runs/static_load/metrics.json" ]'
(cd "$tmp/work" && "$fs" terrain heightmap.ini >"$tmp/terrain.txt" 2>&1)
check '[ $? -eq 0 ] && grep -q "^$P/share/footsim/terrains/heightmap.ini: heightmap terrain" "$tmp/terrain.txt"'
# --data first: a terrain of the same name in a folder given with --data wins over the installed one
mkdir -p "$tmp/mine/terrains"
sed 's/^mu = .*/mu = 0.5/' "$P/share/footsim/terrains/flat.ini" >"$tmp/mine/terrains/flat.ini"
(cd "$tmp/work" && "$fs" terrain flat.ini --data "$tmp/mine" >"$tmp/mine.txt" 2>&1)
check 'grep -q "^$tmp/mine/terrains/flat.ini: flat terrain; material mu 0.50" "$tmp/mine.txt"'
(cd "$tmp/work" && "$fs" stiffness biomimetic.ini >"$tmp/stiffness.txt" 2>&1)
check '[ $? -eq 0 ] && grep -q "agree" "$tmp/stiffness.txt"'
# nothing was written into the prefix
(cd "$P" && find . | sort) >"$tmp/prefix-after.txt"
check 'cmp -s "$tmp/prefix-before.txt" "$tmp/prefix-after.txt"'

# the man page: valid roff, every command of --help, every exit status
if command -v groff >/dev/null; then
    check 'groff -man -Tutf8 -ww -z "$P/share/man/man1/footsim.1" 2>"$tmp/groff.txt" && [ ! -s "$tmp/groff.txt" ]'
else
    echo "cli_install: no groff (Debian groff-base); the man page's roff is not checked" >&2
fi
for c in $("$fs" --help | sed -n '/^commands:/,/^$/p' | awk 'NR > 1 && NF {print $1}'); do
    check 'grep -Eq "^\.BI? \"?$c( |\"|$)" "$P/share/man/man1/footsim.1"'
done
for s in 0 1 2 3 4 5; do
    check 'sed -n "/^\.SH EXIT STATUS/,/^\.SH /p" "$P/share/man/man1/footsim.1" | grep -q "^\.B $s$"'
done

# a program built against the installed library with pkg-config, run from the prefix's library
export PKG_CONFIG_PATH="$P/$libdir/pkgconfig"
flags=$(pkg-config --cflags --libs footsim)
# ODE is private to the library (issue 31: no public header includes it): Requires.private, not
# Requires, so a program links libfootsim alone
check '[ $? -eq 0 ] && echo "$flags" | grep -q -- "-lfootsim" && ! echo "$flags" | grep -q -- "-lode"'
check '[ -z "$(pkg-config --print-requires footsim)" ] && pkg-config --print-requires-private footsim | grep -qx "ode"'
# the program compiled without ODE's flags, against an ode/ode.h that fails if anything includes it
# (Debian's ODE headers are in /usr/include: leaving out ODE's -I alone would not show an include)
mkdir -p "$tmp/poison/ode"
echo '#error "a footsim public header included ODE'"'"'s header"' >"$tmp/poison/ode/ode.h"
cc -std=c11 -Wall -Wextra -pedantic -Werror -I"$tmp/poison" -I"$P/include" -o "$tmp/example" \
    "$src/tests/install/example.c" $(pkg-config --libs footsim) 2>"$tmp/cc.txt"
check '[ $? -eq 0 ] || { cat "$tmp/cc.txt" >&2; false; }'
LD_LIBRARY_PATH="$P/$libdir" "$tmp/example" "$P/share/footsim" >"$tmp/example.txt" 2>&1
check '[ $? -eq 0 ] || { cat "$tmp/example.txt" >&2; false; }'
check 'LD_LIBRARY_PATH="$P/$libdir" ldd "$tmp/example" | grep -q "libfootsim.so.1 => $P/$libdir/libfootsim.so.1"'
# the library says what the command says: its version and chain 1's analytic stiffness
check 'grep -qxF "$(cat "$tmp/version.txt")" "$tmp/example.txt"'
want=$(grep -m1 "exact geometry" "$tmp/stiffness.txt" | sed 's/.*\[/[/')
check '[ -n "$want" ] && grep -qF "chain 1 exact geometry $want" "$tmp/example.txt"'
check 'grep -Eq "^static_load: 500 steps to t = 0.050 s, ankle at z = " "$tmp/example.txt"'
# every installed header compiles alone with the flags pkg-config gives
for h in $(cd "$P/include" && find footsim -name '*.h' | sort); do
    [ "$renderer" = render ] && rflags=$(pkg-config --cflags footsim-render) || rflags=
    printf '#include "%s"\n' "$h" | cc -std=c11 -Wall -Wextra -pedantic -Werror -fsyntax-only -x c - -I"$tmp/poison" $flags $rflags 2>"$tmp/h.txt"
    check '[ $? -eq 0 ] || { echo "$h:" >&2; cat "$tmp/h.txt" >&2; false; }'
done
if [ "$renderer" = render ]; then
    cc -std=c11 -Wall -Wextra -pedantic -Werror -o "$tmp/render_example" "$src/tests/install/render_example.c" \
        $(pkg-config --cflags --libs footsim-render) 2>"$tmp/cc.txt"
    check '[ $? -eq 0 ] || { cat "$tmp/cc.txt" >&2; false; }'
    LD_LIBRARY_PATH="$P/$libdir" "$tmp/render_example" "$tmp/2x2.png" >"$tmp/render.txt" 2>&1
    check 'grep -q "written and read back: same" "$tmp/render.txt"'
fi
# outside a git checkout the version's git part is "unknown"
mkdir "$tmp/notgit"
"$cmake" -DSRC="$tmp/notgit" -DOUT="$tmp/v.h" -P "$src/cmake/git_describe.cmake"
check 'grep -q "FS_GIT_DESCRIBE \"unknown\"" "$tmp/v.h"'
finish
