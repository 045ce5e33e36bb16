#include "io/config/crg_file.h"

#include <cmath>
#include <string>

#include "io/config/config_error.h"
#include "io/config/crg_header.h"
#include "io/config/crg_payload.h"
#include "io/config/input_file.h"

namespace rig::io::config {
namespace {

using crg::ChannelKind;
using model::road::CrgData;
namespace fs = std::filesystem;

constexpr int kMaxReferenceDepth = 8;
constexpr double kMaxHeight_m = 1e5;  // beyond any road on earth, absolute altitudes included
constexpr double kMaxSlope = 10;      // slope and banking (84 degrees)

/// Which payload column holds what.
struct Layout {
  int phi = -1, x = -1, y = -1, banking = -1, slope = -1;
  std::vector<int> z;  ///< the long sections, right to left
};

Layout layout_of(const crg::Definition& def, const std::string& file) {
  Layout l;
  for (std::size_t c = 0; c < def.channels.size(); ++c) {
    const crg::Channel& ch = def.channels[c];
    int* slot = ch.kind == ChannelKind::kPhi       ? &l.phi
                : ch.kind == ChannelKind::kX       ? &l.x
                : ch.kind == ChannelKind::kY       ? &l.y
                : ch.kind == ChannelKind::kBanking ? &l.banking
                : ch.kind == ChannelKind::kSlope   ? &l.slope
                                                   : nullptr;
    if (slot == nullptr) {
      l.z.push_back(static_cast<int>(c));
    } else if (*slot >= 0) {
      throw crg::error_at(file, ch.line, "a reference line channel defined twice");
    } else {
      *slot = static_cast<int>(c);
    }
  }
  if ((l.x >= 0) != (l.y >= 0))
    throw crg::error_at(file, def.line, "reference line x and y channels: give both or neither");
  if (l.z.size() < 2)
    throw crg::error_at(file, def.line,
                        "$KD_Definition: " + std::to_string(l.z.size()) +
                            " long sections; a grid needs at least 2");
  return l;
}

/// v of numbered long sections from LONG_SECTION_V_RIGHT/LEFT/INCREMENT (only the increment:
/// centred on the reference line, as OpenCRG's minimalist files are).
std::vector<double> numbered_v(std::size_t n, const crg::RoadCrgKeys& k, int line,
                               const std::string& file) {
  const double count = static_cast<double>(n - 1);
  double inc = k.v_increment.value_or(0.0);
  if (!k.v_increment) {
    if (!k.v_right || !k.v_left)
      throw crg::error_at(file, line,
                          "'long section N' channels need LONG_SECTION_V_INCREMENT (or "
                          "LONG_SECTION_V_RIGHT and _LEFT) in $ROAD_CRG");
    inc = (*k.v_left - *k.v_right) / count;
  }
  if (!(inc > 0)) throw crg::error_at(file, k.v_line, "LONG_SECTION_V_INCREMENT must be > 0");
  double right = k.v_right ? *k.v_right : (k.v_left ? *k.v_left - count * inc : -count * inc / 2);
  if (k.v_right && k.v_left && std::abs(*k.v_right + count * inc - *k.v_left) > 1e-6 * inc)
    throw crg::error_at(file, k.v_line,
                        "LONG_SECTION_V_RIGHT/LEFT/INCREMENT give " +
                            std::to_string((*k.v_left - *k.v_right) / inc + 1) +
                            " long sections, $KD_Definition defines " + std::to_string(n));
  std::vector<double> v(n);
  for (std::size_t j = 0; j < n; ++j) v[j] = right + static_cast<double>(j) * inc;
  return v;
}

std::vector<double> long_section_v(const crg::Definition& def, const Layout& l,
                                   const crg::RoadCrgKeys& k, const std::string& file) {
  const crg::Channel& first = def.channels[static_cast<std::size_t>(l.z.front())];
  std::vector<double> v;
  for (std::size_t j = 0; j < l.z.size(); ++j) {
    const crg::Channel& ch = def.channels[static_cast<std::size_t>(l.z[j])];
    if (ch.v_m.has_value() != first.v_m.has_value())
      throw crg::error_at(file, ch.line,
                          "mixes 'long section N' and 'long section at v = X' channels");
    if (!ch.v_m && ch.number != static_cast<int>(j) + 1)
      throw crg::error_at(file, ch.line,
                          "long section " + std::to_string(ch.number) + " where long section " +
                              std::to_string(j + 1) + " is due");
    if (ch.v_m && j > 0 && !(*ch.v_m > v.back()))
      throw crg::error_at(file, ch.line, "long sections must go from right to left (v rising)");
    if (ch.v_m) v.push_back(*ch.v_m);
  }
  if (!first.v_m) return numbered_v(l.z.size(), k, first.line, file);
  const auto off = [&](const std::optional<double>& given, double have) {
    return given && std::abs(*given - have) > 1e-6;
  };
  if (off(k.v_right, v.front()) || off(k.v_left, v.back()))
    throw crg::error_at(file, k.v_line,
                        "LONG_SECTION_V_RIGHT/LEFT differ from the first/last 'long section at v'");
  return v;
}

/// The number of cross sections $ROAD_CRG implies (0: as many as the data has).
std::size_t expected_rows(const crg::RoadCrgKeys& k, const std::string& file) {
  if (k.increment && !(*k.increment > 0))
    throw crg::error_at(file, k.increment_line, "REFERENCE_LINE_INCREMENT must be > 0");
  if (!k.end_u || !k.increment) return 0;
  const double n = (*k.end_u - k.start_u.value_or(0.0)) / *k.increment;
  if (!(n >= 1) || n > 1e9 || std::abs(n - std::round(n)) > 1e-3)
    throw crg::error_at(file, k.end_u_line,
                        "REFERENCE_LINE_END_U is not a whole number (>= 1) of "
                        "REFERENCE_LINE_INCREMENT from REFERENCE_LINE_START_U");
  return static_cast<std::size_t>(std::llround(n)) + 1;
}

void fill_u(CrgData& d, const crg::RoadCrgKeys& k, std::size_t rows, const std::string& file) {
  if (rows < 2) throw crg::error_at(file, k.line, "a grid needs at least 2 cross sections");
  d.u_first_m = k.start_u.value_or(0.0);
  if (k.increment) {
    d.u_increment_m = *k.increment;
  } else if (k.end_u && *k.end_u > d.u_first_m) {
    d.u_increment_m = (*k.end_u - d.u_first_m) / static_cast<double>(rows - 1);
  } else {
    throw crg::error_at(file, k.line,
                        "$ROAD_CRG needs REFERENCE_LINE_INCREMENT (or REFERENCE_LINE_END_U > "
                        "REFERENCE_LINE_START_U)");
  }
}

/// Column `c` of every row into `out` (empty if the file has no such channel); rows from
/// `first_row` must be finite and within `limit`.
void channel(const crg::Payload& p, std::size_t channels, int c, std::size_t first_row,
             double limit, const char* name, const std::string& file, std::vector<double>& out) {
  if (c < 0) return;
  out.resize(p.rows);
  for (std::size_t i = 0; i < p.rows; ++i) {
    out[i] = p.values[i * channels + static_cast<std::size_t>(c)];
    if (i >= first_row && !(std::abs(out[i]) <= limit))
      throw ConfigError(p.where(file, i) + ": reference line " + name + " " +
                        std::to_string(out[i]) + ": not a finite number within +-" +
                        std::to_string(limit));
  }
}

void fill_reference_line(CrgData& d, const crg::RoadCrgKeys& k, const Layout& l,
                         const crg::Payload& p, std::size_t channels, const std::string& file) {
  d.start_x_m = k.start_x.value_or(0.0);
  d.start_y_m = k.start_y.value_or(0.0);
  d.start_phi_rad = k.start_phi.value_or(0.0);
  d.start_z_m = k.start_z.value_or(0.0);
  d.start_slope = k.start_slope.value_or(0.0);
  d.start_bank = k.start_bank.value_or(0.0);
  d.end_x_m = k.end_x.value_or(d.end_x_m);
  d.end_y_m = k.end_y.value_or(d.end_y_m);
  d.end_z_m = k.end_z.value_or(d.end_z_m);
  if ((l.slope < 0 && k.end_slope.value_or(d.start_slope) != d.start_slope) ||
      (l.banking < 0 && k.end_bank.value_or(d.start_bank) != d.start_bank))
    throw crg::error_at(file, k.line,
                        "REFERENCE_LINE_END_S/B differ from START_S/B: a varying slope or banking "
                        "needs its channel");
  channel(p, channels, l.phi, 1, 1e6, "phi", file, d.heading_rad);  // entry 0 unused
  channel(p, channels, l.slope, 1, kMaxSlope, "slope", file, d.slope);
  channel(p, channels, l.banking, 0, kMaxSlope, "banking", file, d.banking);
  if (l.phi < 0) {  // x/y channels define the line only without a heading channel
    channel(p, channels, l.x, 0, 1e8, "x", file, d.ref_x_m);
    channel(p, channels, l.y, 0, 1e8, "y", file, d.ref_y_m);
    for (std::size_t i = 1; i < d.ref_x_m.size(); ++i) {
      if (d.ref_x_m[i] == d.ref_x_m[i - 1] && d.ref_y_m[i] == d.ref_y_m[i - 1])
        throw ConfigError(p.where(file, i) + ": reference line x/y repeats the point before");
    }
  }
}

/// The heights; each cross section needs a valid cell and NaN only at its ends (OpenCRG).
void fill_heights(CrgData& d, const Layout& l, const crg::Payload& p, std::size_t channels,
                  const std::string& file) {
  const std::size_t nv = l.z.size();
  d.z_m.resize(p.rows * nv);
  for (std::size_t i = 0; i < p.rows; ++i) {
    int state = 0;  // 0: NaN on the right, 1: valid cells, 2: NaN on the left
    for (std::size_t j = 0; j < nv; ++j) {
      const double z = p.values[i * channels + static_cast<std::size_t>(l.z[j])];
      if (!std::isnan(z) && !(std::abs(z) <= kMaxHeight_m))
        throw ConfigError(p.where(file, i) + ": height " + std::to_string(z) +
                          " m in long section " + std::to_string(j + 1) + ": beyond +-1e5 m");
      if (std::isnan(z) && state == 1) state = 2;
      if (!std::isnan(z) && state == 2)
        throw ConfigError(p.where(file, i) + ": NaN between valid heights (long section " +
                          std::to_string(j) + "); NaN may only fill a cross section's ends");
      if (!std::isnan(z)) state = 1;
      d.z_m[i * nv + j] = static_cast<float>(z);
    }
    if (state == 0)
      throw ConfigError(p.where(file, i) + ": a cross section without a valid height");
  }
}

/// A given end point must be near where the heading channel leads (OpenCRG spreads the
/// difference over the line; a large one is a wrong file).
void check_closure(const CrgData& d, const crg::RoadCrgKeys& k, const std::string& file) {
  if (!k.end_x || !k.end_y || !d.ref_x_m.empty()) return;
  double x = d.start_x_m;
  double y = d.start_y_m;
  for (std::size_t i = 1; i < d.nu(); ++i) {
    const double phi = d.heading_rad.empty() ? d.start_phi_rad : d.heading_rad[i];
    x += d.u_increment_m * std::cos(phi);
    y += d.u_increment_m * std::sin(phi);
  }
  const double miss = std::hypot(*k.end_x - x, *k.end_y - y);
  const double length = d.u_last_m() - d.u_first_m;
  if (miss > 0.01 * length + 1e-3)
    throw crg::error_at(file, k.end_xy_line,
                        "REFERENCE_LINE_END_X/Y is " + std::to_string(miss) +
                            " m from where the reference line ends (" + std::to_string(x) + ", " +
                            std::to_string(y) + ")");
}

CrgData read_grid(const std::string& content, const crg::Header& h, const std::string& file) {
  const crg::RoadCrgKeys k = crg::read_road_crg(h.find("ROAD_CRG"), file);
  const crg::Section* kd = h.find("KD_DEFINITION");
  if (kd == nullptr)
    throw crg::error_at(file, 1, "no $KD_Definition section (the road data's channels)");
  const crg::Definition def = crg::read_definition(*kd, file);
  const Layout l = layout_of(def, file);
  CrgData d;
  d.v_m = long_section_v(def, l, k, file);
  const std::size_t channels = def.channels.size();
  const std::size_t rows = expected_rows(k, file);
  const crg::Payload p = crg::read_payload(content, h, def.format, channels, rows, file);
  if (rows > 0 && p.rows != rows)
    throw crg::error_at(file, k.end_u_line,
                        "REFERENCE_LINE_START_U/END_U/INCREMENT make " + std::to_string(rows) +
                            " cross sections, the data has " + std::to_string(p.rows) + " rows");
  fill_u(d, k, p.rows, file);
  fill_reference_line(d, k, l, p, channels, file);
  fill_heights(d, l, p, channels, file);
  check_closure(d, k, file);
  return d;
}

/// $ROAD_CRG_FILE: one path, possibly split over records, relative to the referencing file.
fs::path referenced_file(const crg::Section& s, const fs::path& file) {
  std::string path;
  for (const crg::Record& r : s.records) path += r.text;
  const std::string name = file.string();
  if (path.empty()) throw crg::error_at(name, s.line, "$ROAD_CRG_FILE names no file");
  const int line = s.records.front().line;
  if (path.find('$') != std::string::npos)
    throw crg::error_at(name, line,
                        "$ROAD_CRG_FILE '" + path +
                            "': environment variables in file references are not supported");
  fs::path p(path);
  if (p.is_relative()) p = file.parent_path() / p;
  std::error_code ec;
  if (!fs::is_regular_file(p, ec))
    throw crg::error_at(name, line,
                        "$ROAD_CRG_FILE '" + path + "' not found (resolved as " +
                            p.lexically_normal().string() + ")");
  return p;
}

CrgData load(const fs::path& file, int depth) {
  const std::string name = file.string();
  const std::string content = read_input_file(file, kMaxCrgFileBytes);
  const crg::Header h = crg::read_header(content, name);
  CrgData d;
  if (const crg::Section* ref = h.find("ROAD_CRG_FILE")) {
    if (depth >= kMaxReferenceDepth)
      throw crg::error_at(name, ref->line,
                          "$ROAD_CRG_FILE references nest deeper than " +
                              std::to_string(kMaxReferenceDepth) + " (a cycle?)");
    d = load(referenced_file(*ref, file), depth + 1);
  } else {
    d = read_grid(content, h, name);
  }
  if (const crg::Section* o = h.find("ROAD_CRG_OPTS")) d.options = crg::read_options(*o, name);
  if (const crg::Section* m = h.find("ROAD_CRG_MODS")) d.mods = crg::read_modifiers(*m, name, d);
  return d;
}

}  // namespace

model::road::CrgData load_crg_file(const std::filesystem::path& file) { return load(file, 0); }

}  // namespace rig::io::config
