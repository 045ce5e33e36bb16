#!/usr/bin/env bash
# The log -> CSV -> figures chain: rig-lcm-feed writes an LCM log, rig-log2csv turns it into CSVs,
# `scripts/plot log` must print the PNG paths (the feed has 2 units: combination.png too; road.png:
# the road under the wheels) and write non-empty PNG files.
# Usage: lcm_plot_test.sh BINDIR
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bin="$1"
work="$(mktemp -d /tmp/rig-lcm-plot.XXXXXX)"
trap 'rm -rf "$work"' EXIT
"$bin/rig-lcm-feed" --url none --fast --duration 1 --log "$work/run.lcm" >/dev/null
"$bin/rig-log2csv" "$work/run.lcm" "$work/csv" >/dev/null
RIG_BUILD_DIR="$bin/.." "$here/../../../scripts/plot" log "$work/csv" "$work/png" | tee "$work/printed"
for name in trajectory speed_accel steering wheel_slips dynamics wheel_loads combination road \
  lateness misses; do
  grep -qx "$work/png/$name.png" "$work/printed" || { echo "FAIL: $name.png not printed"; exit 1; }
  [[ "$(head -c 8 "$work/png/$name.png" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]] ||
    { echo "FAIL: $name.png is not a PNG"; exit 1; }
done
echo PASS
