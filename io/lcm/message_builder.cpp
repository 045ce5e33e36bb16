#include "io/lcm/message_builder.h"

#include <algorithm>
#include <string>

#include "io/lcm/vehicle_state_fields.h"

namespace rig::io::lcm {

namespace {

template <typename T>
void resize(std::vector<T>& v, std::size_t n) {
  if (v.size() != n) v.resize(n);
}

std::int32_t clamp_count(std::int32_t count, int max) { return std::clamp(count, 0, max); }

using Fields = VehicleStateFields;

/// Sizes the arrays of `Rows` to `n` elements (no allocation once they have that size).
template <const auto& Rows>
void size_arrays(rig::vehicle_state_t& msg, std::size_t n) {
  for (const auto& row : Rows) resize(msg.*row.lcm, n);
}

/// Element `i` of every array of `Rows`, from `from` (a unit, wheel or joint report).
template <const auto& Rows, typename From>
void set_elements(rig::vehicle_state_t& msg, std::size_t i, const From& from) {
  for_each_row<Rows>([&](const auto& row) { (msg.*row.lcm)[i] = row.source(from); });
}

template <const auto& Rows>
void set_scalars(rig::vehicle_state_t& msg, const model::ModelReport& r) {
  for_each_row<Rows>([&](const auto& row) { msg.*row.lcm = row.source(r); });
}

void fill_frame(const CycleTiming& t, rig::vehicle_state_t& msg) {
  msg.sim_time_s = t.sim_time_s;
  msg.monotonic_ns = t.wake_ns;
  msg.cycle = static_cast<std::int64_t>(t.cycle);
  msg.lateness_ns = t.lateness_ns;
  msg.compute_ns = t.compute_ns;
  msg.deadline_miss = t.deadline_miss ? 1 : 0;
}

std::size_t wheel_count(const model::UnitReport& unit) {
  return static_cast<std::size_t>(clamp_count(unit.wheel_count, model::kMaxWheelsPerUnit));
}

}  // namespace

void fill_vehicle_state(const Snapshot& snapshot, rig::vehicle_state_t& msg) {
  const auto& r = snapshot.report;
  fill_frame(snapshot.timing, msg);

  const std::int32_t units = clamp_count(r.unit_count, model::kMaxUnits);
  const auto nu = static_cast<std::size_t>(units);
  msg.num_units = units;
  size_arrays<Fields::kUnit>(msg, nu);
  std::size_t wheels = 0;
  for (std::size_t u = 0; u < nu; ++u) {
    set_elements<Fields::kUnit>(msg, u, r.units[u]);
    wheels += wheel_count(r.units[u]);
  }

  msg.num_wheels = static_cast<std::int32_t>(wheels);
  resize(msg.wheel_unit, wheels);
  size_arrays<Fields::kWheel>(msg, wheels);
  size_arrays<Fields::kWheelFlag>(msg, wheels);
  std::size_t k = 0;
  for (std::size_t u = 0; u < nu; ++u) {
    const auto& unit = r.units[u];
    for (std::size_t w = 0; w < wheel_count(unit); ++w, ++k) {
      msg.wheel_unit[k] = static_cast<std::int8_t>(u);
      set_elements<Fields::kWheel>(msg, k, unit.wheels[w]);
      set_elements<Fields::kWheelFlag>(msg, k, unit.wheels[w]);
    }
  }

  set_scalars<Fields::kVehicle>(msg, r);
  set_scalars<Fields::kVehicleInt>(msg, r);

  const std::int32_t joints = clamp_count(r.joint_count, model::kMaxJoints);
  const auto nj = static_cast<std::size_t>(joints);
  msg.num_joints = joints;
  size_arrays<Fields::kJoint>(msg, nj);
  for (std::size_t j = 0; j < nj; ++j) set_elements<Fields::kJoint>(msg, j, r.joints[j]);

  const std::int32_t diffs = clamp_count(r.differential_count, model::kMaxDifferentials);
  const auto nd = static_cast<std::size_t>(diffs);
  msg.num_diffs = diffs;
  size_arrays<Fields::kDiff>(msg, nd);
  size_arrays<Fields::kDiffFlag>(msg, nd);
  for (std::size_t j = 0; j < nd; ++j) {
    set_elements<Fields::kDiff>(msg, j, r.differentials[j]);
    set_elements<Fields::kDiffFlag>(msg, j, r.differentials[j]);
  }
  const std::int32_t bodies = clamp_count(r.body_count, model::kMaxFreeBodiesPerUnit);
  const auto nb = static_cast<std::size_t>(bodies);
  msg.num_bodies = bodies;
  size_arrays<Fields::kBody>(msg, nb);
  size_arrays<Fields::kBodyFlag>(msg, nb);
  for (std::size_t b = 0; b < nb; ++b) {
    set_elements<Fields::kBody>(msg, b, r.bodies[b]);
    set_elements<Fields::kBodyFlag>(msg, b, r.bodies[b]);
  }
}

namespace {

/// The source of an input as signals_t says it.
std::int8_t source_code(model::SignalSource source) {
  switch (source) {
    case model::SignalSource::kModel:
      return rig::signals_t::SOURCE_MODEL;
    case model::SignalSource::kDriver:
      return rig::signals_t::SOURCE_DRIVER;
    case model::SignalSource::kCan:
      return rig::signals_t::SOURCE_CAN;
  }
  return rig::signals_t::SOURCE_MODEL;
}

/// [lcm] signals: each chosen catalogue entry through its binding.
void fill_chosen_signals(const Snapshot& snapshot, std::span<const LcmSignal> chosen,
                         rig::signals_t& msg) {
  const std::size_t n = chosen.size();
  if (msg.name.size() != n) {
    msg.num_signals = static_cast<std::int32_t>(n);
    msg.name.assign(n, std::string());
    msg.unit.assign(n, std::string());
    msg.is_input.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      msg.name[i] = chosen[i].name;
      msg.unit[i] = chosen[i].unit;
      msg.is_input[i] = chosen[i].binding.is_input() ? 1 : 0;
    }
    msg.value.assign(n, 0.0);
    msg.valid.assign(n, 0);
    msg.source.assign(n, 0);
  }
  const signals::CycleView cycle{snapshot.signals, snapshot.report};
  for (std::size_t i = 0; i < n; ++i) {
    const signals::Binding& b = chosen[i].binding;
    msg.value[i] = b.value(cycle);
    msg.valid[i] = b.valid(cycle) ? 1 : 0;
    msg.source[i] =
        b.is_input() ? source_code(snapshot.signals.source[b.slot]) : rig::signals_t::SOURCE_MODEL;
  }
}

}  // namespace

void fill_signals(const Snapshot& snapshot, std::span<const LcmSignal> chosen,
                  rig::signals_t& msg) {
  msg.sim_time_s = snapshot.timing.sim_time_s;
  msg.monotonic_ns = snapshot.timing.wake_ns;
  msg.cycle = static_cast<std::int64_t>(snapshot.timing.cycle);
  if (!chosen.empty()) {
    fill_chosen_signals(snapshot, chosen, msg);
    return;
  }
  constexpr auto n = model::kSignalCount;
  if (msg.name.size() != n) {
    // Names, units and the input flag are constant: set them once.
    msg.num_signals = static_cast<std::int32_t>(n);
    msg.name.assign(n, std::string());
    msg.unit.assign(n, std::string());
    msg.is_input.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      msg.name[i] = std::string(model::kSignalTable[i].name);
      msg.unit[i] = std::string(model::kSignalTable[i].unit);
      msg.is_input[i] = model::kSignalTable[i].is_input ? 1 : 0;
    }
    msg.value.assign(n, 0.0);
    msg.valid.assign(n, 0);
    msg.source.assign(n, 0);
  }
  const auto& s = snapshot.signals;
  for (std::size_t i = 0; i < n; ++i) {
    msg.value[i] = s.value[i];
    msg.valid[i] = s.valid[i] ? 1 : 0;
    msg.source[i] = source_code(s.source[i]);
  }
}

void fill_status(const Snapshot& snapshot, const RunInfo& info, const StatusTotals& totals,
                 const TimingPercentiles& window, rig::rig_status_t& msg) {
  constexpr auto n_inputs = model::index(model::kFirstOutput);
  if (msg.input_name.size() != n_inputs) {
    msg.num_inputs = static_cast<std::int32_t>(n_inputs);
    msg.input_name.assign(n_inputs, std::string());
    for (std::size_t i = 0; i < n_inputs; ++i) {
      msg.input_name[i] = std::string(model::kSignalTable[i].name);
    }
    msg.input_valid.assign(n_inputs, 0);
  }
  if (msg.overrun_policy != info.policy) msg.overrun_policy = info.policy;

  const auto& t = snapshot.timing;
  msg.sim_time_s = t.sim_time_s;
  msg.monotonic_ns = t.wake_ns;
  msg.cycles = totals.cycles;
  msg.deadline_misses = totals.deadline_misses;
  msg.consecutive_misses = static_cast<std::int32_t>(t.consecutive_misses);
  msg.max_consecutive_misses = totals.max_consecutive_misses;
  msg.snapshots_dropped = totals.snapshots_dropped;

  msg.window_cycles = window.cycles;
  msg.window_misses = window.misses;
  msg.lateness_p50_ns = window.lateness_p50_ns;
  msg.lateness_p99_ns = window.lateness_p99_ns;
  msg.lateness_p999_ns = window.lateness_p999_ns;
  msg.lateness_max_ns = window.lateness_max_ns;
  msg.compute_p50_ns = window.compute_p50_ns;
  msg.compute_p99_ns = window.compute_p99_ns;
  msg.compute_max_ns = window.compute_max_ns;

  msg.period_s = info.period_s;
  msg.offline = info.offline ? 1 : 0;
  msg.sched_fifo = info.sched_fifo ? 1 : 0;
  msg.priority = info.priority;
  msg.memory_locked = info.memory_locked ? 1 : 0;
  msg.cpu = info.cpu;

  const auto& c = snapshot.can;
  switch (c.bus_state) {
    case BusState::kDisabled:
      msg.bus_state = rig::rig_status_t::BUS_DISABLED;
      break;
    case BusState::kUp:
      msg.bus_state = rig::rig_status_t::BUS_UP;
      break;
    case BusState::kErrorPassive:
      msg.bus_state = rig::rig_status_t::BUS_ERROR_PASSIVE;
      break;
    case BusState::kBusOff:
      msg.bus_state = rig::rig_status_t::BUS_OFF;
      break;
    case BusState::kDown:
      msg.bus_state = rig::rig_status_t::BUS_DOWN;
      break;
  }
  const auto i64 = [](std::uint64_t v) { return static_cast<std::int64_t>(v); };
  msg.can_frames_received = i64(c.frames_received);
  msg.can_frames_sent = i64(c.frames_sent);
  msg.can_timeouts = i64(c.timeouts);
  msg.can_checksum_failures = i64(c.checksum_failures);
  msg.can_counter_failures = i64(c.counter_failures);
  msg.can_bad_frames = i64(c.bad_frames);
  msg.can_unknown_frames = i64(c.unknown_frames);
  msg.can_error_frames = i64(c.error_frames);
  msg.can_out_of_range = i64(c.out_of_range);
  msg.can_send_no_buffer = i64(c.send_no_buffer);
  msg.can_send_dropped = i64(c.send_dropped);
  msg.can_reopens = i64(c.reopens);
  msg.can_rx_overflows = i64(c.rx_overflows);

  for (std::size_t i = 0; i < n_inputs; ++i) {
    msg.input_valid[i] = snapshot.signals.valid[i] ? 1 : 0;
  }
}

}  // namespace rig::io::lcm
