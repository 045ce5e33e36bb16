#!/usr/bin/env bash
# Two rigs on one network (issue 18): each in its own network namespace, joined by veth pairs to
# a bridge in a third ("hub"), publishing LCM with ttl=1 and distinct channel prefixes (RIGA_,
# RIGB_: --set lcm.channel_prefix); the subscribers in the hub, lcm-logger and the dashboard
# (rig-scope --prefix RIGA_ --prefix RIGB_), see both. Checks: both rigs' RIG_STATE and RIG_STATUS channels reach the hub, each
# rig's RIG_STATE count within 5 % of its summary's cycles (two real-time rigs on this 2-core VM
# share it with the logger); and a rig publishing with ttl=0 stays in its namespace (none of its
# messages reach the hub): it is ttl=1 that crosses. The dashboard's full frame, read from its
# /events stream in the hub after the runs, holds both rigs' latest RIG_STATE and RIG_STATUS,
# each rig's position one of the last positions the logger recorded from that rig.
#
# The namespaces route 224.0.0.0/4 via their veth (the hub via the bridge), not lo: multicast
# must leave the namespace. The bridge's IGMP snooping is off (no querier here).
# Usage: multi_rig_test.sh BINDIR SOURCE_DIR
set -euo pipefail
bin="$1"
src="$2"
rig="$bin/rig"
if [[ "$(id -u)" != 0 ]] || ! command -v ip >/dev/null; then
  echo "SKIP: needs root and iproute2 for network namespaces"
  exit 77
fi
command -v lcm-logger >/dev/null || { echo "SKIP: lcm-logger missing (Debian liblcm-bin)"; exit 77; }

tag="$$-$RANDOM"
hub="rig-mr-hub-$tag" a="rig-mr-a-$tag" b="rig-mr-b-$tag"
work="$(mktemp -d /tmp/rig-multi-rig.XXXXXX)"
pids=()
cleanup() {
  local pid
  for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  for ns in "$a" "$b" "$hub"; do ip netns del "$ns" 2>/dev/null || true; done
  [[ -n "${RIG_KEEP_WORK:-}" ]] || rm -rf "$work"
}
trap cleanup EXIT
for ns in "$hub" "$a" "$b"; do
  ip netns add "$ns" || { echo "SKIP: cannot create a network namespace"; exit 77; }
  ip -n "$ns" link set lo up
  ip netns exec "$ns" sysctl -q -w net.core.rmem_max=8388608 2>/dev/null || true
done
# the bridge and a veth pair per rig (created inside the namespaces: no name clashes with a
# parallel run of this test)
ip -n "$hub" link add br0 type bridge mcast_snooping 0
ip -n "$hub" addr add 10.77.0.254/24 dev br0
ip -n "$hub" link set br0 up
n=1
for ns in "$a" "$b"; do
  ip -n "$hub" link add "p$n" type veth peer name eth0 netns "$ns"
  ip -n "$hub" link set "p$n" master br0
  ip -n "$hub" link set "p$n" up
  ip -n "$ns" addr add "10.77.0.$n/24" dev eth0
  ip -n "$ns" link set eth0 up
  ip -n "$ns" route add 224.0.0.0/4 dev eth0
  n=$((n + 1))
done
ip -n "$hub" route add 224.0.0.0/4 dev br0

config="$src/config/maneuvers/double-lane-change-iso3888.toml"
url="udpm://239.255.76.67:7667?ttl=1"
ip netns exec "$hub" lcm-logger -q -f "$work/hub.lcm" &
pids+=($!)
for _ in $(seq 100); do [[ -f "$work/hub.lcm" ]] && break; sleep 0.05; done
ip netns exec "$hub" "$bin/rig-scope" --lcm-url "$url" --prefix RIGA_ --prefix RIGB_ --port 0 \
  >"$work/scope.log" 2>&1 &
pids+=($!)
for _ in $(seq 200); do grep -q "http://" "$work/scope.log" 2>/dev/null && break; sleep 0.05; done
scope_url="$(grep -o 'http://127.0.0.1:[0-9]*/' "$work/scope.log" | head -1)"
[[ -n "$scope_url" ]] || { echo "FAIL: rig-scope did not start"; cat "$work/scope.log"; exit 1; }
sleep 0.3  # subscribed
ip netns exec "$a" "$rig" run --config "$config" --duration 3 --lcm-url "$url" \
  --set lcm.channel_prefix=RIGA_ --summary-json "$work/a.json" >"$work/a.log" 2>&1 &
rig_a=$!
ip netns exec "$b" "$rig" run --config "$config" --duration 3 --lcm-url "$url" \
  --set lcm.channel_prefix=RIGB_ --summary-json "$work/b.json" >"$work/b.log" 2>&1 &
rig_b=$!
wait "$rig_a" || { echo "FAIL: rig A exit $?"; cat "$work/a.log"; exit 1; }
wait "$rig_b" || { echo "FAIL: rig B exit $?"; cat "$work/b.log"; exit 1; }
grep -q "ttl=1" "$work/a.log" || { echo "FAIL: no ttl warning from rig A"; exit 1; }
# a third run with ttl=0 in namespace A: its channel must not reach the hub
ip netns exec "$a" "$rig" run --config "$config" --duration 1 \
  --lcm-url "udpm://239.255.76.67:7667?ttl=0" --set lcm.channel_prefix=RIGZ_ >/dev/null 2>&1
sleep 0.5
# the dashboard's full frame: the first event of a new /events stream
ip netns exec "$hub" /usr/bin/python3 - "${scope_url}events" "$work/scope.json" <<'PY'
import sys, urllib.request
with urllib.request.urlopen(sys.argv[1], timeout=10) as stream:
    for line in stream:
        if line.startswith(b"data: "):
            open(sys.argv[2], "wb").write(line[6:])
            break
PY
for pid in "${pids[@]}"; do kill -INT "$pid"; done
for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
pids=()
"$bin/rig-log2csv" "$work/hub.lcm" "$work/csv" >/dev/null
/usr/bin/python3 - "$work" <<'PY'
import csv, json, os, sys
work = sys.argv[1]
files = sorted(os.listdir(f"{work}/csv"))
print("hub received:", " ".join(files))
def rows(name):
    path = f"{work}/csv/{name}.csv"
    return sum(1 for _ in open(path)) - 1 if os.path.exists(path) else 0
ok = True
for rig in ("a", "b"):
    prefix = f"RIG{rig.upper()}_"
    cycles = json.load(open(f"{work}/{rig}.json"))["cycles"]
    state, status = rows(prefix + "RIG_STATE"), rows(prefix + "RIG_STATUS")
    print(f"rig {rig}: {cycles} cycles, hub got {state} {prefix}RIG_STATE, {status} {prefix}RIG_STATUS")
    ok &= status > 0 and abs(state - cycles) <= 0.05 * cycles
    # the dashboard's latest values of this rig are values this rig sent near the end (udpm
    # may drop a datagram at either subscriber: the last 100 messages, matched exactly)
    frame = json.load(open(f"{work}/scope.json"))["rigs"].get(prefix, {}).get("latest", {})
    with open(f"{work}/csv/{prefix}RIG_STATE.csv") as f:
        tail = list(csv.DictReader(f))[-100:]
    x = frame.get(f"{prefix}RIG_STATE.unit0_x_m")
    matched = x is not None and any(float(r["unit0_x_m"]) == x for r in tail)
    statuses = sum(1 for k in frame if k.startswith(prefix + "RIG_STATUS."))
    print(f"rig {rig}: the dashboard shows x = {x} m (logger's last {tail[-1]['unit0_x_m']}),"
          f" {statuses} {prefix}RIG_STATUS values")
    ok &= matched and statuses > 0
z = [f for f in files if f.startswith("RIGZ_")]
print("ttl=0 rig's channels at the hub:", z or "none")
ok &= not z
sys.exit(0 if ok else 1)
PY
echo PASS
