#!/bin/sh
# Installs footsim's Debian build dependencies when any is missing.
# Run as root on Debian 12; otherwise it prints the apt-get line to run.
set -eu
# python3 and sqlite3: the tests read every CSV file footsim writes with them (cli_csv)
pkgs="cmake make gcc pkg-config libode-dev libccd-dev libinih-dev libcjson-dev libosmesa6-dev libpng-dev libgsl-dev libnlopt-dev libxml2-dev gnuplot-nox python3 sqlite3"
# optional: MuJoCo, for the test that loads the MJCF export (export_mujoco skips without it); Debian's
# Python with numpy, pytest and matplotlib, for the Python package, its tests and examples (the ctest
# test python skips without pytest or numpy); pandas, for the test that reads the CSV files with
# pandas.read_csv (cli_csv_pandas skips without it)
optional="libmujoco-dev python3-numpy python3-pytest python3-matplotlib python3-pandas"
missing=""
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
updated=""
for p in $optional; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" && continue
  if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
    # a fresh machine has no package lists yet: read them once before the first install
    [ -n "$updated" ] || { DEBIAN_FRONTEND=noninteractive apt-get update -q >/dev/null 2>&1; updated=1; }
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q "$p" >/dev/null 2>&1 ||
      echo "footsim: optional package $p not installed (its test will be skipped)" >&2
  else
    echo "footsim: optional package $p is not installed (its test will be skipped)" >&2
  fi
done
[ -z "$missing" ] && exit 0
echo "footsim: installing missing packages:$missing" >&2
if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
  echo "footsim: cannot install as this user; run as root:" >&2
  echo "  apt-get update && apt-get install -y$missing" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
[ -n "$updated" ] || apt-get update -q >/dev/null
apt-get install -y -q $missing >/dev/null
