#include "rig/check.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <iostream>
#include <ostream>
#include <vector>

#include "io/can/dbc/dbc_parser.h"
#include "io/can/mapping/can_mapping.h"
#include "io/config/config_error.h"
#include "io/config/crg_file.h"
#include "io/config/input_file.h"
#include "io/config/leaf_spring_config.h"
#include "io/config/opendrive_file.h"
#include "io/config/strict_table.h"
#include "io/config/vehicle_file.h"
#include "io/lcm/lcm_settings.h"
#include "model/road/crg_surface.h"
#include "rig/config.h"
#include "rig/sinks.h"
#include "rig/sweep/sweep_command.h"

namespace rig {

namespace {

constexpr std::size_t kHeadBytes = std::size_t{64} * 1024;

bool has_table(const FileContent& c, std::string_view key) {
  return c.toml && c.toml->get_as<toml::table>(key) != nullptr;
}

bool has_array(const FileContent& c, std::string_view key) {
  return c.toml && c.toml->get_as<toml::array>(key) != nullptr;
}

/// [model] kind of a run configuration, "" if there is none.
std::string_view model_kind(const FileContent& c) {
  if (!c.toml) return "";
  return (*c.toml)["model"]["kind"].value_or(std::string_view{});
}

// ---- run configurations (rig run --config): [rig], [model], [driver], [routing], ...

bool is_run_config(const FileContent& c) {
  return (has_table(c, "rig") || has_table(c, "model")) && model_kind(c) != "combination";
}

void check_run_config(const FileContent& c, std::ostream& notes) {
  const RigConfig config = load_config(c.path);
  // The warnings `rig run` gives, on stderr as there (make_io adds the DBC's and CAN's).
  if (const std::string warning = io::lcm::lcm_url_warning(config.lcm.url); !warning.empty())
    std::cerr << warning << "\n";
  RunOptions options;
  options.config_file = c.path.string();
  try {
    (void)make_io(config, options);  // loads DBC and mapping files, opens CAN
  } catch (const io::config::ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    notes << "note: " << e.what()
          << " (not available on this machine; not a configuration error)\n";
  }
}

// ---- combinations: run configurations of a vehicle combination ([model] kind = "combination",
// config/combinations/*.toml), checked as run configurations with every unit's vehicle file.

bool is_combination(const FileContent& c) { return model_kind(c) == "combination"; }

void check_combination(const FileContent& c, std::ostream& notes) {
  if (c.toml && !is_combination(c)) {
    const auto* model = c.toml->get_as<toml::table>("model");
    if (model == nullptr) {
      throw io::config::StrictTable(*c.toml, c.path, "top level")
          .error("no [model] table with kind = \"combination\"");
    }
    throw io::config::StrictTable(*model, c.path, "[model]")
        .error("kind", "is \"" + std::string(model_kind(c)) + "\", not \"combination\"");
  }
  check_run_config(c, notes);
}

// ---- vehicles (config/vehicles/*.toml): [chassis], [[axle]], [tires.*], ...

bool is_vehicle(const FileContent& c) { return has_table(c, "chassis") || has_array(c, "axle"); }

void check_vehicle(const FileContent& c, std::ostream& /*notes*/) {
  (void)io::config::load_vehicle_file(c.path);
}

// ---- CAN mappings (config/can/*.toml): dbc = "...", [[rx]], [[tx]]

bool is_can_mapping(const FileContent& c) {
  return has_array(c, "rx") || has_array(c, "tx") ||
         (c.toml && c.toml->get_as<std::string>("dbc") != nullptr);
}

void check_can_mapping(const FileContent& c, std::ostream& /*notes*/) {
  const auto config = io::can::mapping::load_can_config(c.path);
  // As `rig run` shows them (make_io): e.g. restbus messages without a cycle time.
  for (const auto& warning : config.mapping.warnings)
    std::cerr << "rig: warning: " << warning << "\n";
}

// ---- DBC files: text whose first word is a DBC section keyword (VERSION, NS_, BU_, BO_, ...)

bool is_dbc(const FileContent& c) {
  static constexpr std::array<std::string_view, 8> kKeywords{
      "VERSION", "NS_", "BS_", "BU_", "BO_", "CM_", "BA_DEF_", "VAL_TABLE_"};
  std::string_view text = c.head;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
  std::size_t begin = 0;
  while (begin < text.size() && std::isspace(static_cast<unsigned char>(text[begin])) != 0) {
    ++begin;
  }
  std::size_t end = begin;
  while (end < text.size() &&
         (std::isalnum(static_cast<unsigned char>(text[end])) != 0 || text[end] == '_')) {
    ++end;
  }
  const std::string_view word = text.substr(begin, end - begin);
  for (const auto keyword : kKeywords) {
    if (word == keyword) return true;
  }
  return false;
}

void check_dbc(const FileContent& c, std::ostream& notes) {
  const auto database = io::can::dbc::load_dbc(c.path);
  for (const auto& warning : database.warnings) notes << "note: " << warning << "\n";
}

// ---- OpenCRG road surfaces (.crg): the first record that is not a comment opens an OpenCRG
// section ($CT, $ROAD_CRG, $KD_Definition, ...); the rest may be binary.

bool is_crg(const FileContent& c) {
  std::string_view text = c.head;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    if (line.find_first_not_of(" \t\r") == std::string_view::npos || line.starts_with('*') ||
        line.starts_with('%'))
      continue;
    std::string word;
    for (std::size_t i = 1;
         i < line.size() &&
         (std::isalnum(static_cast<unsigned char>(line[i])) != 0 || line[i] == '_');
         ++i)
      word += static_cast<char>(std::toupper(static_cast<unsigned char>(line[i])));
    return line.starts_with('$') &&
           (word == "CT" || word == "KD_DEFINITION" || word.starts_with("ROAD_CRG"));
  }
  return false;
}

void check_crg(const FileContent& c, std::ostream& notes) {
  const model::road::CrgData data = io::config::load_crg_file(c.path);
  const model::road::CrgSurface surface(data);  // the reference line and NaN modes apply
  notes << "note: " << data.nu() << " x " << data.nv() << " grid, u " << data.u_first_m << " .. "
        << data.u_last_m() << " m, v " << data.v_m.front() << " .. " << data.v_m.back() << " m\n";
}

// ---- OpenDRIVE roads (config/roads/*.xodr): XML whose root element is <OpenDRIVE>

bool is_opendrive(const FileContent& c) {
  return !c.toml && c.head.find("<OpenDRIVE") != std::string::npos;
}

void check_opendrive(const FileContent& c, std::ostream& /*notes*/) {
  const auto file = io::config::load_opendrive_file(c.path);
  for (const auto& road : file.roads)  // every road, as the model would build its surface
    (void)io::config::make_opendrive_surface(file, road.id, {});
  // as `rig run` shows them: gaps between geometries, ignored profiles
  for (const auto& warning : file.warnings) std::cerr << "rig: warning: " << warning << "\n";
}

// ---- sweep specifications (rig sweep SPEC; config/sweeps/): TOML with base = "..." or
// maneuvers = [...] at the top and no [rig] or [model]

bool is_sweep(const FileContent& c) {
  return c.toml && (c.toml->contains("base") || c.toml->contains("maneuvers")) &&
         !has_table(c, "rig") && !has_table(c, "model");
}

void check_sweep(const FileContent& c, std::ostream& notes) {
  notes << "note: " << sweep::check_sweep_spec(c.path) << " runs\n";
}

// ---- a leaf spring on its own: a TOML file with only [axle.leaf_spring] (issue 17 item 2)

bool is_leaf_spring(const FileContent& c) {
  return has_table(c, "axle") && (*c.toml)["axle"]["leaf_spring"].as_table() != nullptr;
}

void check_leaf_spring(const FileContent& c, std::ostream& /*notes*/) {
  (void)io::config::load_leaf_spring_file(c.path);
}

/// The registry. A new kind of file: one entry (and its recognizer and checker above).
constexpr std::array kFileKinds{
    FileKind{"run-config",
             "TOML with [rig] or [model] (rig run --config; config/rig.toml, "
             "config/maneuvers/)",
             is_run_config, check_run_config},
    FileKind{"combination",
             "a run configuration with [model] kind = \"combination\" "
             "(config/combinations/)",
             is_combination, check_combination},
    FileKind{"vehicle", "TOML with [chassis] and [[axle]] (config/vehicles/)", is_vehicle,
             check_vehicle},
    FileKind{"can-mapping", "TOML with dbc = \"...\" and [[rx]] / [[tx]] (config/can/)",
             is_can_mapping, check_can_mapping},
    FileKind{"dbc", "a CAN database starting with VERSION, NS_, BU_ or BO_ (config/can/)", is_dbc,
             check_dbc},
    FileKind{"crg", "an OpenCRG road surface starting with $CT or another OpenCRG section (*.crg)",
             is_crg, check_crg},
    FileKind{"opendrive", "XML with the root element <OpenDRIVE> (an ASAM OpenDRIVE road, .xodr)",
             is_opendrive, check_opendrive},
    FileKind{
        "sweep",
        "TOML with base = \"...\" or maneuvers = [...] and [[vary]] (rig sweep; config/sweeps/)",
        is_sweep, check_sweep},
    FileKind{"leaf-spring", "TOML with only [axle.leaf_spring] (a five-link leaf spring)",
             is_leaf_spring, check_leaf_spring},
};

void print_expected(std::ostream& err) {
  err << "  expected one of:\n";
  for (const auto& kind : kFileKinds) {
    err << "    " << kind.name << ": " << kind.looks_like << "\n";
  }
}

/// The kind `content` shows; nullptr (with the message printed) if none or more than one.
const FileKind* recognize(const FileContent& content, const std::string& file, std::ostream& err) {
  std::vector<const FileKind*> matches;
  for (const auto& kind : kFileKinds) {
    if (kind.recognize(content)) matches.push_back(&kind);
  }
  if (matches.size() == 1) return matches.front();
  if (matches.empty()) {
    // A *.toml that does not parse is most likely a rig file with a syntax error: say where.
    if (!content.toml && content.path.extension() == ".toml") {
      err << content.toml_error << "\n";
      return nullptr;
    }
    err << file << ": not a rig file\n";
    if (!content.toml) err << "  not TOML: " << content.toml_error << "\n";
    print_expected(err);
    return nullptr;
  }
  err << file << ": ambiguous: looks like";
  for (std::size_t i = 0; i < matches.size(); ++i) {
    err << (i == 0 ? " " : " and ") << matches[i]->name;
  }
  err << "; say which with --kind\n";
  return nullptr;
}

}  // namespace

FileContent read_file_content(const std::filesystem::path& file) {
  FileContent content;
  content.path = file;
  try {
    content.head = io::config::read_input_file(file).substr(0, kHeadBytes);
  } catch (const io::config::ConfigError& e) {
    content.toml_error = e.what();
    return content;
  }
  try {
    content.toml = io::config::load_toml_file(file);
  } catch (const io::config::ConfigError& e) {
    content.toml_error = e.what();
  }
  return content;
}

std::span<const FileKind> file_kinds() { return kFileKinds; }

const FileKind* find_file_kind(std::string_view name) {
  for (const auto& kind : kFileKinds) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

int check_file(const std::string& file, const FileKind* kind, std::ostream& out,
               std::ostream& err) {
  try {
    (void)io::config::read_input_file(file);  // a regular file of bounded size, or why not
  } catch (const io::config::ConfigError& e) {
    err << e.what() << "\n";
    return 2;
  }
  const FileContent content = read_file_content(file);
  if (kind == nullptr) kind = recognize(content, file, err);
  if (kind == nullptr) return 2;
  try {
    kind->check(content, out);
  } catch (const io::config::ConfigError& e) {
    err << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // a loader's other complaints about the file
    err << file << ": " << e.what() << "\n";
    return 2;
  }
  out << file << ": " << kind->name << ": OK\n";
  return 0;
}

}  // namespace rig
