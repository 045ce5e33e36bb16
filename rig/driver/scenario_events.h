#pragma once
/// @file
/// Scenario events: a maneuver that reacts to conditions (docs/scenarios.md).
///
///   [[event]]
///   name = "step"                                   # optional, default "event<i>" (from 0)
///   when = { signal = "vehicle_speed_mps", op = ">=", value = 16.67, for_s = 0.0 }
///   do = { set = { steering_wheel_angle_cmd_rad = 0.5 }, ramp_s = 0.1 }
///
///   [[event]]
///   when = { signal = "vehicle_speed_mps", op = "<", value = 0.1, for_s = 2.0 }
///   do = "stop"
///
/// `when` compares any catalogue signal (input or output, docs/signals.md) with a value; the
/// event fires once, at the first cycle at which the comparison has held for `for_s` seconds
/// of simulated time without a break (an invalid signal does not hold; the first cycle has no
/// previous step, so the model's outputs hold from the first step on). `do.set` then takes over
/// the named inputs: each ramps linearly from its value at the firing (0 if nobody gave it) to
/// its target over `ramp_s` (0: a step; whole-number inputs such as the gear always step) and
/// is held there for the rest of the run, whatever the driver writes (a later event may take
/// an input over again). `do = "stop"` ends the run after that cycle (stop reason "event",
/// exit 0).
///
/// Where and why: at the driver stage of the loop thread, right after the driver
/// (Executive::cycle), on the outputs of the previous step (the state the driver also sees).
/// Only there can a set act on the very next step - deterministically, offline and in real
/// time alike - and only there does it win over the driver's value; the dispatcher sees the
/// snapshots later, by a varying number of cycles, and cannot write inputs. So the stage is
/// built at load time (signals bound to catalogue entries, fixed arrays per event and per input
/// slot) and update() only compares, counts and writes: no allocation, no lookup, no lock.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "io/config/strict_table.h"
#include "io/cycle_io.h"
#include "io/signals/catalogue.h"
#include "model/signals.h"

namespace rig::driver {

enum class CompareOp : std::uint8_t {
  kLess,
  kLessEqual,
  kGreater,
  kGreaterEqual,
  kEqual,
  kNotEqual
};

/// "<", "<=", ">", ">=", "==", "!=".
const char* compare_op_name(CompareOp op);

struct EventCondition {
  std::string signal_name;  ///< as written
  io::signals::Binding signal;
  CompareOp op = CompareOp::kGreaterEqual;
  double value = 0.0;
  double for_s = 0.0;  ///< how long it must hold, >= 0
};

/// One input an event sets: its slot (model/signals.h) and target.
struct EventSet {
  std::string name;  ///< as written
  std::string at;    ///< its file:line
  std::size_t slot = 0;
  double value = 0.0;
};

struct EventSpec {
  std::string name;
  EventCondition when;
  bool stop = false;          ///< do = "stop"
  std::vector<EventSet> set;  ///< do.set
  double ramp_s = 0.0;        ///< do.ramp_s
  std::string location;       ///< file:line of the [[event]]
};

/// The most [[event]] tables a configuration may have.
inline constexpr std::size_t kMaxEvents = 64;

/// Reads the top level's `[[event]]` array (none: empty). Throws ConfigError(file:line) with
/// the key's name on an unknown key or signal, an output in `set`, a value outside its input's
/// range, an unknown `op`, a negative `for_s`/`ramp_s`, `do` neither "stop" nor a table with
/// `set`, or a duplicate name.
std::vector<EventSpec> read_events(io::config::StrictTable& top,
                                   const io::signals::Catalogue& catalogue);

/// The inputs the events set (they count as written by the driver: rig/routing.h).
io::InputSet event_inputs(const std::vector<EventSpec>& events);

/// Whether `v op value` holds (NaN never holds).
bool compare(CompareOp op, double v, double value) noexcept;

/// The running events of one run.
class EventStage {
 public:
  /// Allocates everything here.
  explicit EventStage(std::vector<EventSpec> events);

  /// The driver stage after the driver: `previous` is the last step's view (its outputs) and
  /// the inputs so far; fires the events whose condition held long enough, then writes every
  /// input an event holds. Returns true if an event asked to stop. No allocation.
  bool update(double sim_time_s, const io::signals::CycleView& previous,
              model::Signals& signals) noexcept;

  /// The events fired by the last update() (indices into specs()).
  [[nodiscard]] std::span<const std::size_t> fired() const noexcept {
    return {fired_.data(), fired_count_};
  }
  [[nodiscard]] const std::vector<EventSpec>& specs() const noexcept { return specs_; }
  /// When event i fired [s], NaN if it has not.
  [[nodiscard]] double fired_at_s(std::size_t i) const noexcept { return fired_at_s_[i]; }

 private:
  /// An input held by an event: a ramp from `from` at t0 to `to` at t0 + ramp_s.
  struct Hold {
    bool active = false;
    double from = 0.0, to = 0.0, t0_s = 0.0, ramp_s = 0.0;
  };
  void fire(std::size_t i, double t_s, const model::Signals& signals) noexcept;

  std::vector<EventSpec> specs_;
  std::vector<double> held_since_s_;  ///< NaN while the condition does not hold
  std::vector<double> fired_at_s_;    ///< NaN until fired
  std::vector<std::size_t> fired_;    ///< capacity: every event
  std::size_t fired_count_ = 0;
  std::array<Hold, model::kSlotCount> holds_{};
};

}  // namespace rig::driver
