#!/bin/sh
# The Python package's tests (python/tests, pytest) over the build's libfootsim, with the
# interpreter CMake found (Debian's /usr/bin/python3). Exit 77 (ctest: skipped) when that python
# lacks pytest or numpy (Debian: python3-pytest, python3-numpy).
# usage: python.sh PYTHON|sanitized path/to/libfootsim.so   (run from the source folder)
py=$1
lib=$2
if [ "$py" = sanitized ]; then
  echo "skipped: a libfootsim built with the sanitizers cannot be loaded into an uninstrumented python"
  exit 77
fi
if [ -z "$py" ] || ! "$py" -c 'import pytest, numpy' 2>/dev/null; then
  echo "skipped: '${py:-no python3 found}' lacks pytest or numpy (apt-get install python3-pytest python3-numpy)"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
FOOTSIM_LIB=$lib PYTHONPATH=$PWD/python MPLCONFIGDIR=$tmp PYTHONDONTWRITEBYTECODE=1 \
  "$py" -m pytest -q -p no:cacheprovider python/tests
rc=$?
[ $rc -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $rc
