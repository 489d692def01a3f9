// Checks every TypeId, attribute and value of a Config before ns-3 sees it. ns-3 ends the
// process (NS_FATAL_ERROR, NS_ABORT_MSG) on an unknown name or a value it cannot parse, even on
// a trailing blank in a number, so nothing reaches it unchecked: a value is parsed here with the
// same stream operations ns-3 uses, then by ns-3's own checker, then held to the bounds of the
// few parameters ns-3 takes unchecked and cannot live with (a zero slot, a zero routing timer),
// and only then handed over, already parsed. Errors are std::runtime_error:
// "ns-3 engine: <type>: attribute <name> = <value>: <why>".
#pragma once

#include <ns3/attribute.h>
#include <ns3/object-factory.h>
#include <ns3/type-id.h>
#include <ns3/wifi-phy-common.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet::ns3engine {

// An attribute whose value has been checked, ready to be set.
struct CheckedAttribute {
  std::string name;
  ns3::Ptr<ns3::AttributeValue> value;
};

// The TypeId `name`, which must exist, be `base` or derive from it and have a constructor.
// `role` says where the name comes from (e.g. "loss_chain[1]").
ns3::TypeId checked_type(const std::string& name, const ns3::TypeId& base, const std::string& role);

// `attribute` checked against `tid`'s attribute of that name. `flag` is how it will be set:
// ns3::TypeId::ATTR_CONSTRUCT (through a factory or helper) or ATTR_SET (on a live object).
CheckedAttribute checked_attribute(const ns3::TypeId& tid, const Attribute& attribute,
                                   std::uint32_t flag);

std::vector<CheckedAttribute> checked_attributes(const ns3::TypeId& tid,
                                                 const std::vector<Attribute>& attributes,
                                                 std::uint32_t flag);

// A factory for `spec`: its type checked against `base`, every attribute against the type.
ns3::ObjectFactory checked_factory(const ObjectSpec& spec, const ns3::TypeId& base,
                                   const std::string& role);

// The modulation class of the Wi-Fi mode named `name` (e.g. "OfdmRate6Mbps"), or nothing if ns-3
// has no such mode.
std::optional<ns3::WifiModulationClass> wifi_mode_class(const std::string& name);

// Throws the error above for `attribute` of `type_name`.
[[noreturn]] void reject_attribute(const std::string& type_name, const Attribute& attribute,
                                   const std::string& why);

}  // namespace swarmnet::ns3engine
