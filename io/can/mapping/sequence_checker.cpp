#include "io/can/mapping/sequence_checker.h"

namespace rig::io::can::mapping {

SequenceResult SequenceChecker::fail(SequenceResult why) noexcept {
  latched_ = true;
  good_steps_ = 0;
  return why;
}

SequenceResult SequenceChecker::check(std::uint32_t value) noexcept {
  if (value >= params_.modulus) {
    have_last_ = false;  // nothing to step from
    resume_ = false;
    return fail(SequenceResult::kInvalid);
  }
  const bool had_last = have_last_;
  const bool resumed = resume_;
  const std::uint32_t step = (value + params_.modulus - last_) % params_.modulus;
  last_ = value;
  have_last_ = true;
  resume_ = false;
  if (!had_last) {
    // First value of a sequence: nothing to compare with; a latch needs proper steps to end.
    return latched_ ? SequenceResult::kLatched : SequenceResult::kOk;
  }
  if (step == 0) return fail(SequenceResult::kRepeated);
  if (step > params_.max_delta) {
    if (!resumed) return fail(SequenceResult::kSkipped);
    good_steps_ = 0;  // a jump after a timeout: no failure, but no proper step either
    return latched_ ? SequenceResult::kLatched : SequenceResult::kOk;
  }
  if (!latched_) return SequenceResult::kOk;
  if (++good_steps_ < params_.good_steps_to_unlatch) return SequenceResult::kLatched;
  latched_ = false;
  good_steps_ = 0;
  return SequenceResult::kOk;
}

}  // namespace rig::io::can::mapping
