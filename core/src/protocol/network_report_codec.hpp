// The report record's fields (protocol/network_report.hpp), encoded and decoded in one place.
#pragma once

#include <cstddef>
#include <vector>

#include "protocol/network_report.hpp"
#include "protocol/record_codec.hpp"

namespace swarmnet {

// The whole record, its type first, into `record` (resized to fit).
void encode_report(const NetworkReport& report, std::vector<std::byte>& record);

// The fields after the type; false for a short, long or inconsistent record.
bool decode_report(RecordReader& reader, NetworkReport& report);

}  // namespace swarmnet
