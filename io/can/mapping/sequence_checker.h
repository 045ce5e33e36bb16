#pragma once
/// @file
/// The receive-side check of an alive (sequence) counter: one rule for every counter the rig
/// receives (the CAN mapping's `counter`, and the E2E profiles that carry one).
///
/// Each received counter value is compared with the previous one: the step (value - last) mod
/// modulus must lie in 1..max_delta. A step of 0 (a repeated or frozen counter) or beyond
/// max_delta (frames skipped, or a jump) latches the checker: every frame is rejected until the
/// counter has moved properly `good_steps_to_unlatch` times in a row. After restart() (the
/// message came back after a timeout) any step but 0 is taken without complaint, as a sender
/// may resume anywhere; the same value as before the silence is still a repeat. So a frozen
/// sender stays rejected however long it lasts and however slowly it sends, and a latch
/// survives timeouts (only reset() clears it). The checker always resynchronises on the value
/// received, so a single jump costs the jump and the steps needed to unlatch, nothing more.
///
/// Plain data, allocation-free, noexcept: it runs on the RT thread.

#include <cstdint>

namespace rig::io::can::mapping {

struct SequenceParams {
  std::uint32_t modulus = 16;               ///< counter values 0 .. modulus - 1 (max + 1)
  std::uint32_t max_delta = 1;              ///< accepted step per frame: 1 .. max_delta
  std::uint32_t good_steps_to_unlatch = 1;  ///< proper steps in a row that end a latch (>= 1)
};

/// What check() made of one counter value.
enum class SequenceResult : std::uint8_t {
  kOk,        ///< a proper step (or the first value of a sequence): accept the frame
  kInvalid,   ///< value >= modulus: rejected, latched
  kRepeated,  ///< the same value again (frozen counter): rejected, latched
  kSkipped,   ///< the counter jumped beyond max_delta (lost frames or a jump): rejected, latched
  kLatched,   ///< a proper step, but still latched by an earlier failure: rejected
};

[[nodiscard]] constexpr bool accepted(SequenceResult r) noexcept {
  return r == SequenceResult::kOk;
}

class SequenceChecker {
 public:
  SequenceChecker() = default;
  explicit SequenceChecker(const SequenceParams& params) noexcept : params_(params) {}

  /// Checks the next received counter value and resynchronises on it.
  SequenceResult check(std::uint32_t value) noexcept;

  /// A new sequence (the message timed out; call once per timeout): the next value may jump
  /// anywhere but must differ from the last one; a latch stays until proper steps end it.
  void restart() noexcept { resume_ = have_last_; }
  /// Forgets everything, the latch too (start of a run).
  void reset() noexcept {
    have_last_ = false;
    resume_ = false;
    latched_ = false;
    good_steps_ = 0;
  }

  [[nodiscard]] bool latched() const noexcept { return latched_; }
  [[nodiscard]] const SequenceParams& params() const noexcept { return params_; }

 private:
  SequenceResult fail(SequenceResult why) noexcept;

  SequenceParams params_{};
  std::uint32_t last_ = 0;
  std::uint32_t good_steps_ = 0;  // proper steps since the latch
  bool have_last_ = false;
  bool resume_ = false;  // restarted: the next non-zero step is no skip
  bool latched_ = false;
};

}  // namespace rig::io::can::mapping
