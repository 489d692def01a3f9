#!/usr/bin/env bash
# The ./swarmnet bootstrap builds only the `swarmnet` target (the command and its plugins) for a
# run and every other command, and everything for `./swarmnet test`; it configures a build
# directory again when the packages installed change. cmake, ctest, dpkg-query and apt-get are
# stand-ins on PATH that record their arguments, so nothing is built or installed.
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
# Every package installed but those listed in $tmp/absent, as `dpkg-query -W -f=...` prints them.
cat >"$tmp/fake/dpkg-query" <<EOF
#!/bin/sh
for arg; do
  case \$arg in
    -*) ;;
    *) grep -qx "\$arg" "$tmp/absent" 2>/dev/null || echo "\$arg install ok installed" ;;
  esac
done
EOF
printf '#!/bin/sh\necho "apt-get $*" >>"%s/calls"\nexit 1\n' "$tmp" >"$tmp/fake/apt-get"
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

# Configured again only when the packages installed changed since the last configuration (here
# libns3-dev, which a run does not install: CMake must see that it is gone, or newly there).
bootstrap run
bootstrap run
grep -q "^cmake -S" "$tmp/calls" && { cat "$tmp/calls" >&2; fail "configured again, nothing changed"; }
echo libns3-dev >"$tmp/absent"
bootstrap run
grep -q "^cmake -S $src -B $tmp/build\$" "$tmp/calls" ||
  { cat "$tmp/calls" >&2; fail "not configured again after a package was removed"; }
grep -q "^apt-get" "$tmp/calls" && fail "./swarmnet run installed libns3-dev, which it does not need"
: >"$tmp/absent"

bootstrap test
grep -q "^cmake --build $tmp/build --parallel 1\$" "$tmp/calls" ||
  { cat "$tmp/calls" >&2; fail "./swarmnet test did not build everything"; }
grep -q "^ctest --test-dir $tmp/build" "$tmp/calls" || fail "./swarmnet test did not run ctest"
echo "ok"
