/// @file
/// rig-log2csv LOG OUTDIR: one CSV per channel of an LCM log file. The rig's types are decoded
/// into named columns (arrays flattened: wheel0_spin_radps, unit1_x_m, input_valid_<name>);
/// channels of any other type get the columns timestamp_us,channel,size_bytes. Exit status: 0,
/// 2 usage, 1 an unreadable log, 3 a CSV that could not be written completely (a full disk).

#include <cstdio>
#include <exception>

#include "rig/log2csv/log_to_csv.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr,
                 "usage: rig-log2csv LOG OUTDIR\n"
                 "  Writes OUTDIR/CHANNEL.csv for every channel of the LCM log LOG.\n");
    return 2;
  }
  try {
    const auto summary = rig::log2csv::convert_lcm_log(argv[1], argv[2]);
    for (const auto& [channel, c] : summary.channels) {
      std::printf("%s: %llu rows (%s)", c.file.c_str(), static_cast<unsigned long long>(c.rows),
                  c.type_name.c_str());
      if (c.undecodable > 0) {
        std::printf(", %llu events did not decode and were skipped",
                    static_cast<unsigned long long>(c.undecodable));
      }
      std::printf("\n");
    }
    if (summary.events == 0) std::fprintf(stderr, "rig-log2csv: %s holds no events\n", argv[1]);
    return 0;
  } catch (const rig::log2csv::WriteError& e) {
    std::fprintf(stderr, "rig-log2csv: error: %s\n", e.what());
    return 3;  // as the rig: an output lost data
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rig-log2csv: %s\n", e.what());
    return 1;
  }
}
