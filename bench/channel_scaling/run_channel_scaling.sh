#!/bin/sh
# Runs the channel-scaling benchmark (docs/performance.md, "Channel scaling") and writes
# channel_scaling.json in the current directory. Usage: run_channel_scaling.sh [BUILD_DIR] [ARGS]
set -eu
build=${1:-build}
[ $# -gt 0 ] && shift
cmake --build "$build" --target channel_scaling
"$build/bin/channel_scaling" --out channel_scaling.json "$@"
cat channel_scaling.json
