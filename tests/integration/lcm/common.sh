# Sourced by the LCM integration tests. Gives each test its own network namespace (unique name,
# so that parallel ctest runs do not collide) and a work directory, both removed on any exit.
#   rig_lcm_setup MODE   MODE: route (lo up + 224.0.0.0/4 via lo), noroute (lo up), lodown
#   rig_ns CMD...        runs CMD inside the namespace
set -euo pipefail

RIG_NETNS=""
RIG_WORK=""
RIG_PIDS=()

rig_lcm_cleanup() {
  local pid
  for pid in "${RIG_PIDS[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "${RIG_PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [[ -n "$RIG_NETNS" ]]; then ip netns del "$RIG_NETNS" 2>/dev/null || true; fi
  if [[ -n "$RIG_WORK" && -z "${RIG_KEEP_WORK:-}" ]]; then rm -rf "$RIG_WORK"; fi
}

rig_lcm_setup() {
  local mode="$1"
  if [[ "$(id -u)" != 0 ]] || ! command -v ip >/dev/null; then
    echo "SKIP: needs root and iproute2 for a network namespace"
    exit 77
  fi
  for tool in lcm-logger lcm-logplayer; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool missing (Debian liblcm-bin)"; exit 77; }
  done
  trap rig_lcm_cleanup EXIT
  RIG_WORK="$(mktemp -d /tmp/rig-lcm-test.XXXXXX)"
  RIG_NETNS="rig-lcm-$$-$RANDOM"
  if ! ip netns add "$RIG_NETNS"; then
    RIG_NETNS=""
    echo "SKIP: cannot create a network namespace"
    exit 77
  fi
  # Room for LCM's receive buffer (it asks for 2 MB), so that a subscriber that is descheduled
  # for a while on a loaded machine does not lose datagrams.
  ip netns exec "$RIG_NETNS" sysctl -q -w net.core.rmem_max=8388608 2>/dev/null || true
  case "$mode" in
    route)
      ip -n "$RIG_NETNS" link set lo up
      ip -n "$RIG_NETNS" route add 224.0.0.0/4 dev lo ;;
    noroute) ip -n "$RIG_NETNS" link set lo up ;;
    lodown) ;;
    *) echo "rig_lcm_setup: bad mode $mode" >&2; exit 2 ;;
  esac
}

rig_ns() { ip netns exec "$RIG_NETNS" "$@"; }

# Starts lcm-logger into FILE in the namespace and waits until it has created the file.
rig_start_logger() {
  local file="$1"
  ip netns exec "$RIG_NETNS" lcm-logger -q -f "$file" &  # not via rig_ns: $! must be the logger
  RIG_PIDS+=($!)
  for _ in $(seq 100); do [[ -f "$file" ]] && break; sleep 0.05; done
  [[ -f "$file" ]] || { echo "FAIL: lcm-logger did not start"; exit 1; }
  sleep 0.3  # let it subscribe
}

# Stops the loggers (SIGINT flushes their files).
rig_stop_loggers() {
  sleep 0.5  # the last datagrams
  local pid
  for pid in "${RIG_PIDS[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "${RIG_PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  RIG_PIDS=()
}
