#include "traffic_csv.hpp"

#include <charconv>
#include <fstream>
#include <stdexcept>
#include <string_view>

namespace swarmnet::validation {

namespace {

template <typename Integer>
Integer parse_integer(std::string_view field, const std::string& where) {
  Integer value{};
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc{} || end != field.data() + field.size()) {
    throw std::runtime_error(where + ": '" + std::string(field) + "' is not an integer");
  }
  return value;
}

}  // namespace

std::vector<TrafficMessage> read_traffic_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the traffic schedule");
  std::string line;
  std::getline(in, line);
  if (line.rfind("message_id,step,inject_ns,source,destination,payload_bytes", 0) != 0) {
    throw std::runtime_error(path + ":1: not a SwarmNet traffic schedule (unexpected header)");
  }
  std::vector<TrafficMessage> messages;
  std::size_t line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(line_number);
    std::vector<std::string_view> fields;
    std::string_view rest(line);
    while (true) {
      const std::size_t comma = rest.find(',');
      fields.push_back(rest.substr(0, comma));
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    if (fields.size() != 6) throw std::runtime_error(where + ": expected 6 fields");
    TrafficMessage message;
    message.message_id = parse_integer<std::uint64_t>(fields[0], where);
    message.inject_ns = parse_integer<std::int64_t>(fields[2], where);
    message.source = parse_integer<std::uint32_t>(fields[3], where);
    message.destination = fields[4] == "broadcast" ? kBroadcastDestination
                                                   : parse_integer<std::uint32_t>(fields[4], where);
    message.payload_bytes = parse_integer<std::uint32_t>(fields[5], where);
    messages.push_back(message);
  }
  return messages;
}

}  // namespace swarmnet::validation
