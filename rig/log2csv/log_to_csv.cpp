#include "rig/log2csv/log_to_csv.h"

#include <lcm/eventlog.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <system_error>

#include "rig/log2csv/channel_csv.h"

namespace rig::log2csv {

namespace {

/// A channel's CSV: rows go to a temporary body file until the header is known (it is sized by
/// the first message that decodes), then the header and body are joined at the end.
struct ChannelOutput {
  std::unique_ptr<ChannelCsv> decoder;
  std::filesystem::path path;
  std::ofstream body;
  ChannelSummary summary;
};

struct EventlogCloser {
  void operator()(lcm_eventlog_t* log) const { lcm_eventlog_destroy(log); }
};
struct EventCloser {
  void operator()(lcm_eventlog_event_t* event) const { lcm_eventlog_free_event(event); }
};

/// Header + body into the CSV, every write checked (a full disk shows at a flush or the close).
void join_csv(ChannelOutput& out) {
  const std::filesystem::path body_path = out.path.string() + ".body";
  errno = 0;
  out.body.close();
  const bool body_ok = !out.body.fail();
  const auto failed = [&](const std::string& what) {
    const std::string why = errno != 0 ? std::strerror(errno) : "write failed";
    std::error_code ec;
    std::filesystem::remove(body_path, ec);
    return WriteError("writing " + what + " failed (" + why + "): the CSV is incomplete");
  };
  if (!body_ok) throw failed(body_path.string());
  std::ofstream csv(out.path, std::ios::binary | std::ios::trunc);
  std::ifstream body(body_path, std::ios::binary);
  if (!csv) throw failed(out.path.string());
  csv << out.decoder->header() << '\n';
  if (out.summary.rows > 0) csv << body.rdbuf();
  errno = 0;
  csv.close();
  if (csv.fail()) throw failed(out.path.string());
  std::filesystem::remove(body_path);
}

}  // namespace

std::string csv_file_name(const std::string& channel) {
  std::string name = channel;
  for (char& c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_' && c != '-' && c != '.') {
      c = '_';
    }
  }
  if (name.empty() || name == "." || name == "..") name = "_" + name;
  return name + ".csv";
}

ConversionSummary convert_lcm_log(const std::filesystem::path& log_file,
                                  const std::filesystem::path& out_dir) {
  if (!std::filesystem::is_regular_file(log_file)) {
    throw std::runtime_error(log_file.string() + ": no such LCM log file");
  }
  std::unique_ptr<lcm_eventlog_t, EventlogCloser> log(lcm_eventlog_create(log_file.c_str(), "r"));
  if (!log) {
    throw std::runtime_error(log_file.string() + ": cannot open (" + std::strerror(errno) + ")");
  }
  std::filesystem::create_directories(out_dir);

  ConversionSummary summary;
  std::map<std::string, ChannelOutput> outputs;
  CsvLine line;
  for (;;) {
    std::unique_ptr<lcm_eventlog_event_t, EventCloser> raw(lcm_eventlog_read_next_event(log.get()));
    if (!raw) break;  // end of file (or a truncated last event)
    ++summary.events;
    const std::string channel(raw->channel, static_cast<std::size_t>(raw->channellen));
    Event event{raw->timestamp, nullptr, static_cast<const std::uint8_t*>(raw->data),
                static_cast<std::size_t>(raw->datalen)};
    auto [it, inserted] = outputs.try_emplace(channel);
    ChannelOutput& out = it->second;
    event.channel = &it->first;
    if (inserted) {
      out.decoder = make_channel_csv(event);
      out.path = out_dir / csv_file_name(channel);
      out.summary.file = out.path.string();
      out.summary.type_name = out.decoder->type_name();
      out.body.open(out.path.string() + ".body", std::ios::binary | std::ios::trunc);
      if (!out.body) throw WriteError("cannot write " + out.path.string() + ".body");
    }
    line.reset();
    if (!out.decoder->row(event, line)) {
      ++out.summary.undecodable;
      continue;
    }
    out.body << line.text() << '\n';
    ++out.summary.rows;
  }

  for (auto& [channel, out] : outputs) {
    join_csv(out);
    summary.channels.emplace(channel, out.summary);
  }
  return summary;
}

}  // namespace rig::log2csv
