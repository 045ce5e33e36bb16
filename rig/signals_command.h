#pragma once
/// @file
/// `rig signals CONFIG [--json]`: the signal catalogue of the model a run configuration builds
/// (io/signals/catalogue.h, docs/signals.md), one entry a line: name, unit, direction (in/out),
/// min, max (inputs; "-" for outputs), aliases; --json: an array of objects with exactly the
/// keys name, unit, direction, min, max (null for outputs), aliases.

#include <iosfwd>
#include <string>

#include "io/signals/catalogue.h"

namespace rig {

/// Writes the catalogue as text or JSON to `out`.
void write_signals(const io::signals::Catalogue& catalogue, bool json, std::ostream& out);

/// Loads `config_file` as `rig run` does and writes its catalogue. Returns the exit code: 0, or
/// 2 with `file:line: what is wrong` on `err` for a bad configuration.
int signals_command(const std::string& config_file, bool json, std::ostream& out,
                    std::ostream& err);

}  // namespace rig
