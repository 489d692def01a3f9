#!/usr/bin/env bash
# `./swarmnet packages COMMAND` lists what the bootstrap would install for COMMAND: a run needs
# neither the viewer's browser and encoder, nor Slurm, ns-2, ns-3 or clang; the test suite needs
# all of them. cmake, dpkg-query, apt-get and sudo are stand-ins on PATH that fail and record
# their calls, so that listing is shown to install, query and build nothing.
#
#   bootstrap_packages_test.sh SOURCE_DIR
set -euo pipefail

src=$1
tmp=$(mktemp -d "${TMPDIR:-/tmp}/swarmnet-packages.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

mkdir -p "$tmp/fake"
for tool in cmake ctest dpkg-query apt-get sudo; do
  printf '#!/bin/sh\necho "%s $*" >>"%s/calls"\nexit 1\n' "$tool" "$tmp" >"$tmp/fake/$tool"
done
chmod +x "$tmp"/fake/*
: >"$tmp/calls"

packages() {
  PATH=$tmp/fake:$PATH SWARMNET_BUILD_DIR=$tmp/build "$src/swarmnet" packages "$@" ||
    fail "./swarmnet packages $* exited with $?"
}

packages run >"$tmp/run"
packages test >"$tmp/test"
[[ -s $tmp/run ]] || fail "./swarmnet packages run printed nothing"

optional=(chromium ffmpeg slurm-wlm munge ns2 libns3-dev clang-14)
for pkg in "${optional[@]}"; do
  grep -qxF "$pkg" "$tmp/run" && fail "the run group has $pkg: $(paste -sd ' ' "$tmp/run")"
  grep -qxF "$pkg" "$tmp/test" || fail "the test group lacks $pkg: $(paste -sd ' ' "$tmp/test")"
done
# The test suite builds what a run builds: its packages include the run group's.
while read -r pkg; do
  grep -qxF "$pkg" "$tmp/test" || fail "the test group lacks $pkg, which a run needs"
done <"$tmp/run"
for pkg in g++ cmake libyaml-cpp-dev libode-dev; do
  grep -qxF "$pkg" "$tmp/run" || fail "the run group lacks $pkg"
done

[[ -d $tmp/build ]] && fail "./swarmnet packages made a build directory"
[[ -s $tmp/calls ]] && { cat "$tmp/calls" >&2; fail "./swarmnet packages ran a tool"; }
echo "ok: run $(wc -l <"$tmp/run") packages, test $(wc -l <"$tmp/test")"
