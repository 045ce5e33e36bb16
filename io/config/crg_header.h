#pragma once
/// @file
/// The plain-text header of an OpenCRG file (ASAM OpenCRG 1.2, "OpenCRG data files"): records of
/// at most 72 significant bytes in sections that start with `$KEYWORD` and end with `$`; `*` in
/// column 1 and `!` in a line start comments; the header ends at a record starting with `$$`.
/// Internal to io/config/crg_file.cpp; every error is a ConfigError `file:line: what`.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/config/config_error.h"
#include "model/road/crg_data.h"

namespace rig::io::config::crg {

/// One record of a section, comments removed, trimmed (empty records dropped).
struct Record {
  std::string text;
  int line = 0;
};

struct Section {
  std::string name;  ///< upper case, without '$'
  int line = 0;
  std::vector<Record> records;
};

struct Header {
  std::vector<Section> sections;
  bool has_payload = false;        ///< a `$$` separator record was found
  std::size_t payload_offset = 0;  ///< first byte after the separator record
  int payload_line = 0;            ///< line number of the first payload record
  [[nodiscard]] const Section* find(std::string_view name) const;
};

/// Splits the header into its sections. Unknown sections and text outside a section are errors.
Header read_header(std::string_view content, const std::string& file);

/// `file:line: what`
ConfigError error_at(const std::string& file, int line, std::string_view what);

/// A header number: decimal or scientific; also the form `2.000000000+e00` (a mantissa and a
/// signed exponent after it) that ASAM's handmade_platform.crg uses.
std::optional<double> parse_number(std::string_view text);

/// A `KEY = value` record's keyword (upper case) and number; records of other shapes are errors.
struct Assignment {
  std::string key;
  double value = 0;
  int line = 0;
};
std::vector<Assignment> assignments(const Section& section, const std::string& file);

/// $ROAD_CRG: the reference line and the v axis as the file gives them (absent: nullopt).
struct RoadCrgKeys {
  std::optional<double> start_u, end_u, increment;
  std::optional<double> start_x, start_y, start_phi, start_z, end_x, end_y, end_z;
  std::optional<double> start_slope, end_slope, start_bank, end_bank;
  std::optional<double> v_right, v_left, v_increment;
  int line = 0;  ///< of the section (for errors about what is missing)
  int increment_line = 0, end_u_line = 0, v_line = 0, end_xy_line = 0;
};
RoadCrgKeys read_road_crg(const Section* section, const std::string& file);

/// $KD_Definition: the payload's format and channels.
enum class Format { kLrfi, kLdfi, kKrbi, kKdbi };
enum class ChannelKind { kPhi, kX, kY, kBanking, kSlope, kLongSection };
struct Channel {
  ChannelKind kind = ChannelKind::kLongSection;
  std::optional<double> v_m;  ///< `long section at v = X`
  int number = 0;             ///< `long section N`
  int line = 0;
};
struct Definition {
  Format format = Format::kKrbi;  ///< the default when no `#:` record is given
  std::vector<Channel> channels;
  int line = 0;
};
Definition read_definition(const Section& section, const std::string& file);

/// $ROAD_CRG_OPTS (absent keys: the defaults).
model::road::CrgOptions read_options(const Section& section, const std::string& file);

/// $ROAD_CRG_MODS (absent keys: the defaults); the REFPOINT_* keys resolved against the grid's
/// u and v range.
model::road::CrgModifiers read_modifiers(const Section& section, const std::string& file,
                                         const model::road::CrgData& grid);

}  // namespace rig::io::config::crg
