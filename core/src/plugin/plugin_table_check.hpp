// Checks what a plugin says about itself before anything uses it: a plugin's own table is not
// trusted. Its name and every parameter name must be lower_snake_case, no parameter may be
// declared twice, and each default must have the declared type, lie in the declared range (or
// among the choices) of a range that is not empty. Otherwise the scenario validator would accept
// values the plugin cannot take, and a run would die later naming neither plugin nor file.
#pragma once

#include <filesystem>
#include <string_view>

#include "swarmnet/plugin.hpp"

namespace swarmnet {

// Throws PluginError naming the plugin, its file, the parameter and what is wrong.
void check_plugin_table(const PluginInfo& info, const std::filesystem::path& file);

// Whether `name` is lower_snake_case: [a-z][a-z0-9]* words joined by single underscores.
bool is_lower_snake_case(std::string_view name);

}  // namespace swarmnet
