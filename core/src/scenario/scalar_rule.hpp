// What a scalar value must look like (type, range, choices, unit), and the check of one YAML
// scalar against it. Shared by the scenario's own keys and by plugin parameters, so both are
// refused with the same words.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "swarmnet/params.hpp"

namespace swarmnet {

enum class ScalarType : std::uint8_t {
  real,     // a finite number; an integer is accepted
  integer,  // digits only: 2.0 and 1e3 are refused
  boolean,  // true or false, nothing else
  text,     // any scalar, quoted or not
  name,     // text of letters, digits, '_', '-' and '.'
  choice,   // text from `choices`
};

struct ScalarRule {
  ScalarType type = ScalarType::real;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // min itself is refused (x > min)
  bool max_open = false;
  std::vector<std::string> choices;
  std::string unit;

  // The expected form, for messages and the reference: "real > 0 (m)", "integer 1..100000",
  // "true or false", "one of strict, pipelined".
  [[nodiscard]] std::string describe() const;
};

// The rule a plugin parameter's schema entry stands for.
ScalarRule rule_for(const ParamSpec& spec);

// How a YAML scalar was written. Quoted scalars are always text; plain ones are read as YAML 1.2
// core types would be (true/false, integers, reals, null) and otherwise as text.
struct YamlScalar {
  enum class Kind : std::uint8_t { null, boolean, integer, real, text };
  Kind kind = Kind::null;
  bool quoted = false;
  bool boolean = false;
  std::int64_t integer = 0;
  bool integer_overflow = false;  // digits only, but beyond int64
  double real = 0.0;
  std::string text;  // as written
};
YamlScalar read_scalar(const YAML::Node& node);

// Checks `node` against `rule`. Returns the value (double for real, std::int64_t for integer, bool,
// std::string for the text types), or nullopt with `*problem` saying what is wrong with it.
std::optional<ParamValue> check_scalar(const ScalarRule& rule, const YAML::Node& node,
                                       std::string* problem);

// A value as it is written into the resolved scenario (reals as format_real()).
YAML::Node to_yaml(const ParamValue& value);

// The value as written in a message: 'abc', "12" (quoted), 2.5, a mapping, a list, no value.
std::string quote_value(const YAML::Node& node);

}  // namespace swarmnet
