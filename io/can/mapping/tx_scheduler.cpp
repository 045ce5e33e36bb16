#include "io/can/mapping/tx_scheduler.h"

#include <algorithm>
#include <cmath>

#include "io/can/mapping/protection.h"

namespace rig::io::can::mapping {

TxScheduler::TxScheduler(const CanConfig& config) {
  messages_.reserve(config.mapping.tx.size());
  for (const MessageBinding& b : config.mapping.tx) {
    const dbc::MessageDef& def = config.database.messages[b.dbc_message];
    Message m{.id = def.id,
              .extended = def.extended,
              .length_bytes = def.length_bytes,
              .fd = def.is_fd(),
              .codec = dbc::MessageCodec(def),
              .physical = {},
              .bound = b.signals,
              .minimum = {},
              .maximum = {},
              .clamp = {},
              .name = def.name,
              .names = {},
              .reports = {},
              .last_out_of_range = {},
              .mux_pages = {},
              .next_page = 0,
              .counter = b.counter,
              .checksum = b.checksum,
              .e2e = b.e2e,
              .counter_value = 0,
              .period_ns = b.period_ns,
              .next_due_ns = 0};
    // Unmapped signals go out at their start value (GenSigStartValue is raw).
    for (std::size_t i = 0; i < def.signals.size(); ++i) {
      m.physical.push_back(m.codec.signal(i).raw_to_physical(m.codec.signal(i).physical_to_raw(
          def.signals[i].start_value_raw * def.signals[i].factor + def.signals[i].offset)));
      if (def.signals[i].mux_role == dbc::MuxRole::kMultiplexed &&
          std::find(m.mux_pages.begin(), m.mux_pages.end(), def.signals[i].mux_value) ==
              m.mux_pages.end()) {
        m.mux_pages.push_back(def.signals[i].mux_value);
      }
    }
    std::sort(m.mux_pages.begin(), m.mux_pages.end());
    for (const SignalBinding& sb : b.signals) {
      const dbc::SignalDef& s = def.signals[sb.dbc_signal];
      m.minimum.push_back(s.minimum);
      m.maximum.push_back(s.maximum);
      m.clamp.push_back(s.has_range());
      m.names.push_back(s.name);
      m.reports.emplace_back();
      m.last_out_of_range.push_back(0.0);
    }
    messages_.push_back(std::move(m));
  }
}

void TxScheduler::start(std::int64_t loop_start_ns) {
  loop_start_ns_ = loop_start_ns;
  for (Message& m : messages_) m.next_due_ns = loop_start_ns;
}

void TxScheduler::encode(std::size_t i, const signals::CycleView& cycle, TxFrame& frame,
                         io::IoCounters& counters) {
  Message& m = messages_[i];
  for (std::size_t k = 0; k < m.bound.size(); ++k) {
    const SignalBinding& b = m.bound[k];
    double physical = b.constant;
    if (b.model) physical = (b.model->value(cycle) - b.offset) / b.scale;
    if (m.clamp[k] && !(physical >= m.minimum[k] && physical <= m.maximum[k])) {
      // NaN goes to the minimum too: never send an undefined value.
      m.last_out_of_range[k] = physical;
      m.reports[k].count();
      physical = physical > m.maximum[k] ? m.maximum[k] : m.minimum[k];
      ++counters.out_of_range;
    }
    m.physical[b.dbc_signal] = physical;
  }
  const int mux = m.codec.multiplexor_index();
  if (mux >= 0 && !m.mux_pages.empty()) {
    m.physical[static_cast<std::size_t>(mux)] =
        m.codec.signal(static_cast<std::size_t>(mux)).raw_to_physical(m.mux_pages[m.next_page]);
    m.next_page = (m.next_page + 1) % m.mux_pages.size();
  }
  frame.id = m.id;
  frame.extended = m.extended;
  frame.fd = m.fd;
  frame.len = static_cast<std::uint8_t>(m.length_bytes);
  m.codec.encode(m.physical, frame.data.data());
  for (const SignalBinding& b : m.bound) {  // after a vehicle fault, say: its SNA value
    if (b.model && b.invalid_raw && !b.model->valid(cycle))
      m.codec.signal(b.dbc_signal).insert_raw(*b.invalid_raw, frame.data.data());
  }
  if (m.counter) {
    m.codec.signal(m.counter->dbc_signal).insert_raw(m.counter_value, frame.data.data());
    m.counter_value = (m.counter_value + 1) % m.counter->modulus;
  }
  if (m.checksum) write_checksum(*m.checksum, m.codec, frame.data.data());
  if (m.e2e) {  // the counter advances per send, over the profile's counter range
    e2e::protect(*m.e2e, frame.data.data(), m.counter_value);
    m.counter_value = (m.counter_value + 1) % e2e::counter_modulus(m.e2e->profile);
  }
}

std::size_t TxScheduler::due_frames(std::int64_t now_ns, const signals::CycleView& cycle,
                                    std::span<TxFrame> out, io::IoCounters& counters) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < messages_.size() && n < out.size(); ++i) {
    Message& m = messages_[i];
    if (now_ns < m.next_due_ns || m.period_ns <= 0) continue;
    encode(i, cycle, out[n++], counters);
    // Next slot on the grid loop_start + k * period strictly after now (no burst after overrun).
    const std::int64_t k = (now_ns - loop_start_ns_) / m.period_ns + 1;
    m.next_due_ns = loop_start_ns_ + k * m.period_ns;
  }
  return n;
}

}  // namespace rig::io::can::mapping
