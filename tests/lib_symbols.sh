#!/bin/sh
# Every symbol the shared libraries export carries footsim's prefix (fs_): a program that links
# libfootsim (or libfootsim-render) gets no name that could clash with its own. AddressSanitizer's
# own markers of globals (__odr_asan.NAME, a sanitized build only) are its, not footsim's.
# usage: lib_symbols.sh LIBRARY...
fail=0
for lib in "$@"; do
  [ -n "$lib" ] || continue # the renderer's place, empty in a build without it
  [ -f "$lib" ] || { echo "$lib: no such library"; fail=1; continue; }
  total=$(nm -D --defined-only "$lib" | awk '$2 ~ /[TDBRVW]/' | wc -l)
  stray=$(nm -D --defined-only "$lib" | awk '$2 ~ /[TDBRVW]/ && $3 !~ /^fs_/ && $3 !~ /^_(init|fini|edata|end|_bss_start)$/ && $3 !~ /^__odr_asan\./ {print $3}')
  if [ -n "$stray" ] || [ "$total" -lt 10 ]; then
    echo "$lib: $total symbols; exported without the fs_ prefix:"; echo "$stray" | sed 's/^/  /'
    fail=1
  else
    echo "$lib: $total symbols, every one fs_"
  fi
done
[ $fail -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $fail
