/// @file
/// libFuzzer target over the DBC parser and, for every database that parses, the signal codec:
/// decode a frame made of the input's bytes and encode it back. Must never crash, leak, hit UB
/// or grow memory without bound (run by scripts/fuzz-dbc under ASan + UBSan).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "io/can/dbc/dbc_parser.h"
#include "io/can/dbc/signal_codec.h"

namespace dbc = rig::io::can::dbc;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  dbc::Database db;
  try {
    db = dbc::parse_dbc(text, "fuzz.dbc");
  } catch (const rig::io::config::ConfigError&) {
    return 0;
  }
  std::array<std::uint8_t, 64> frame{};
  for (std::size_t i = 0; i < frame.size(); ++i) {
    frame[i] = size > 0 ? data[(i * 7) % size] : 0;
  }
  for (const dbc::MessageDef& m : db.messages) {
    const dbc::MessageCodec codec(m);
    std::vector<double> physical(m.signals.size());
    std::unique_ptr<bool[]> present(new bool[m.signals.size() + 1]);
    if (codec.decode(frame.data(), frame.size(), physical,
                     std::span<bool>(present.get(), m.signals.size()))) {
      std::array<std::uint8_t, 64> out{};
      codec.encode(physical, out.data());
    }
  }
  return 0;
}
