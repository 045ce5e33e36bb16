#include "io/config/crg_header.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

namespace rig::io::config::crg {
namespace {

constexpr std::size_t kRecordBytes = 72;  // significant bytes of a header record
constexpr std::array<std::string_view, 7> kSections{
    "CT",           "ROAD_CRG", "ROAD_CRG_MPRO", "KD_DEFINITION", "ROAD_CRG_OPTS", "ROAD_CRG_MODS",
    "ROAD_CRG_FILE"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())) != 0) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())) != 0) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

/// OpenCRG keywords: a letter, then letters, digits and underscores.
std::size_t keyword_length(std::string_view s) {
  if (s.empty() || std::isalpha(static_cast<unsigned char>(s[0])) == 0) return 0;
  std::size_t n = 1;
  while (n < s.size() && (std::isalnum(static_cast<unsigned char>(s[n])) != 0 || s[n] == '_')) ++n;
  return n;
}

/// A section record: the first 72 bytes, without the `!` comment, trimmed.
std::string_view record_text(std::string_view raw) {
  raw = raw.substr(0, std::min(raw.size(), kRecordBytes));
  if (const auto bang = raw.find('!'); bang != std::string_view::npos) raw = raw.substr(0, bang);
  return trim(raw);
}

/// Opens section `keyword` (or closes the current one if the `$` record has none).
void open_section(std::string_view raw, int line, const std::string& file, Header& h,
                  int& current) {
  const std::string_view rest = raw.substr(1);
  const std::size_t n = keyword_length(rest);
  if (n == 0) {  // `$` or `$!...`: the section ends
    current = -1;
    return;
  }
  const std::string name = upper(rest.substr(0, n));
  if (std::find(kSections.begin(), kSections.end(), name) == kSections.end())
    throw error_at(file, line,
                   "unknown section $" + std::string(rest.substr(0, n)) +
                       " (OpenCRG has $CT, $ROAD_CRG, $ROAD_CRG_MPRO, $KD_Definition, "
                       "$ROAD_CRG_OPTS, $ROAD_CRG_MODS, $ROAD_CRG_FILE)");
  if (const Section* s = h.find(name))
    throw error_at(
        file, line,
        "a second $" + name + " section (the first is at line " + std::to_string(s->line) + ")");
  h.sections.push_back({name, line, {}});
  current = static_cast<int>(h.sections.size()) - 1;
}

/// A record inside a section or outside every section.
void add_record(std::string_view raw, int line, const std::string& file, Header& h, int current) {
  if (current < 0) {  // outside a section: only comments and blank lines
    if (trim(raw).empty() || raw[0] == '*' || raw[0] == '%') return;
    throw error_at(file, line,
                   "text outside a section (sections start with a $KEYWORD record, the data "
                   "after a $$$$ record)");
  }
  Section& s = h.sections[static_cast<std::size_t>(current)];
  if (s.name == "CT" || s.name == "ROAD_CRG_MPRO" || raw.starts_with('*')) return;
  const std::string_view text = record_text(raw);
  if (!text.empty()) s.records.push_back({std::string(text), line});
}

/// Reads `KEY = value` records into named numbers: unknown keys and a key given twice with
/// different values are errors (ASAM's own handmade_sloped_opts.crg repeats LOG_EVAL alike).
class KeyValues {
 public:
  KeyValues(const Section& section, const std::string& file) : file_(file), section_(section) {
    for (const Assignment& a : assignments(section, file)) {
      auto [it, inserted] = values_.try_emplace(a.key, a);
      if (!inserted && it->second.value != a.value)
        throw error_at(file, a.line,
                       a.key + " given twice with different values (line " +
                           std::to_string(it->second.line) + ")");
    }
  }
  /// The value of `key` if given (and marks it read).
  std::optional<double> take(const std::string& key) {
    const auto it = values_.find(key);
    if (it == values_.end()) return std::nullopt;
    read_.push_back(key);
    return it->second.value;
  }
  [[nodiscard]] int line_of(const std::string& key) const {
    const auto it = values_.find(key);
    return it == values_.end() ? section_.line : it->second.line;
  }
  /// An integer in [lo, hi] (or the fallback).
  int integer(const std::string& key, int fallback, int lo, int hi) {
    const auto v = take(key);
    if (!v) return fallback;
    if (*v != std::floor(*v) || *v < lo || *v > hi)
      throw error_at(file_, line_of(key),
                     key + " = " + std::to_string(*v) + ": expected an integer in [" +
                         std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(*v);
  }
  /// Every key not read is unknown to `what`.
  void finish(std::string_view what) const {
    for (const auto& [key, a] : values_) {
      if (std::find(read_.begin(), read_.end(), key) == read_.end())
        throw error_at(
            file_, a.line,
            "$" + section_.name + ": unknown key " + key + " (" + std::string(what) + ")");
    }
  }

 private:
  const std::string& file_;
  const Section& section_;
  std::map<std::string, Assignment> values_;
  std::vector<std::string> read_;
};

}  // namespace

const Section* Header::find(std::string_view name) const {
  for (const Section& s : sections) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

ConfigError error_at(const std::string& file, int line, std::string_view what) {
  return ConfigError(file + ":" + std::to_string(line) + ": " + std::string(what));
}

Header read_header(std::string_view content, const std::string& file) {
  Header h;
  int current = -1;
  int line = 0;
  std::size_t pos = 0;
  while (pos < content.size()) {
    std::size_t end = content.find('\n', pos);
    const std::size_t next = end == std::string_view::npos ? content.size() : end + 1;
    if (end == std::string_view::npos) end = content.size();
    std::string_view raw = content.substr(pos, end - pos);
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    ++line;
    pos = next;
    if (raw.starts_with("$$")) {  // the header ends; the payload follows
      h.has_payload = true;
      h.payload_offset = next;
      h.payload_line = line + 1;
      return h;
    }
    if (raw.starts_with('$')) {
      open_section(raw, line, file, h, current);
    } else {
      add_record(raw, line, file, h, current);
    }
  }
  return h;
}

std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (text.starts_with('+')) text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
  if (ptr == end) return value;
  // `2.000000000+e00`: a signed exponent written after the mantissa
  std::string_view rest(ptr, static_cast<std::size_t>(end - ptr));
  if (rest.size() < 3 || (rest[0] != '+' && rest[0] != '-') || (rest[1] != 'e' && rest[1] != 'E'))
    return std::nullopt;
  int exponent = 0;
  const std::string_view digits = rest.substr(2);
  const auto [p2, e2] = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
  if (e2 != std::errc() || p2 != digits.data() + digits.size() || exponent < 0) return std::nullopt;
  return value * std::pow(10.0, rest[0] == '-' ? -exponent : exponent);
}

std::vector<Assignment> assignments(const Section& section, const std::string& file) {
  std::vector<Assignment> out;
  for (const Record& r : section.records) {
    const std::string_view text = r.text;
    const auto eq = text.find('=');
    const std::string_view key = trim(text.substr(0, eq));
    if (eq == std::string_view::npos || keyword_length(key) != key.size())
      throw error_at(file, r.line,
                     "$" + section.name + ": expected KEY = value, not '" + r.text + "'");
    const auto value = parse_number(text.substr(eq + 1));
    if (!value)
      throw error_at(file, r.line,
                     std::string(key) + ": '" + std::string(trim(text.substr(eq + 1))) +
                         "' is not a finite number");
    out.push_back({upper(key), *value, r.line});
  }
  return out;
}

RoadCrgKeys read_road_crg(const Section* section, const std::string& file) {
  RoadCrgKeys k;
  if (section == nullptr) return k;
  k.line = section->line;
  KeyValues kv(*section, file);
  const std::string p = "REFERENCE_LINE_";
  k.start_u = kv.take(p + "START_U");
  k.end_u = kv.take(p + "END_U");
  k.increment = kv.take(p + "INCREMENT");
  k.start_x = kv.take(p + "START_X");
  k.start_y = kv.take(p + "START_Y");
  k.start_phi = kv.take(p + "START_PHI");
  k.start_z = kv.take(p + "START_Z");
  k.end_x = kv.take(p + "END_X");
  k.end_y = kv.take(p + "END_Y");
  k.end_z = kv.take(p + "END_Z");
  k.start_slope = kv.take(p + "START_S");
  k.end_slope = kv.take(p + "END_S");
  k.start_bank = kv.take(p + "START_B");
  k.end_bank = kv.take(p + "END_B");
  k.v_right = kv.take("LONG_SECTION_V_RIGHT");
  k.v_left = kv.take("LONG_SECTION_V_LEFT");
  k.v_increment = kv.take("LONG_SECTION_V_INCREMENT");
  k.increment_line = kv.line_of(p + "INCREMENT");
  k.end_u_line = kv.line_of(p + "END_U");
  k.v_line = kv.line_of(k.v_increment ? "LONG_SECTION_V_INCREMENT" : "LONG_SECTION_V_RIGHT");
  k.end_xy_line = kv.line_of(p + "END_X");
  // the end heading (a check value) and the geographic position: read, not needed
  for (const char* key :
       {"END_PHI", "START_LON", "START_LAT", "START_ALT", "END_LON", "END_LAT", "END_ALT"})
    (void)kv.take(p + key);
  kv.finish(
      "OpenCRG's REFERENCE_LINE_START/END_U/X/Y/Z/PHI/S/B/LON/LAT/ALT, "
      "REFERENCE_LINE_INCREMENT, LONG_SECTION_V_RIGHT/LEFT/INCREMENT");
  return k;
}

namespace {

/// `D:name,unit`: the channel, or why not.
Channel channel_of(std::string_view spec, int line, const std::string& file) {
  const auto comma = spec.rfind(',');
  if (comma == std::string_view::npos)
    throw error_at(file, line, "channel definition without a unit: expected D:name,unit");
  std::string name;  // lower case, single spaces
  for (const char c : trim(spec.substr(0, comma))) {
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      if (!name.empty() && name.back() != ' ') name += ' ';
    } else {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  std::string unit(trim(spec.substr(comma + 1)));
  for (char& c : unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  Channel ch;
  ch.line = line;
  std::string want = "m";
  if (name == "reference line phi") {
    ch.kind = ChannelKind::kPhi;
    want = "rad";
  } else if (name == "reference line x" || name == "reference line y") {
    ch.kind = name.back() == 'x' ? ChannelKind::kX : ChannelKind::kY;
  } else if (name == "reference line banking" || name == "reference line slope") {
    ch.kind = name.back() == 'g' ? ChannelKind::kBanking : ChannelKind::kSlope;
    want = "m/m";
  } else if (name.starts_with("long section at v =") || name.starts_with("long section at v=")) {
    ch.v_m = parse_number(std::string_view(name).substr(name.find('=') + 1));
    if (!ch.v_m) throw error_at(file, line, "'" + name + "': v is not a finite number");
  } else if (name.starts_with("long section ")) {
    const auto n = parse_number(std::string_view(name).substr(13));
    if (!n || *n < 1 || *n != std::floor(*n) || *n > 1e6)
      throw error_at(file, line, "'" + name + "': expected long section N (N = 1, 2, ...)");
    ch.number = static_cast<int>(*n);
  } else {
    throw error_at(file, line,
                   "unknown channel '" + name +
                       "' (OpenCRG channels: reference line phi, x, y, banking, slope; long "
                       "section N; long section at v = X)");
  }
  if (unit != want)
    throw error_at(file, line,
                   "channel '" + name + "' has unit '" + unit + "', expected '" + want + "'");
  return ch;
}

model::road::CrgBorderMode border_mode(KeyValues& kv, const std::string& key,
                                       const std::string& file) {
  const int mode = kv.integer(key, 2, 0, 4);
  if (mode == 0)
    throw error_at(file, kv.line_of(key),
                   key +
                       " = 0 gives NaN beyond the grid, which no tire can stand on; use 1 "
                       "(zero), 2 (keep last), 3 (repeat) or 4 (reflect)");
  return static_cast<model::road::CrgBorderMode>(mode);
}

/// REFPOINT_*: the grid point (u, v) the file places at (x, y, z, phi) (OpenCRG's crg_mods:
/// u = REFPOINT_U or u_begin + REFPOINT_U_FRACTION (u_end - u_begin), then + REFPOINT_U_OFFSET;
/// v alike from 0 or v_right).
model::road::Placement refpoint(KeyValues& kv, const std::string& file,
                                const model::road::CrgData& grid) {
  model::road::Placement p;
  const auto u = kv.take("REFPOINT_U");
  const auto u_fraction = kv.take("REFPOINT_U_FRACTION");
  const auto u_offset = kv.take("REFPOINT_U_OFFSET");
  const auto v = kv.take("REFPOINT_V");
  const auto v_fraction = kv.take("REFPOINT_V_FRACTION");
  const auto v_offset = kv.take("REFPOINT_V_OFFSET");
  const auto x = kv.take("REFPOINT_X");
  const auto y = kv.take("REFPOINT_Y");
  const auto z = kv.take("REFPOINT_Z");
  const auto phi = kv.take("REFPOINT_PHI");
  if (u && u_fraction)
    throw error_at(file, kv.line_of("REFPOINT_U"),
                   "give REFPOINT_U or REFPOINT_U_FRACTION, not both");
  if (v && v_fraction)
    throw error_at(file, kv.line_of("REFPOINT_V"),
                   "give REFPOINT_V or REFPOINT_V_FRACTION, not both");
  p.given = u || u_fraction || u_offset || v || v_fraction || v_offset || x || y || z || phi;
  const double u_span = grid.u_last_m() - grid.u_first_m;
  p.u_m = u ? *u : grid.u_first_m + u_fraction.value_or(0.0) * u_span;
  p.u_m += u_offset.value_or(0.0);
  const double v_span = grid.v_m.back() - grid.v_m.front();
  p.v_m = v ? *v : (v_fraction ? grid.v_m.front() + *v_fraction * v_span : 0.0);
  p.v_m += v_offset.value_or(0.0);
  p.x_m = x.value_or(0.0);
  p.y_m = y.value_or(0.0);
  p.z_m = z.value_or(0.0);
  p.heading_rad = phi.value_or(0.0);
  return p;
}

}  // namespace

Definition read_definition(const Section& section, const std::string& file) {
  Definition d;
  d.line = section.line;
  bool have_format = false;
  for (const Record& r : section.records) {
    const std::string_view text = r.text;
    if (text.starts_with("#:")) {
      const std::string f = upper(trim(text.substr(2)));
      if (have_format) throw error_at(file, r.line, "a second data format (#:) record");
      have_format = true;
      if (f == "LRFI")
        d.format = Format::kLrfi;
      else if (f == "LDFI")
        d.format = Format::kLdfi;
      else if (f == "KRBI")
        d.format = Format::kKrbi;
      else if (f == "KDBI")
        d.format = Format::kKdbi;
      else
        throw error_at(file, r.line, "unknown data format '" + f + "' (LRFI, LDFI, KRBI, KDBI)");
    } else if (text.starts_with("U:") || text.starts_with("u:")) {
      continue;  // a virtual channel (for viewers); $ROAD_CRG defines u
    } else if (text.starts_with("D:") || text.starts_with("d:")) {
      d.channels.push_back(channel_of(text.substr(2), r.line, file));
    } else {
      throw error_at(
          file, r.line,
          "$KD_Definition: expected #:FORMAT, U:... or D:name,unit, not '" + r.text + "'");
    }
  }
  return d;
}

model::road::CrgOptions read_options(const Section& section, const std::string& file) {
  model::road::CrgOptions o;
  KeyValues kv(section, file);
  o.border_u = border_mode(kv, "BORDER_MODE_U", file);
  o.border_v = border_mode(kv, "BORDER_MODE_V", file);
  o.border_offset_u_m = kv.take("BORDER_OFFSET_U").value_or(0.0);
  o.border_offset_v_m = kv.take("BORDER_OFFSET_V").value_or(0.0);
  for (const char* key : {"BORDER_SMOOTH_UBEG", "BORDER_SMOOTH_UEND"}) {
    const double zone = kv.take(key).value_or(0.0);
    if (zone < 0) throw error_at(file, kv.line_of(key), std::string(key) + " must be >= 0");
    (std::string_view(key).ends_with("BEG") ? o.smooth_ubeg_m : o.smooth_uend_m) = zone;
  }
  if (kv.integer("REFLINE_CONTINUATION", 0, 0, 1) == 1)
    throw error_at(file, kv.line_of("REFLINE_CONTINUATION"),
                   "REFLINE_CONTINUATION = 1 (a closed track) is not supported; 0 extends the "
                   "reference line straight");
  // the OpenCRG tools' own messages, logs, searches and consistency checks: read, not needed
  for (const char* key : {"REFLINE_SEARCH_FAR", "REFLINE_SEARCH_CLOSE", "WARN_MSGS",
                          "WARN_CURV_LOCAL", "WARN_CURV_GLOBAL", "LOG_MSGS", "LOG_EVAL",
                          "LOG_EVAL_FREQ", "LOG_HIST", "LOG_HIST_FREQ", "LOG_STAT", "LOG_STAT_FREQ",
                          "CHECK_EPS", "CHECK_INC", "CHECK_TOL", "CHECK_PRO", "CHECK_WGS"})
    (void)kv.take(key);
  kv.finish("OpenCRG's BORDER_*, REFLINE_*, WARN_*, LOG_*, CHECK_* options");
  return o;
}

model::road::CrgModifiers read_modifiers(const Section& section, const std::string& file,
                                         const model::road::CrgData& grid) {
  model::road::CrgModifiers m;
  KeyValues kv(section, file);
  const int nan_mode = kv.integer("GRID_NAN_MODE", 2, 0, 2);
  if (nan_mode == 0)
    throw error_at(file, kv.line_of("GRID_NAN_MODE"),
                   "GRID_NAN_MODE = 0 keeps NaN heights, which no tire can stand on; use 1 (set "
                   "to GRID_NAN_OFFSET) or 2 (keep the last valid value)");
  m.nan_mode = static_cast<model::road::CrgNanMode>(nan_mode);
  m.nan_offset_m = kv.take("GRID_NAN_OFFSET").value_or(0.0);
  m.scale_z_grid = kv.take("SCALE_Z_GRID").value_or(1.0);
  m.scale_slope = kv.take("SCALE_SLOPE").value_or(1.0);
  m.scale_banking = kv.take("SCALE_BANKING").value_or(1.0);
  m.refpoint = refpoint(kv, file, grid);
  for (const char* key : {"SCALE_LENGTH", "SCALE_WIDTH", "SCALE_CURVATURE", "REFLINE_ROTCENTER_X",
                          "REFLINE_ROTCENTER_Y", "REFLINE_OFFSET_PHI", "REFLINE_OFFSET_X",
                          "REFLINE_OFFSET_Y", "REFLINE_OFFSET_Z"}) {
    if (kv.take(key))
      throw error_at(file, kv.line_of(key),
                     std::string(key) +
                         " is not supported; place the surface with REFPOINT_* or the "
                         "configuration's [road.placement]");
  }
  kv.finish("the rig reads GRID_NAN_MODE/OFFSET, SCALE_Z_GRID/SLOPE/BANKING, REFPOINT_*");
  return m;
}

}  // namespace rig::io::config::crg
