#include "io/can/mapping/rx_processor.h"

#include <cmath>
#include <limits>

#include "io/can/mapping/protection.h"

namespace rig::io::can::mapping {
namespace {

void set(model::Signals& signals, std::size_t slot, double value, bool valid) noexcept {
  signals.value[slot] = value;
  signals.valid[slot] = valid;
}

}  // namespace

RxProcessor::RxProcessor(const CanConfig& config) {
  messages_.reserve(config.mapping.rx.size());
  for (const MessageBinding& b : config.mapping.rx) {
    const dbc::MessageDef& def = config.database.messages[b.dbc_message];
    Message m{.id = def.id,
              .extended = def.extended,
              .length_bytes = def.length_bytes,
              .fd = def.is_fd(),
              .name = def.name,
              .codec = dbc::MessageCodec(def),
              .bound = {},
              .counter = b.counter,
              .checksum = b.checksum,
              .e2e = b.e2e,
              .timeout_ns = b.timeout_ns};
    if (b.counter) {
      m.sequence =
          SequenceChecker(SequenceParams{.modulus = b.counter->modulus,
                                         .max_delta = b.counter->max_step,
                                         .good_steps_to_unlatch = b.counter->unlatch_steps});
    }
    if (b.e2e) {  // the profile's counter goes through the same checker
      m.sequence = SequenceChecker(SequenceParams{.modulus = e2e::counter_modulus(b.e2e->profile),
                                                  .max_delta = b.e2e->max_delta_counter,
                                                  .good_steps_to_unlatch = 1});
    }
    for (const SignalBinding& sb : b.signals) {
      const dbc::SignalDef& s = def.signals[sb.dbc_signal];
      m.bound.push_back(Bound{.codec_signal = sb.dbc_signal,
                              .slot = sb.model->slot,
                              .scale = sb.scale,
                              .offset = sb.offset,
                              .fallback = sb.fallback,
                              .minimum = s.minimum,
                              .maximum = s.maximum,
                              .clamp = s.has_range(),
                              .name = s.name});
    }
    messages_.push_back(std::move(m));
  }
}

void RxProcessor::apply_fallback(Message& message, model::Signals& signals) {
  for (const Bound& b : message.bound) set(signals, b.slot, b.fallback, false);
}

void RxProcessor::reset(std::int64_t now_ns, model::Signals& signals) {
  for (Message& m : messages_) {
    apply_fallback(m, signals);
    m.last_ns = now_ns;
    m.timed_out = true;
    m.timeout_counted = false;
    m.sequence.reset();
  }
}

void RxProcessor::decode(Message& m, const std::uint8_t* data, model::Signals& signals,
                         io::IoCounters& counters) noexcept {
  const int mux = m.codec.multiplexor_index();
  const std::uint64_t mux_raw =
      mux >= 0 ? m.codec.signal(static_cast<std::size_t>(mux)).extract_raw(data) : 0;
  for (Bound& b : m.bound) {
    if (!m.codec.present(b.codec_signal, mux_raw)) continue;
    double physical = m.codec.signal(b.codec_signal).decode(data);
    if (!std::isfinite(physical)) {
      ++counters.out_of_range;  // NaN/inf from a float signal: keep the previous value
      b.last_out_of_range = physical;
      b.reports.count();
      continue;
    }
    if (b.clamp && (physical < b.minimum || physical > b.maximum)) {
      b.last_out_of_range = physical;
      b.reports.count();
      physical = physical < b.minimum ? b.minimum : b.maximum;
      ++counters.out_of_range;
    }
    set(signals, b.slot, physical * b.scale + b.offset, true);
  }
}

RxResult RxProcessor::on_frame(std::uint32_t id, bool extended, FrameFormat format,
                               const std::uint8_t* data, std::size_t len, std::int64_t time_ns,
                               model::Signals& signals, io::IoCounters& counters) {
  Message* found = nullptr;
  for (Message& m : messages_) {
    if (m.id == id && m.extended == extended) {
      found = &m;
      break;
    }
  }
  if (found == nullptr) {
    ++counters.unknown_frames;
    return RxResult::kUnknownId;
  }
  Message& m = *found;
  if (format == FrameFormat::kRemote) {
    ++counters.bad_frames;
    return RxResult::kRemoteFrame;
  }
  if ((format == FrameFormat::kFd) != m.fd) {
    ++counters.bad_frames;
    return RxResult::kWrongFormat;
  }
  if (len != m.length_bytes || data == nullptr) {
    ++counters.bad_frames;
    return RxResult::kBadLength;
  }
  if (m.checksum && !checksum_ok(*m.checksum, m.codec, data)) {
    ++counters.checksum_failures;
    return RxResult::kChecksumFailure;
  }
  if (m.e2e) return check_e2e(m, data, time_ns, signals, counters);
  if (m.counter) {
    const std::uint64_t raw = m.codec.signal(m.counter->dbc_signal).extract_raw(data);
    const auto value = raw > std::numeric_limits<std::uint32_t>::max()
                           ? std::numeric_limits<std::uint32_t>::max()
                           : static_cast<std::uint32_t>(raw);
    if (!accepted(m.sequence.check(value))) {
      ++counters.counter_failures;
      return RxResult::kCounterFailure;
    }
  }
  accept(m, data, time_ns, signals, counters);
  return RxResult::kAccepted;
}

void RxProcessor::accept(Message& m, const std::uint8_t* data, std::int64_t time_ns,
                         model::Signals& signals, io::IoCounters& counters) noexcept {
  decode(m, data, signals, counters);
  m.last_ns = time_ns;
  m.timed_out = false;
  m.timeout_counted = false;
}

RxResult RxProcessor::check_e2e(Message& m, const std::uint8_t* data, std::int64_t time_ns,
                                model::Signals& signals, io::IoCounters& counters) noexcept {
  // A wrong Data ID is a wrong CRC (or, explicit in P01 NIBBLE and P04, a wrong field).
  const e2e::CheckResult r = e2e::check(*m.e2e, data);
  if (!r.crc_ok) {
    ++counters.checksum_failures;
    return RxResult::kChecksumFailure;
  }
  if (!accepted(m.sequence.check(r.counter))) {
    ++counters.counter_failures;
    return RxResult::kCounterFailure;
  }
  accept(m, data, time_ns, signals, counters);
  return RxResult::kAccepted;
}

void RxProcessor::check_timeouts(std::int64_t now_ns, model::Signals& signals,
                                 io::IoCounters& counters) {
  for (Message& m : messages_) {
    if (now_ns - m.last_ns < m.timeout_ns) continue;
    if (!m.timeout_counted) {
      ++counters.timeouts;
      m.timeout_counted = true;
    }
    if (!m.timed_out) m.sequence.restart();  // once per timeout: a new sequence, a latch stays
    m.timed_out = true;
    apply_fallback(m, signals);
  }
}

}  // namespace rig::io::can::mapping
