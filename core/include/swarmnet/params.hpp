// Plugin parameters: the schema a plugin declares and the values the kernel hands it.
//
// The kernel validates a scenario's parameters against the schema (type, range, no unknown
// names) and fills defaults before a plugin sees them, so accessors below only fail on a
// programming error (asking for a name the schema does not declare).
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace swarmnet {

enum class ParamType : std::uint8_t { real, integer, boolean, text };

inline const char* to_string(ParamType type) {
  switch (type) {
    case ParamType::real:
      return "real";
    case ParamType::integer:
      return "integer";
    case ParamType::boolean:
      return "boolean";
    case ParamType::text:
      return "text";
  }
  return "?";
}

using ParamValue = std::variant<double, std::int64_t, bool, std::string>;

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::real;
  ParamValue default_value;
  std::string unit;  // SI unit ("m", "s", "bit/s", "dBm", "1/s") or "" when dimensionless
  std::string help;
  // Inclusive bounds for real and integer parameters.
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  // For text parameters: the accepted values, or empty for any text.
  std::vector<std::string> choices;
};

// Builders so that a schema reads as a table in the plugin's source.
inline ParamSpec real_param(std::string name, double default_value, std::string unit,
                            std::string help, double min = -std::numeric_limits<double>::infinity(),
                            double max = std::numeric_limits<double>::infinity()) {
  return {std::move(name),
          ParamType::real,
          default_value,
          std::move(unit),
          std::move(help),
          min,
          max,
          {}};
}
inline ParamSpec integer_param(std::string name, std::int64_t default_value, std::string unit,
                               std::string help,
                               std::int64_t min = std::numeric_limits<std::int64_t>::min(),
                               std::int64_t max = std::numeric_limits<std::int64_t>::max()) {
  return {std::move(name),
          ParamType::integer,
          default_value,
          std::move(unit),
          std::move(help),
          static_cast<double>(min),
          static_cast<double>(max),
          {}};
}
inline ParamSpec bool_param(std::string name, bool default_value, std::string help) {
  return {std::move(name), ParamType::boolean, default_value, "", std::move(help), 0, 1, {}};
}
inline ParamSpec text_param(std::string name, std::string default_value, std::string help,
                            std::vector<std::string> choices = {}) {
  return {std::move(name),   ParamType::text, std::move(default_value), "", std::move(help), 0, 0,
          std::move(choices)};
}

// Validated parameter values of one plugin instance, keyed by name (ordered: deterministic).
class ParamSet {
 public:
  ParamSet() = default;
  explicit ParamSet(std::map<std::string, ParamValue> values) : values_(std::move(values)) {}

  [[nodiscard]] double real(const std::string& name) const { return get<double>(name); }
  [[nodiscard]] std::int64_t integer(const std::string& name) const {
    return get<std::int64_t>(name);
  }
  [[nodiscard]] bool boolean(const std::string& name) const { return get<bool>(name); }
  [[nodiscard]] const std::string& text(const std::string& name) const {
    return get<std::string>(name);
  }
  [[nodiscard]] bool contains(const std::string& name) const { return values_.contains(name); }
  [[nodiscard]] const std::map<std::string, ParamValue>& values() const { return values_; }

  void set(const std::string& name, ParamValue value) { values_[name] = std::move(value); }

 private:
  template <typename T>
  const T& get(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) throw std::logic_error("parameter '" + name + "' is not declared");
    const T* value = std::get_if<T>(&it->second);
    if (value == nullptr) throw std::logic_error("parameter '" + name + "' has another type");
    return *value;
  }
  std::map<std::string, ParamValue> values_;
};

}  // namespace swarmnet
