#include "scenario/scalar_rule.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

#include "plugin/plugin_catalog.hpp"
#include "scenario/nearest_name.hpp"
#include "scenario/shown_value.hpp"
#include "text/text_join.hpp"

namespace swarmnet {

namespace {

// Integer bounds are stored as doubles; the int64 extremes mean "no bound".
constexpr double kIntegerLimit = 9.2e18;

std::string format_bound(const ScalarRule& rule, double value) {
  if (rule.type == ScalarType::integer) return std::to_string(static_cast<std::int64_t>(value));
  return format_real(value);
}

bool is_digits(std::string_view text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::optional<double> parse_real(std::string_view text) {
  if (text == ".inf" || text == ".Inf" || text == ".INF" || text == "+.inf" || text == "+.Inf" ||
      text == "+.INF") {
    return std::numeric_limits<double>::infinity();
  }
  if (text == "-.inf" || text == "-.Inf" || text == "-.INF") {
    return -std::numeric_limits<double>::infinity();
  }
  if (text == ".nan" || text == ".NaN" || text == ".NAN") {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text.front())) ||
                        text.front() == '-' || text.front() == '.')) {
    return std::nullopt;  // from_chars would also take "inf" and "nan": those are YAML text
  }
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
  // At least one digit: "-" and "." alone are text.
  if (std::none_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return value;
}

// Names become parts of file names (runs/NAME-seedSEED): far below any file system's limit.
constexpr std::size_t kMaxNameLength = 128;

bool is_name(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

}  // namespace

std::string ScalarRule::describe() const {
  std::string text;
  switch (type) {
    case ScalarType::boolean:
      return "true or false";
    case ScalarType::text:
      return "text";
    case ScalarType::name:
      return "a name of letters, digits, '_', '-' and '.', at most " +
             std::to_string(kMaxNameLength) + " characters";
    case ScalarType::choice:
      return "one of " + join(choices, ", ");
    case ScalarType::real:
      text = "real";
      break;
    case ScalarType::integer:
      text = "integer";
      break;
  }
  const bool integer = type == ScalarType::integer;
  const bool has_min = std::isfinite(min) && !(integer && min <= -kIntegerLimit);
  const bool has_max = std::isfinite(max) && !(integer && max >= kIntegerLimit);
  const std::string low = has_min ? format_bound(*this, min) : "";
  const std::string high = has_max ? format_bound(*this, max) : "";
  if (has_min && has_max && !min_open && !max_open) {
    text += " " + low + ".." + high;
  } else {
    if (has_min) text += (min_open ? " > " : " >= ") + low;
    if (has_min && has_max) text += " and";
    if (has_max) text += (max_open ? " < " : " <= ") + high;
  }
  if (!unit.empty()) text += " (" + unit + ")";
  return text;
}

ScalarRule rule_for(const ParamSpec& spec) {
  ScalarRule rule;
  switch (spec.type) {
    case ParamType::real:
      rule.type = ScalarType::real;
      break;
    case ParamType::integer:
      rule.type = ScalarType::integer;
      break;
    case ParamType::boolean:
      rule.type = ScalarType::boolean;
      break;
    case ParamType::text:
      rule.type = spec.choices.empty() ? ScalarType::text : ScalarType::choice;
      break;
  }
  if (spec.type == ParamType::real || spec.type == ParamType::integer) {
    rule.min = spec.min;
    rule.max = spec.max;
  }
  rule.choices = spec.choices;
  rule.unit = spec.unit;
  return rule;
}

YamlScalar read_scalar(const YAML::Node& node) {
  YamlScalar scalar;
  if (!node.IsDefined() || node.IsNull()) return scalar;
  scalar.text = node.Scalar();
  const std::string& tag = node.Tag();
  if (tag == "!" || tag == "tag:yaml.org,2002:str") {
    scalar.kind = YamlScalar::Kind::text;
    scalar.quoted = true;
    return scalar;
  }
  const std::string& text = scalar.text;
  if (text == "true" || text == "false") {
    scalar.kind = YamlScalar::Kind::boolean;
    scalar.boolean = text == "true";
    return scalar;
  }
  if (text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL") {
    return scalar;  // null
  }
  const std::string_view digits =
      (text.front() == '-' || text.front() == '+') ? std::string_view(text).substr(1) : text;
  if (is_digits(digits)) {
    scalar.kind = YamlScalar::Kind::integer;
    std::string_view number = text;
    if (number.front() == '+') number.remove_prefix(1);
    const auto result =
        std::from_chars(number.data(), number.data() + number.size(), scalar.integer);
    scalar.integer_overflow = result.ec != std::errc();
    scalar.real = parse_real(text).value_or(0.0);
    return scalar;
  }
  if (const auto real = parse_real(text)) {
    scalar.kind = YamlScalar::Kind::real;
    scalar.real = *real;
    return scalar;
  }
  scalar.kind = YamlScalar::Kind::text;
  return scalar;
}

std::string quote_value(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "no value";
  if (node.IsMap()) return "a mapping";
  if (node.IsSequence()) return "a list";
  const YamlScalar scalar = read_scalar(node);
  const std::string text = shown_value(scalar.text);
  if (scalar.quoted) return "\"" + text + "\" (quoted)";
  if (scalar.kind == YamlScalar::Kind::text) return "'" + text + "'";
  return text;
}

std::optional<ParamValue> check_scalar(const ScalarRule& rule, const YAML::Node& node,
                                       std::string* problem) {
  if (!node.IsDefined() || node.IsNull()) {
    *problem = "has no value";
    return std::nullopt;
  }
  if (!node.IsScalar()) {
    *problem = quote_value(node) + " is not " +
               (rule.type == ScalarType::real || rule.type == ScalarType::integer
                    ? std::string("a number")
                    : std::string("a single value"));
    return std::nullopt;
  }
  const YamlScalar scalar = read_scalar(node);
  const std::string shown = quote_value(node);
  const auto check_range = [&](double value) {
    const bool low = rule.min_open ? value <= rule.min : value < rule.min;
    const bool high = rule.max_open ? value >= rule.max : value > rule.max;
    if (low || high) *problem = shown + " is out of range";
    return !(low || high);
  };

  switch (rule.type) {
    case ScalarType::real: {
      double value = 0.0;
      if (scalar.kind == YamlScalar::Kind::integer || scalar.kind == YamlScalar::Kind::real) {
        value = scalar.kind == YamlScalar::Kind::integer && !scalar.integer_overflow
                    ? static_cast<double>(scalar.integer)
                    : scalar.real;
      } else if (scalar.quoted) {
        *problem = shown + " is text, not a number (remove the quotes)";
        return std::nullopt;
      } else {
        *problem = shown + " is not a number";
        return std::nullopt;
      }
      if (!std::isfinite(value)) {
        *problem = shown + " is not a finite number";
        return std::nullopt;
      }
      if (!check_range(value)) return std::nullopt;
      return value;
    }
    case ScalarType::integer: {
      if (scalar.kind == YamlScalar::Kind::real) {
        *problem = shown + " is not an integer";
        return std::nullopt;
      }
      if (scalar.kind != YamlScalar::Kind::integer) {
        *problem = shown + (scalar.quoted ? " is text, not an integer (remove the quotes)"
                                          : " is not an integer");
        return std::nullopt;
      }
      if (scalar.integer_overflow) {
        *problem = shown + " is out of range";
        return std::nullopt;
      }
      if (!check_range(static_cast<double>(scalar.integer))) return std::nullopt;
      return scalar.integer;
    }
    case ScalarType::boolean:
      if (scalar.kind != YamlScalar::Kind::boolean) {
        *problem = shown + " is not a boolean";
        return std::nullopt;
      }
      return scalar.boolean;
    case ScalarType::text:
      return scalar.text;
    case ScalarType::name:
      if (scalar.text.size() > kMaxNameLength) {
        *problem = "a name of " + std::to_string(scalar.text.size()) + " characters is too long";
        return std::nullopt;
      }
      if (!is_name(scalar.text)) {
        *problem = shown + " is not a valid name";
        return std::nullopt;
      }
      return scalar.text;
    case ScalarType::choice:
      if (std::find(rule.choices.begin(), rule.choices.end(), scalar.text) == rule.choices.end()) {
        *problem = shown + " is not a valid choice";
        if (const auto near = nearest_name(scalar.text, rule.choices)) {
          *problem += " (did you mean '" + *near + "'?)";
        }
        return std::nullopt;
      }
      return scalar.text;
  }
  return std::nullopt;
}

YAML::Node to_yaml(const ParamValue& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return YAML::Node(*text);
  return YAML::Node(format_param_value(value));
}

}  // namespace swarmnet
