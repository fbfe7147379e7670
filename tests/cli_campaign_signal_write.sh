#!/bin/sh
# A campaign stopped while it writes its results (issues 13 §1 and 16 §3): SIGTERM to footsim, or
# SIGINT to its whole process group (Ctrl-C), arriving while gnuplot draws success.png, must not
# install a folder without its chart or with gnuplot's temporary file in it, nor exit 0: the old
# folder stays whole, the journal is kept, exit 143/130 with the one "stopped by" line, and the
# printed command then writes the uninterrupted run's bytes. The signal is sent by a gnuplot
# stand-in on PATH (then the real gnuplot runs), so it always lands in the write phase.
# Usage: cli_campaign_signal_write.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"

gnuplot=$(command -v gnuplot)
if [ -z "$gnuplot" ]; then
    echo "cli_campaign_signal_write: gnuplot is not installed: skipped"
    exit 0
fi
. tests/small_campaign.sh

camp -j 2 --out "$tmp/ref" >/dev/null 2>&1
check_that "the uninterrupted run exits 0" [ $? -eq 0 ]

# gnuplot stand-ins: each signals, then runs the real gnuplot (killed with its group for SIGINT)
mkdir "$tmp/term-bin" "$tmp/int-bin"
printf '#!/bin/sh\nkill -TERM $PPID\nexec %s "$@"\n' "$gnuplot" >"$tmp/term-bin/gnuplot"
printf '#!/bin/sh\nkill -INT 0\nexec %s "$@"\n' "$gnuplot" >"$tmp/int-bin/gnuplot"
chmod +x "$tmp/term-bin/gnuplot" "$tmp/int-bin/gnuplot"

stopped_in_write() { # stopped_in_write NAME SIGNAL STATUS: $tmp/NAME held seeds=2 before the stop
    check_that "$1: exit $3" [ "$4" -eq "$3" ]
    check_that "$1: the old folder whole" cmp -s "$tmp/$1.old.json" "$tmp/$1/summary.json"
    check_that "$1: its chart still there" [ -s "$tmp/$1/success.png" ]
    check_that "$1: no temporary file in it" [ -z "$(find "$tmp/$1" -name '*.tmp.*')" ]
    check_that "$1: no partial folder left" [ -z "$(ls "$tmp" | grep "^$1\.partial\.")" ]
    check_that "$1: the one line, all 6 trials kept" \
        grep -q "^footsim campaign: stopped by $2: 6 of 6 trials done, kept in $tmp/$1.journal/; to continue: " \
        "$tmp/$1.err"
    camp -j 2 --out "$tmp/$1" >/dev/null 2>&1
    check_that "$1: run again: exit 0" [ $? -eq 0 ]
    for f in $files; do
        check_that "$1: run again: $f byte for byte an uninterrupted run's" cmp -s "$tmp/ref/$f" "$tmp/$1/$f"
    done
    check_that "$1: run again: the journal removed" [ ! -e "$tmp/$1.journal" ]
}

# SIGTERM to footsim alone
camp -j 2 --out "$tmp/term" --set campaign.seeds=2 >/dev/null 2>&1
cp "$tmp/term/summary.json" "$tmp/term.old.json"
PATH="$tmp/term-bin:$PATH" camp -j 2 --out "$tmp/term" >/dev/null 2>"$tmp/term.err"
stopped_in_write term SIGTERM 143 $?

# SIGINT to the process group (a Ctrl-C), in a session of its own so that only footsim's group gets it
if command -v setsid >/dev/null 2>&1 && env --default-signal=INT true 2>/dev/null; then
    camp -j 2 --out "$tmp/int" --set campaign.seeds=2 >/dev/null 2>&1
    cp "$tmp/int/summary.json" "$tmp/int.old.json"
    PATH="$tmp/int-bin:$PATH" setsid -w env --default-signal=INT nice "$fs" campaign "$tmp/small.ini" \
        --set run.duration_s=0.15 -j 2 --out "$tmp/int" >/dev/null 2>"$tmp/int.err"
    stopped_in_write int SIGINT 130 $?
else
    echo "cli_campaign_signal_write: no setsid or env --default-signal: the Ctrl-C case skipped"
fi

finish cli_campaign_signal_write
