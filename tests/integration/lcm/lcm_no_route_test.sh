#!/usr/bin/env bash
# No multicast route: in a bare namespace (lo up without the 224.0.0.0/4 route, then lo down) the
# publisher prints ONE clear message naming the fix, the run goes on to the end, the log file is
# still written, and the exit status is 0. Then the route is removed in the middle of a run. Usage: lcm_no_route_test.sh BINDIR
here="$(cd "$(dirname "$0")" && pwd)"
bin="$1"
source "$here/common.sh"

check_mode() {
  local mode="$1"
  rig_lcm_setup "$mode"
  local rc=0
  rig_ns "$bin/rig-lcm-feed" --duration 0.3 --log "$RIG_WORK/log.lcm" \
    >"$RIG_WORK/out" 2>"$RIG_WORK/err" || rc=$?
  echo "[$mode] exit $rc; stderr:"; cat "$RIG_WORK/err"
  [[ $rc == 0 ]] || { echo "FAIL: exit status $rc"; exit 1; }
  grep -q "fed 300 snapshots" "$RIG_WORK/out" || { echo "FAIL: the run did not go on"; exit 1; }
  [[ $(wc -l <"$RIG_WORK/err") == 1 ]] || { echo "FAIL: not exactly one message"; exit 1; }
  grep -q "ip route add 224.0.0.0/4 dev lo" "$RIG_WORK/err" || { echo "FAIL: no advice"; exit 1; }
  "$bin/rig-log2csv" "$RIG_WORK/log.lcm" "$RIG_WORK/csv" >/dev/null
  [[ $(($(wc -l <"$RIG_WORK/csv/RIG_STATE.csv") - 1)) == 300 ]] || { echo "FAIL: log"; exit 1; }
  rig_lcm_cleanup
  RIG_NETNS="" RIG_WORK=""
}

check_mode noroute
check_mode lodown

# The route vanishes in the middle of a run: publishing fails, one message, the run goes on.
rig_lcm_setup route
rc=0
rig_ns "$bin/rig-lcm-feed" --duration 1.5 >"$RIG_WORK/out" 2>"$RIG_WORK/err" &
feed=$!
sleep 0.7
ip -n "$RIG_NETNS" route del 224.0.0.0/4 dev lo
wait "$feed" || rc=$?
echo "[route removed mid-run] exit $rc; stderr:"; cat "$RIG_WORK/err"
[[ $rc == 0 ]] || { echo "FAIL: exit status $rc"; exit 1; }
grep -q "fed 1500 snapshots" "$RIG_WORK/out" || { echo "FAIL: the run did not go on"; exit 1; }
[[ $(wc -l <"$RIG_WORK/err") == 1 ]] || { echo "FAIL: not exactly one message"; exit 1; }
grep -q "ip route add 224.0.0.0/4 dev lo" "$RIG_WORK/err" || { echo "FAIL: no advice"; exit 1; }
echo "PASS"
