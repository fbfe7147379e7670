#!/bin/sh
# No public header (include/footsim/, every one) reaches an ODE header, directly or through
# footsim's (issue 31: fs_sim is opaque, so a program built on footsim needs neither ODE's headers
# nor a struct's layout; footsim.pc lists ODE under Requires.private).
# usage: api_header.sh CC   (run from the source folder)
cc=${1:-cc}
fail=0
n=0
for h in $(find include/footsim -name "*.h" | sort); do
  n=$((n + 1))
  files=$("$cc" -std=c11 -E -I include "$h" | sed -n 's/^# [0-9]* "\([^"]*\)".*/\1/p' | sort -u)
  [ -n "$files" ] || { echo "$h: did not preprocess"; fail=1; continue; }
  ode=$(echo "$files" | grep '/ode/' || true)
  if [ -n "$ode" ]; then
    echo "$h: reaches ODE's headers:"; echo "$ode" | sed 's/^/  /'; fail=1
  else
    echo "$h: $(echo "$files" | grep -c 'footsim/') footsim headers, none of ODE's"
  fi
done
[ $n -ge 30 ] || { echo "only $n public headers found"; fail=1; }
[ $fail -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $fail
