/// @file
/// Test helper (not installed): drives the rig's DBC codec from stdin so that an independent
/// implementation (python3-canmatrix, see codec_vs_canmatrix.py) can check it.
///
///   rig-dbc-codec-check FILE.dbc
///   stdin:  decode MESSAGE HEXBYTES         -> stdout: SIGNAL=VALUE ... (present signals only)
///           encode MESSAGE SIGNAL=VALUE ...  -> stdout: HEXBYTES (signals not given are 0)
/// Values are physical, printed with 17 significant digits.

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "io/can/dbc/dbc_parser.h"
#include "io/can/dbc/signal_codec.h"

namespace dbc = rig::io::can::dbc;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: rig-dbc-codec-check FILE.dbc\n";
    return 2;
  }
  const dbc::Database db = dbc::load_dbc(argv[1]);
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream in(line);
    std::string command, name;
    in >> command >> name;
    const dbc::MessageDef* m = db.find_message(name);
    if (m == nullptr) {
      std::cout << "error unknown message " << name << std::endl;
      continue;
    }
    const dbc::MessageCodec codec(*m);
    std::vector<double> physical(m->signals.size(), 0.0);
    if (command == "decode") {
      std::string hex;
      in >> hex;
      std::vector<std::uint8_t> bytes;
      for (std::size_t i = 0; i + 1 < hex.size(); i += 2) {
        bytes.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
      }
      bool present[64 * 8] = {};
      if (!codec.decode(bytes.data(), bytes.size(), physical,
                        std::span<bool>(present, physical.size()))) {
        std::cout << "error short frame" << std::endl;
        continue;
      }
      for (std::size_t i = 0; i < m->signals.size(); ++i) {
        if (!present[i]) continue;
        char value[64];
        std::snprintf(value, sizeof value, "%.17g", physical[i]);
        std::cout << m->signals[i].name << '=' << value << ' ';
      }
      std::cout << std::endl;
    } else if (command == "encode") {
      std::string pair;
      while (in >> pair) {
        const auto eq = pair.find('=');
        const std::string signal = pair.substr(0, eq);
        for (std::size_t i = 0; i < m->signals.size(); ++i) {
          if (m->signals[i].name == signal)
            physical[i] = std::strtod(pair.c_str() + eq + 1, nullptr);
        }
      }
      std::vector<std::uint8_t> bytes(m->length_bytes);
      codec.encode(physical, bytes.data());
      for (std::uint8_t b : bytes) {
        char h[3];
        std::snprintf(h, sizeof h, "%02x", b);
        std::cout << h;
      }
      std::cout << std::endl;
    } else {
      std::cout << "error unknown command " << command << std::endl;
    }
  }
  return 0;
}
