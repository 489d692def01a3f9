#include "ns3_engine/attribute_check.hpp"

#include <ns3/double.h>
#include <ns3/ht-phy.h>
#include <ns3/integer.h>
#include <ns3/nstime.h>
#include <ns3/ofdm-phy.h>
#include <ns3/phy-entity.h>
#include <ns3/string.h>
#include <ns3/tuple.h>
#include <ns3/uinteger.h>
#include <ns3/wifi-mode.h>
#include <ns3/wifi-phy.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace swarmnet::ns3engine {

namespace {

// Longest time accepted. ns-3 keeps time in 64-bit nanoseconds (292 years) and multiplies some
// times (a slot by a contention window, an interval by a hold factor): a week and a half leaves
// room for that, and no timer of a simulation is longer.
constexpr double kMaxTimeS = 1e6;

// Bounds ns-3 does not check and cannot live with. Each was found by trying: a value outside
// ends the process, loops for ever or makes received powers NaN.
struct Bound {
  const char* type = nullptr;
  const char* attribute = nullptr;  // nullptr: every Time attribute of the type (its timers)
  double min = 0.0;
  bool min_inclusive = false;
  double max = std::numeric_limits<double>::infinity();
};

const Bound kBounds[] = {
    {"ns3::LogDistancePropagationLossModel", "ReferenceDistance", 0.0, false},
    {"ns3::FriisPropagationLossModel", "Frequency", 0.0, false},
    {"ns3::FriisPropagationLossModel", "SystemLoss", 0.0, false},
    {"ns3::TwoRayGroundPropagationLossModel", "Frequency", 0.0, false},
    {"ns3::TwoRayGroundPropagationLossModel", "SystemLoss", 0.0, false},
    // Nakagami draws an Erlang variable as a sum of m exponentials, per reception.
    {"ns3::NakagamiPropagationLossModel", "m0", 0.0, false, 1000.0},
    {"ns3::NakagamiPropagationLossModel", "m1", 0.0, false, 1000.0},
    {"ns3::NakagamiPropagationLossModel", "m2", 0.0, false, 1000.0},
    {"ns3::YansWifiPhy", "Slot", 0.0, false},
    {"ns3::YansWifiPhy", "Sifs", 0.0, true},
    {"ns3::YansWifiPhy", "Pifs", 0.0, true},
    {"ns3::QosTxop", "Aifsn", 1.0, true},
    {"ns3::MinstrelWifiManager", "SampleColumn", 1.0, true},
    {"ns3::MinstrelHtWifiManager", "SampleColumn", 1.0, true},
    {"ns3::IdealWifiManager", "BerThreshold", 0.0, false},
    {"ns3::aodv::RoutingProtocol", "NetDiameter", 1.0, true},
    {"ns3::aodv::RoutingProtocol", "MaxQueueLen", 1.0, true},
    {"ns3::aodv::RoutingProtocol", nullptr, 0.0, false},
    {"ns3::olsr::RoutingProtocol", nullptr, 0.0, false},
    {"ns3::dsdv::RoutingProtocol", nullptr, 0.0, false},
};

// A number, time (in seconds) or count as a double; nothing for other values.
std::optional<double> number_of(const ns3::AttributeValue& value) {
  if (const auto* real = dynamic_cast<const ns3::DoubleValue*>(&value)) return real->Get();
  if (const auto* count = dynamic_cast<const ns3::UintegerValue*>(&value)) {
    return static_cast<double>(count->Get());
  }
  if (const auto* integer = dynamic_cast<const ns3::IntegerValue*>(&value)) {
    return static_cast<double>(integer->Get());
  }
  if (const auto* time = dynamic_cast<const ns3::TimeValue*>(&value)) {
    return time->Get().GetSeconds();
  }
  return std::nullopt;
}

// Empty if `value` is within every bound for `type`'s `attribute`; otherwise why not.
std::string why_out_of_bounds(const std::string& type, const std::string& attribute,
                              const ns3::AttributeValue& value) {
  const std::optional<double> number = number_of(value);
  if (!number) return {};
  const bool time = dynamic_cast<const ns3::TimeValue*>(&value) != nullptr;
  const char* unit = time ? " s" : "";
  for (const Bound& bound : kBounds) {
    if (type != bound.type) continue;
    if (bound.attribute == nullptr ? !time : attribute != bound.attribute) continue;
    std::ostringstream why;
    if (bound.min_inclusive ? *number < bound.min : *number <= bound.min) {
      why << "must be " << (bound.min_inclusive ? "at least " : "more than ") << bound.min << unit;
    } else if (*number > bound.max) {
      why << "must be at most " << bound.max << unit;
    }
    if (!why.str().empty()) return why.str();
  }
  return {};
}

bool one_token(const std::string& text) {
  return !text.empty() && std::none_of(text.begin(), text.end(),
                                       [](unsigned char c) { return std::isspace(c) != 0; });
}

// What ns-3's ATTRIBUTE_VALUE_IMPLEMENT does with `text` ("iss >> value", then it aborts unless
// the stream reached its end): true when that takes the whole text and succeeds.
template <typename T>
bool streams_whole(const std::string& text) {
  std::istringstream in(text);
  T value{};
  in >> value;
  return in.eof() && !in.fail();
}

// A number followed by a unit from `units` (any unit if `units` is empty), as Time, QueueSize and
// DataRate parse it: the number is the longest prefix made of `number_chars`.
bool number_with_unit(const std::string& text, const char* number_chars,
                      const std::vector<std::string>& units, bool unit_required) {
  const std::size_t end = text.find_first_not_of(number_chars);
  const std::string number = text.substr(0, end);
  const std::string unit = end == std::string::npos ? std::string() : text.substr(end);
  if (number.empty() || !streams_whole<double>(number)) return false;
  if (unit.empty()) return !unit_required;
  return units.empty() || std::find(units.begin(), units.end(), unit) != units.end();
}

// Time's parser: a number, then a unit or none (seconds). Beyond about 292 years its 64-bit
// nanoseconds overflow, and a timer that long is a mistake anyway.
std::string why_not_a_time(const std::string& text) {
  static const std::map<std::string, double> kSeconds = {
      {"", 1.0},     {"s", 1.0},     {"ms", 1e-3},          {"us", 1e-6},
      {"ns", 1e-9},  {"ps", 1e-12},  {"fs", 1e-15},         {"min", 60.0},
      {"h", 3600.0}, {"d", 86400.0}, {"y", 365.0 * 86400.0}};
  const std::size_t end = text.find_first_not_of("+-0123456789.eE");
  const std::string number = text.substr(0, end);
  const auto unit = kSeconds.find(end == std::string::npos ? std::string() : text.substr(end));
  if (number.empty() || !streams_whole<double>(number) || unit == kSeconds.end()) {
    return "expected a time such as 0.5s or 200ms";
  }
  if (std::abs(std::stod(number) * unit->second) > kMaxTimeS) {
    return "longer than the engine allows (1e6 s)";
  }
  return {};
}

bool enum_has(const ns3::AttributeChecker& checker, const std::string& name) {
  std::istringstream names(checker.GetUnderlyingTypeInformation());  // "a|b|c"
  for (std::string each; std::getline(names, each, '|');) {
    if (each == name) return true;
  }
  return false;
}

// The checker's value type without namespace: ns-3 names some "ns3::DoubleValue", others made
// by ATTRIBUTE_HELPER_CPP "WifiModeValue".
std::string value_type(const ns3::AttributeChecker& checker) {
  std::string type = checker.GetValueTypeName();
  if (type.rfind("ns3::", 0) == 0) type.erase(0, 5);
  return type;
}

std::string why_unparsable(const std::string& text, ns3::Ptr<const ns3::AttributeChecker> checker);

// TupleValue::DeserializeFromString: "{a, b, ...}", each element parsed by its own checker.
std::string why_tuple_unparsable(std::string text, const ns3::TupleChecker& checker) {
  const auto& elements = checker.GetCheckers();
  if (text.empty() || text.front() != '{' || text.back() != '}') {
    return "expected {" + std::to_string(elements.size()) + " comma-separated values}";
  }
  text = text.substr(1, text.size() - 2);
  std::replace(text.begin(), text.end(), ',', ' ');
  std::istringstream in(text);
  std::size_t index = 0;
  for (std::string element; in >> element; ++index) {
    if (index >= elements.size()) break;
    const std::string why = why_unparsable(element, elements[index]);
    if (!why.empty()) {
      return "element " + std::to_string(index + 1) + " (" + element + "): " + why;  // NOLINT
    }
  }
  if (index != elements.size()) {
    return "expected " + std::to_string(elements.size()) + " values in the braces";
  }
  return {};
}

// Empty if ns-3 can parse `text` for `checker` without aborting; otherwise why not.
std::string why_unparsable(const std::string& text, ns3::Ptr<const ns3::AttributeChecker> checker) {
  if (const auto tuple = ns3::DynamicCast<const ns3::TupleChecker>(checker)) {
    return why_tuple_unparsable(text, *tuple);
  }
  const std::string type = value_type(*checker);
  if (type == "StringValue") return {};
  if (!one_token(text)) return "expected one word, without blanks";
  if (type == "BooleanValue") {
    return text == "true" || text == "false" || text == "1" || text == "0" || text == "t" ||
                   text == "f"
               ? std::string()
               : "expected true or false";
  }
  if (type == "EnumValue") {
    return enum_has(*checker, text) ? std::string()
                                    : "expected one of " + checker->GetUnderlyingTypeInformation();
  }
  if (type == "DoubleValue") return streams_whole<double>(text) ? "" : "expected a number";
  if (type == "IntegerValue") {
    return streams_whole<std::int64_t>(text) ? "" : "expected an integer";
  }
  if (type == "UintegerValue") {
    return text.front() != '-' && streams_whole<std::uint64_t>(text)
               ? ""
               : "expected a non-negative integer";
  }
  if (type == "TimeValue") return why_not_a_time(text);
  if (type == "QueueSizeValue") {
    return number_with_unit(
               text, "0123456789.",
               {"B", "kB", "KB", "KiB", "MB", "MiB", "p", "kp", "Kp", "Kip", "Mp", "Mip"}, true)
               ? ""
               : "expected a queue size such as 100p or 64KB";
  }
  if (type == "DataRateValue") {
    // DataRate's own parser refuses an unknown unit safely; an empty number it would not.
    return number_with_unit(text, "0123456789.", {}, true) ? ""
                                                           : "expected a data rate such as 6Mbps";
  }
  if (type == "WifiModeValue") {
    return wifi_mode_class(text) ? "" : "no Wi-Fi mode of that name (e.g. OfdmRate6Mbps)";
  }
  return "the engine cannot check values of type " + type + " and does not set them";
}

std::string type_name(const ns3::TypeId& tid) { return tid.GetName(); }

}  // namespace

void reject_attribute(const std::string& type_name, const Attribute& attribute,
                      const std::string& why) {
  throw std::runtime_error("ns-3 engine: " + type_name + ": attribute " + attribute.name + " = " +
                           attribute.value + ": " + why);
}

ns3::TypeId checked_type(const std::string& name, const ns3::TypeId& base,
                         const std::string& role) {
  ns3::TypeId tid;
  if (!ns3::TypeId::LookupByNameFailSafe(name, &tid)) {
    throw std::runtime_error("ns-3 engine: " + name + ": no such TypeId (" + role + ")");
  }
  if (tid != base && !tid.IsChildOf(base)) {
    throw std::runtime_error("ns-3 engine: " + name + ": not a " + base.GetName() + " (" + role +
                             ")");
  }
  if (!tid.HasConstructor()) {
    throw std::runtime_error("ns-3 engine: " + name + ": has no constructor (" + role + ")");
  }
  return tid;
}

CheckedAttribute checked_attribute(const ns3::TypeId& tid, const Attribute& attribute,
                                   std::uint32_t flag) {
  ns3::TypeId::AttributeInformation info;
  if (attribute.name.empty() || !tid.LookupAttributeByName(attribute.name, &info)) {
    reject_attribute(type_name(tid), attribute, "no such attribute");
  }
  // ns-3 skips a construction value it has no setter for, silently: refuse it here.
  if ((info.flags & flag) == 0 || !info.accessor->HasSetter()) {
    reject_attribute(type_name(tid), attribute,
                     flag == ns3::TypeId::ATTR_SET ? "cannot be set on a live object"
                                                   : "cannot be set at construction");
  }
  const std::string why = why_unparsable(attribute.value, info.checker);
  if (!why.empty()) reject_attribute(type_name(tid), attribute, why);
  ns3::Ptr<ns3::AttributeValue> value =
      info.checker->CreateValidValue(ns3::StringValue(attribute.value));
  if (!value) {
    const std::string range = info.checker->GetUnderlyingTypeInformation();
    reject_attribute(type_name(tid), attribute,
                     "not a valid " + info.checker->GetValueTypeName() +
                         (range.empty() ? std::string() : " (" + range + ")"));
  }
  const std::string why_out = why_out_of_bounds(type_name(tid), attribute.name, *value);
  if (!why_out.empty()) reject_attribute(type_name(tid), attribute, why_out);
  return {attribute.name, value};
}

std::vector<CheckedAttribute> checked_attributes(const ns3::TypeId& tid,
                                                 const std::vector<Attribute>& attributes,
                                                 std::uint32_t flag) {
  std::vector<CheckedAttribute> checked;
  checked.reserve(attributes.size());
  for (const Attribute& attribute : attributes) {
    checked.push_back(checked_attribute(tid, attribute, flag));
  }
  return checked;
}

ns3::ObjectFactory checked_factory(const ObjectSpec& spec, const ns3::TypeId& base,
                                   const std::string& role) {
  const ns3::TypeId tid = checked_type(spec.type_id, base, role);
  ns3::ObjectFactory factory;
  factory.SetTypeId(tid);
  for (const CheckedAttribute& attribute :
       checked_attributes(tid, spec.attributes, ns3::TypeId::ATTR_CONSTRUCT)) {
    factory.Set(attribute.name, *attribute.value);
  }
  return factory;
}

std::optional<ns3::WifiModulationClass> wifi_mode_class(const std::string& name) {
  // Every mode ns-3.37 defines, from its PHY entities (WifiMode's own lookup by name aborts on
  // an unknown one). HT's static entity lists one spatial stream's MCSs, the 10 and 5 MHz OFDM
  // modes belong to no static entity: both are added by hand.
  static const std::map<std::string, ns3::WifiModulationClass> modes = [] {
    std::map<std::string, ns3::WifiModulationClass> all;
    const auto add = [&all](const ns3::WifiMode& mode) {
      all.emplace(mode.GetUniqueName(), mode.GetModulationClass());
    };
    for (const ns3::WifiModulationClass modulation :
         {ns3::WIFI_MOD_CLASS_DSSS, ns3::WIFI_MOD_CLASS_HR_DSSS, ns3::WIFI_MOD_CLASS_ERP_OFDM,
          ns3::WIFI_MOD_CLASS_OFDM, ns3::WIFI_MOD_CLASS_HT, ns3::WIFI_MOD_CLASS_VHT,
          ns3::WIFI_MOD_CLASS_HE, ns3::WIFI_MOD_CLASS_EHT}) {
      const ns3::Ptr<const ns3::PhyEntity> entity = ns3::WifiPhy::GetStaticPhyEntity(modulation);
      for (auto mode = entity->begin(); mode != entity->end(); ++mode) add(*mode);
    }
    for (std::uint8_t mcs = 0; mcs < 32; ++mcs) add(ns3::HtPhy::GetHtMcs(mcs));
    for (const ns3::WifiMode& mode :
         {ns3::OfdmPhy::GetOfdmRate3MbpsBW10MHz(), ns3::OfdmPhy::GetOfdmRate4_5MbpsBW10MHz(),
          ns3::OfdmPhy::GetOfdmRate6MbpsBW10MHz(), ns3::OfdmPhy::GetOfdmRate9MbpsBW10MHz(),
          ns3::OfdmPhy::GetOfdmRate12MbpsBW10MHz(), ns3::OfdmPhy::GetOfdmRate18MbpsBW10MHz(),
          ns3::OfdmPhy::GetOfdmRate24MbpsBW10MHz(), ns3::OfdmPhy::GetOfdmRate27MbpsBW10MHz(),
          ns3::OfdmPhy::GetOfdmRate1_5MbpsBW5MHz(), ns3::OfdmPhy::GetOfdmRate2_25MbpsBW5MHz(),
          ns3::OfdmPhy::GetOfdmRate3MbpsBW5MHz(), ns3::OfdmPhy::GetOfdmRate4_5MbpsBW5MHz(),
          ns3::OfdmPhy::GetOfdmRate6MbpsBW5MHz(), ns3::OfdmPhy::GetOfdmRate9MbpsBW5MHz(),
          ns3::OfdmPhy::GetOfdmRate12MbpsBW5MHz(), ns3::OfdmPhy::GetOfdmRate13_5MbpsBW5MHz()}) {
      add(mode);
    }
    return all;
  }();
  const auto found = modes.find(name);
  if (found == modes.end()) return std::nullopt;
  return found->second;
}

}  // namespace swarmnet::ns3engine
