// What `swarmnet plugins` prints: the table of every plugin found, and one plugin's details with
// its parameter schema (the same schema the scenario validator checks against).
#pragma once

#include <ostream>
#include <string>

#include "plugin/plugin_library.hpp"
#include "plugin/plugin_loader.hpp"
#include "swarmnet/params.hpp"

namespace swarmnet {

// `swarmnet plugins`: one row per plugin (kind, name, version, path, summary) in aligned columns,
// ordered by kind then name; then every library file that could not be opened, with the reason;
// then the search path in order.
void print_plugin_table(std::ostream& out, PluginLoader& loader);

// `swarmnet plugins NAME`: name, kind, version, path, summary, the full description, and a table
// of parameters (name, type, default, range, unit, choices, help).
void print_plugin_details(std::ostream& out, const PluginLibrary& library);

// A real as a person would write it and as it reads back exactly: the shortest decimal that
// round-trips, in fixed notation for ordinary magnitudes (6000000, 0.1) and scientific otherwise
// (1e-09, 1e+20).
std::string format_real(double value);

// A parameter value in the same spelling: reals as format_real(), integers in decimal, booleans as
// true/false, text as is.
std::string format_param_value(const ParamValue& value);

// The accepted range of a real or integer parameter: "0..10", ">= 0", "<= 5" or "any"; "" for
// other types. Integer bounds at the limits of int64 count as open.
std::string format_param_range(const ParamSpec& spec);

}  // namespace swarmnet
