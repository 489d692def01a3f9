#include "protocol/network_report_codec.hpp"

#include "protocol/step_channel.hpp"

namespace swarmnet {

namespace {

// The report record: the type, then every NetworkReport field in declaration order. A list is
// its length and its (name, value) pairs; an optional number is a presence byte and the number.
// One function lists the fields for both measuring and writing, so the two cannot disagree.
template <typename Sink>
void report_fields(const NetworkReport& r, Sink& sink) {
  auto counts = [&sink](const std::vector<NamedCount>& list) {
    sink.put(static_cast<std::uint32_t>(list.size()));
    for (const NamedCount& c : list) sink.put(as_bytes(c.name)).put(c.value);
  };
  auto optional = [&sink](const std::optional<double>& value) {
    sink.put(static_cast<std::uint8_t>(value.has_value())).put(value.value_or(0.0));
  };
  sink.put(RecordType::report).put(r.sent).put(r.delivered);
  counts(r.dropped);
  sink.put(r.broadcast_sent).put(r.broadcast_deliveries).put(r.undelivered).put(r.duplicates);
  sink.put(r.pdr);
  optional(r.delay_mean_s);
  optional(r.delay_p50_s);
  optional(r.delay_p95_s);
  optional(r.hops_mean);
  counts(r.mac);
  counts(r.routing);
  counts(r.arp);
  sink.put(r.events).put(r.network_cpu_s).put(r.transport_cpu_s);
}

// Adds up encoded_bytes() of what report_fields() would write.
struct EncodedSize {
  std::size_t bytes = 0;
  template <typename T>
  EncodedSize& put(const T& value) {
    bytes += encoded_bytes(value);
    return *this;
  }
};

}  // namespace

void encode_report(const NetworkReport& report, std::vector<std::byte>& record) {
  EncodedSize size;
  report_fields(report, size);
  record.assign(size.bytes, std::byte{0});
  RecordWriter writer(record);
  report_fields(report, writer);
}

namespace {

// A report holds a few dozen counters; far more is a corrupt record, not a report.
constexpr std::uint32_t kMaxReportCounters = 4096;

bool decode_counts(RecordReader& reader, std::vector<NamedCount>& list) {
  std::uint32_t count = 0;
  if (!reader.get(count) || count > kMaxReportCounters) return false;
  list.assign(count, NamedCount{});
  for (NamedCount& c : list) {
    std::span<const std::byte> name;
    if (!reader.get_view(name, kMaxTextBytes) || !reader.get(c.value)) return false;
    c.name = as_text(name);
  }
  return true;
}

bool decode_optional(RecordReader& reader, std::optional<double>& value) {
  std::uint8_t present = 0;
  double number = 0.0;
  if (!reader.get(present) || present > 1 || !reader.get(number)) return false;
  value = present == 1 ? std::optional<double>(number) : std::nullopt;
  return true;
}

}  // namespace

bool decode_report(RecordReader& reader, NetworkReport& r) {
  return reader.get(r.sent) && reader.get(r.delivered) && decode_counts(reader, r.dropped) &&
         reader.get(r.broadcast_sent) && reader.get(r.broadcast_deliveries) &&
         reader.get(r.undelivered) && reader.get(r.duplicates) && reader.get(r.pdr) &&
         decode_optional(reader, r.delay_mean_s) && decode_optional(reader, r.delay_p50_s) &&
         decode_optional(reader, r.delay_p95_s) && decode_optional(reader, r.hops_mean) &&
         decode_counts(reader, r.mac) && decode_counts(reader, r.routing) &&
         decode_counts(reader, r.arp) && reader.get(r.events) && reader.get(r.network_cpu_s) &&
         reader.get(r.transport_cpu_s) && reader.at_end();
}

}  // namespace swarmnet
