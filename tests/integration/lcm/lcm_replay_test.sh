#!/usr/bin/env bash
# Replay: the rig's own LCM log (the log writer, run offline) is replayed by lcm-logplayer into
# lcm-logger; every message must arrive, byte for byte the same fields. Usage: lcm_replay_test.sh BINDIR
here="$(cd "$(dirname "$0")" && pwd)"
bin="$1"
source "$here/common.sh"
rig_lcm_setup route

"$bin/rig-lcm-feed" --url none --fast --duration 2 --log "$RIG_WORK/own.lcm"
rig_start_logger "$RIG_WORK/replayed.lcm"
rig_ns lcm-logplayer "$RIG_WORK/own.lcm"
rig_stop_loggers

"$bin/rig-log2csv" "$RIG_WORK/own.lcm" "$RIG_WORK/own"
"$bin/rig-log2csv" "$RIG_WORK/replayed.lcm" "$RIG_WORK/replayed"
/usr/bin/python3 "$here/check_csv.py" "$RIG_WORK/own" --state 2000 --signals 200 --status 20 \
  --tolerance 0
/usr/bin/python3 "$here/check_csv.py" "$RIG_WORK/replayed" --state 2000 --signals 200 \
  --status 20 --tolerance 0 --same-as "$RIG_WORK/own"
