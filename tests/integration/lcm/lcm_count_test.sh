#!/usr/bin/env bash
# Count check: lcm-logger (Debian's independent subscriber) records a 2 s publishing run; RIG_STATE
# must hold rate x duration messages within 1 %, and every decoded field must equal what the
# synthetic dispatcher published. Usage: lcm_count_test.sh BINDIR
here="$(cd "$(dirname "$0")" && pwd)"
bin="$1"
source "$here/common.sh"
rig_lcm_setup route

rig_start_logger "$RIG_WORK/subscriber.lcm"
rig_ns "$bin/rig-lcm-feed" --duration 2 | tee "$RIG_WORK/feed.out"
rig_stop_loggers
grep -q "fed 2000 snapshots" "$RIG_WORK/feed.out"

"$bin/rig-log2csv" "$RIG_WORK/subscriber.lcm" "$RIG_WORK/csv"
/usr/bin/python3 "$here/check_csv.py" "$RIG_WORK/csv" --state 2000 --signals 200 --status 20 \
  --tolerance 0.01
