#!/usr/bin/env bash
# The ./swarmnet bootstrap builds only the `swarmnet` target (the command and its plugins) for a
# run and every other command, and everything for `./swarmnet test`. cmake, ctest and dpkg-query
# are stand-ins on PATH that record their arguments, so nothing is built or installed.
#
#   bootstrap_targets_test.sh SOURCE_DIR
set -euo pipefail

src=$1
tmp=$(mktemp -d "${TMPDIR:-/tmp}/swarmnet-bootstrap.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

mkdir -p "$tmp/fake" "$tmp/build/bin"
for tool in cmake ctest; do
  printf '#!/bin/sh\necho "%s $*" >>"%s/calls"\n' "$tool" "$tmp" >"$tmp/fake/$tool"
done
printf '#!/bin/sh\nprintf "install ok installed"\n' >"$tmp/fake/dpkg-query"
printf '#!/bin/sh\necho "swarmnet $*" >>"%s/calls"\n' "$tmp" >"$tmp/build/bin/swarmnet"
chmod +x "$tmp"/fake/* "$tmp/build/bin/swarmnet"
touch "$tmp/build/CMakeCache.txt"  # configured already: only the build step is under test

bootstrap() {
  : >"$tmp/calls"
  PATH=$tmp/fake:$PATH SWARMNET_BUILD_DIR=$tmp/build SWARMNET_JOBS=1 "$src/swarmnet" "$@" \
    >"$tmp/out" 2>&1 || { cat "$tmp/out" >&2; fail "./swarmnet $*"; }
}

for command in run validate plugins help; do
  bootstrap "$command"
  grep -q "^cmake --build $tmp/build --parallel 1 --target swarmnet\$" "$tmp/calls" ||
    { cat "$tmp/calls" >&2; fail "./swarmnet $command built more than the swarmnet target"; }
  grep -q "^swarmnet $command" "$tmp/calls" || fail "./swarmnet $command did not run the command"
done

bootstrap test
grep -q "^cmake --build $tmp/build --parallel 1\$" "$tmp/calls" ||
  { cat "$tmp/calls" >&2; fail "./swarmnet test did not build everything"; }
grep -q "^ctest --test-dir $tmp/build" "$tmp/calls" || fail "./swarmnet test did not run ctest"
echo "ok"
