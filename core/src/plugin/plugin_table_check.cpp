#include "plugin/plugin_table_check.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <variant>

#include "plugin/plugin_error.hpp"

namespace swarmnet {

namespace {

bool holds_declared_type(const ParamSpec& spec) {
  switch (spec.type) {
    case ParamType::real:
      return std::holds_alternative<double>(spec.default_value);
    case ParamType::integer:
      return std::holds_alternative<std::int64_t>(spec.default_value);
    case ParamType::boolean:
      return std::holds_alternative<bool>(spec.default_value);
    case ParamType::text:
      return std::holds_alternative<std::string>(spec.default_value);
  }
  return false;
}

const char* type_of(const ParamValue& value) {
  if (std::holds_alternative<double>(value)) return "real";
  if (std::holds_alternative<std::int64_t>(value)) return "integer";
  if (std::holds_alternative<bool>(value)) return "boolean";
  return "text";
}

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// What is wrong with one parameter's declaration, or "" when nothing is.
std::string problem_with(const ParamSpec& spec) {
  if (!is_lower_snake_case(spec.name)) return "its name is not lower_snake_case";
  if (!holds_declared_type(spec)) {
    return std::string("it is declared ") + to_string(spec.type) + " but its default is " +
           type_of(spec.default_value);
  }
  if (spec.type == ParamType::real || spec.type == ParamType::integer) {
    if (std::isnan(spec.min) || std::isnan(spec.max) || spec.min > spec.max)
      return "its range [" + number(spec.min) + ", " + number(spec.max) + "] is empty";
    const double value = spec.type == ParamType::real
                             ? std::get<double>(spec.default_value)
                             : static_cast<double>(std::get<std::int64_t>(spec.default_value));
    if (!(value >= spec.min && value <= spec.max)) {
      return "its default " + number(value) + " is outside its range [" + number(spec.min) + ", " +
             number(spec.max) + "]";
    }
  }
  if (spec.type == ParamType::text && !spec.choices.empty()) {
    const auto& value = std::get<std::string>(spec.default_value);
    bool listed = false;
    for (const auto& choice : spec.choices) listed = listed || choice == value;
    if (!listed) return "its default '" + value + "' is not among its choices";
  }
  return "";
}

}  // namespace

bool is_lower_snake_case(std::string_view name) {
  if (name.empty() || name.front() < 'a' || name.front() > 'z' || name.back() == '_') return false;
  char previous = '\0';
  for (const char c : name) {
    const bool allowed = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    if (!allowed || (c == '_' && previous == '_')) return false;
    previous = c;
  }
  return true;
}

void check_plugin_table(const PluginInfo& info, const std::filesystem::path& file) {
  const std::string plugin = "plugin '" + info.name + "' (" + file.string() + ")";
  if (!is_lower_snake_case(info.name))
    throw PluginError(plugin + ": its name is not lower_snake_case");
  std::set<std::string> declared;
  for (const auto& spec : info.params) {
    if (!declared.insert(spec.name).second)
      throw PluginError(plugin + ": parameter '" + spec.name + "' is declared twice");
    const std::string problem = problem_with(spec);
    if (!problem.empty()) throw PluginError(plugin + ": parameter '" + spec.name + "': " + problem);
  }
}

}  // namespace swarmnet
