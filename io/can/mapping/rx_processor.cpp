#include "io/can/mapping/rx_processor.h"

#include <cmath>

namespace rig::io::can::mapping {

RxProcessor::RxProcessor(const CanConfig& config) {
  messages_.reserve(config.mapping.rx.size());
  for (const MessageBinding& b : config.mapping.rx) {
    const dbc::MessageDef& def = config.database.messages[b.dbc_message];
    Message m{.id = def.id,
              .extended = def.extended,
              .length_bytes = def.length_bytes,
              .codec = dbc::MessageCodec(def),
              .bound = {},
              .counter = b.counter,
              .checksum = b.checksum,
              .timeout_ns = b.timeout_ns};
    for (const SignalBinding& sb : b.signals) {
      const dbc::SignalDef& s = def.signals[sb.dbc_signal];
      m.bound.push_back(Bound{.codec_signal = sb.dbc_signal,
                              .model = *sb.model,
                              .scale = sb.scale,
                              .offset = sb.offset,
                              .fallback = sb.fallback,
                              .minimum = s.minimum,
                              .maximum = s.maximum,
                              .clamp = s.has_range()});
    }
    messages_.push_back(std::move(m));
  }
}

void RxProcessor::apply_fallback(Message& message, model::Signals& signals) {
  for (const Bound& b : message.bound) signals.set(b.model, b.fallback, false);
}

void RxProcessor::reset(std::int64_t now_ns, model::Signals& signals) {
  for (Message& m : messages_) {
    apply_fallback(m, signals);
    m.last_ns = now_ns;
    m.timed_out = true;
    m.timeout_counted = false;
    m.have_counter = false;
  }
}

RxResult RxProcessor::on_frame(std::uint32_t id, bool extended, const std::uint8_t* data,
                               std::size_t len, std::int64_t time_ns, model::Signals& signals,
                               io::IoCounters& counters) {
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
  if (len != m.length_bytes || data == nullptr) {
    ++counters.bad_frames;
    return RxResult::kBadLength;
  }
  if (m.checksum) {
    const ChecksumSpec& c = *m.checksum;
    // Gather the covered bytes in their configured order (at most 64, on the stack).
    std::uint8_t covered[64];
    std::size_t n = 0;
    for (std::uint8_t b : c.bytes) covered[n++] = data[b];
    const std::uint8_t expected =
        c.type == ChecksumType::kXor ? xor8(covered, n) : crc8_sae_j1850(covered, n);
    if (m.codec.signal(c.dbc_signal).extract_raw(data) != expected) {
      ++counters.checksum_failures;
      return RxResult::kChecksumFailure;
    }
  }
  if (m.counter) {
    const CounterSpec& c = *m.counter;
    const std::uint64_t value = m.codec.signal(c.dbc_signal).extract_raw(data);
    bool ok = value < c.modulus;
    if (ok && m.have_counter) {
      const std::uint64_t step = (value + c.modulus - m.last_counter) % c.modulus;
      ok = step >= 1 && step <= c.max_step;
    }
    // Resynchronise on the received value either way: a single jump costs one frame, a frozen
    // counter fails every frame.
    if (value < c.modulus) {
      m.last_counter = static_cast<std::uint32_t>(value);
      m.have_counter = true;
    }
    if (!ok) {
      ++counters.counter_failures;
      return RxResult::kCounterFailure;
    }
  }
  const int mux = m.codec.multiplexor_index();
  const std::uint64_t mux_raw =
      mux >= 0 ? m.codec.signal(static_cast<std::size_t>(mux)).extract_raw(data) : 0;
  for (const Bound& b : m.bound) {
    if (!m.codec.present(b.codec_signal, mux_raw)) continue;
    double physical = m.codec.signal(b.codec_signal).decode(data);
    if (!std::isfinite(physical)) {
      ++counters.out_of_range;  // NaN/inf from a float signal: keep the previous value
      continue;
    }
    if (b.clamp && (physical < b.minimum || physical > b.maximum)) {
      physical = physical < b.minimum ? b.minimum : b.maximum;
      ++counters.out_of_range;
    }
    signals.set(b.model, physical * b.scale + b.offset, true);
  }
  m.last_ns = time_ns;
  m.timed_out = false;
  m.timeout_counted = false;
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
    m.timed_out = true;
    m.have_counter = false;  // the next frame starts a new counter sequence
    apply_fallback(m, signals);
  }
}

}  // namespace rig::io::can::mapping
