#include "viewer/view_data.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "outputs/headings_trace.hpp"
#include "outputs/output_files.hpp"
#include "outputs/positions_trace.hpp"
#include "outputs/run_error.hpp"

namespace swarmnet {

static_assert(std::endian::native == std::endian::little,
              "the viewer reads the traces' little-endian numbers in place");

namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const fs::path& file, const std::string& what) {
  throw RunError(file.string() + ": " + what);
}

// Arrays appended to the blob, each aligned to 4 bytes, and named in meta.arrays.
class BlobWriter {
 public:
  template <typename T>
  void add(const char* name, const std::vector<T>& values, const char* type) {
    while (bytes_.size() % 4 != 0) bytes_.push_back(0);
    const std::size_t offset = bytes_.size();
    bytes_.resize(offset + values.size() * sizeof(T));
    if (!values.empty())
      std::memcpy(bytes_.data() + offset, values.data(), values.size() * sizeof(T));
    arrays_[name] = {offset, values.size(), type};
  }
  nlohmann::ordered_json& arrays() { return arrays_; }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
  nlohmann::ordered_json arrays_ = nlohmann::ordered_json::object();
};

// Splits one CSV line into fields. A quoted field (SwarmNet quotes names that hold a comma or a
// quote, as RFC 4180 does) is unquoted in place, so every view points into `line`.
void split(std::string& line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t write = 0;
  std::size_t read = 0;
  while (true) {
    const std::size_t start = write;
    if (read < line.size() && line[read] == '"') {
      ++read;
      while (read < line.size()) {
        if (line[read] == '"') {
          if (read + 1 < line.size() && line[read + 1] == '"') {
            line[write++] = '"';
            read += 2;
            continue;
          }
          ++read;
          break;
        }
        line[write++] = line[read++];
      }
    }
    while (read < line.size() && line[read] != ',') line[write++] = line[read++];
    fields.emplace_back(line.data() + start, write - start);
    if (read >= line.size()) return;
    ++read;  // the comma
  }
}

template <typename T>
std::optional<T> parse_number(std::string_view text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || rest != end) return std::nullopt;
  return value;
}

// A CSV file read line by line, with its header checked; errors name the file and the line.
class CsvReader {
 public:
  CsvReader(fs::path path, std::string_view header) : path_(std::move(path)), in_(path_) {
    if (!in_) refuse(path_, "cannot be opened");
    std::string first;
    if (!std::getline(in_, first))
      refuse(path_, "is empty; expected the header line " + std::string(header));
    if (first != header) {
      refuse(path_,
             "line 1: unexpected header '" + first + "'; expected '" + std::string(header) + "'");
    }
  }
  // The next line's fields; false at the end of the file.
  bool next(std::vector<std::string_view>& fields, std::size_t expected) {
    if (!std::getline(in_, line_)) return false;
    ++line_number_;
    split(line_, fields);
    if (fields.size() != expected) {
      fail("has " + std::to_string(fields.size()) + " fields; expected " +
           std::to_string(expected));
    }
    return true;
  }
  template <typename T>
  T number(std::string_view text, const char* what) {
    const auto value = parse_number<T>(text);
    if (!value) fail(std::string(what) + " '" + std::string(text) + "' is not a number");
    return *value;
  }
  [[noreturn]] void fail(const std::string& what) const {
    refuse(path_, "line " + std::to_string(line_number_) + ": " + what);
  }

 private:
  fs::path path_;
  std::ifstream in_;
  std::string line_;
  std::size_t line_number_ = 1;
};

struct Scene {
  std::string name;
  double width_m = 0.0;
  double height_m = 0.0;
  double robot_radius_m = 0.0;
  double step_s = 0.0;
  double link_range_m = 0.0;  // 0: none stated
  nlohmann::ordered_json obstacles = nlohmann::ordered_json::array();
  nlohmann::ordered_json movables = nlohmann::ordered_json::array();
};

double yaml_real(const YAML::Node& node, const char* key, const fs::path& file, double fallback) {
  const YAML::Node value = node[key];
  if (!value) return fallback;
  try {
    return value.as<double>();
  } catch (const YAML::Exception&) {
    refuse(file, std::string("key ") + key + " is not a number");
  }
}

Scene read_scene(const fs::path& file) {
  if (!fs::is_regular_file(file)) refuse(file, "is missing (is this a SwarmNet run directory?)");
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::Exception& error) {
    refuse(file, std::string("not valid YAML: ") + error.what());
  }
  if (!root.IsMap() || !root["arena"] || !root["robots"]) {
    refuse(file, "holds no arena or robots; expected a resolved scenario");
  }
  Scene scene;
  scene.name = root["name"] ? root["name"].as<std::string>() : std::string("run");
  const YAML::Node arena = root["arena"];
  scene.width_m = yaml_real(arena, "width_m", file, 0.0);
  scene.height_m = yaml_real(arena, "height_m", file, 0.0);
  if (!(scene.width_m > 0.0) || !(scene.height_m > 0.0)) {
    refuse(file, "arena.width_m and arena.height_m must be positive");
  }
  scene.robot_radius_m = yaml_real(root["robots"], "radius_m", file, 0.1);
  scene.step_s = yaml_real(root, "step_s", file, 0.1);
  if (const YAML::Node obstacles = arena["obstacles"]; obstacles && obstacles.IsSequence()) {
    for (const YAML::Node& o : obstacles) {
      scene.obstacles.push_back(
          {yaml_real(o, "x_min_m", file, 0.0), yaml_real(o, "y_min_m", file, 0.0),
           yaml_real(o, "x_max_m", file, 0.0), yaml_real(o, "y_max_m", file, 0.0)});
    }
  }
  if (const YAML::Node objects = arena["objects"]; objects && objects.IsSequence()) {
    for (const YAML::Node& o : objects) {
      const std::string shape = o["shape"] ? o["shape"].as<std::string>() : "box";
      scene.movables.push_back({{"shape", shape},
                                {"size_x_m", yaml_real(o, "size_x_m", file, 0.0)},
                                {"size_y_m", yaml_real(o, "size_y_m", file, 0.0)},
                                {"radius_m", yaml_real(o, "radius_m", file, 0.0)},
                                {"x_m", yaml_real(o, "x_m", file, 0.0)},
                                {"y_m", yaml_real(o, "y_m", file, 0.0)},
                                {"heading_rad", yaml_real(o, "heading_rad", file, 0.0)}});
    }
  }
  // The nominal radio range, when a propagation model states one (disk, range: params.range_m):
  // what the page's links are drawn within.
  if (const YAML::Node network = root["network"]; network && network["propagation"]) {
    for (const YAML::Node& model : network["propagation"]) {
      if (model["params"] && model["params"]["range_m"]) {
        scene.link_range_m = yaml_real(model["params"], "range_m", file, 0.0);
        break;
      }
    }
  }
  return scene;
}

nlohmann::ordered_json read_summary(const fs::path& file) {
  std::ifstream in(file);
  if (!in) refuse(file, "is missing: the run did not finish (or this is no run directory)");
  try {
    nlohmann::ordered_json summary = nlohmann::ordered_json::parse(in);
    if (!summary.is_object() || !summary.contains("robots")) refuse(file, "holds no 'robots'");
    return summary;
  } catch (const nlohmann::json::exception& error) {
    refuse(file, std::string("not valid JSON: ") + error.what());
  }
}

// positions.bin's header, checked against the file's length (outputs/positions_trace.hpp).
struct PositionsHeader {
  std::uint32_t robots = 0;
  std::uint64_t steps = 0;
  std::int64_t step_ns = 0;
};

PositionsHeader read_positions_header(std::ifstream& in, const fs::path& file) {
  char header[kPositionsHeaderBytes];
  if (!in.read(header, sizeof header))
    refuse(file, "is truncated: shorter than its 32-byte header");
  if (std::memcmp(header, "SNPOS\0\0\0", 8) != 0)
    refuse(file, "is not a positions trace (bad magic)");
  std::uint32_t version = 0;
  PositionsHeader h;
  std::memcpy(&version, header + 8, 4);
  std::memcpy(&h.robots, header + 12, 4);
  std::memcpy(&h.steps, header + 16, 8);
  std::memcpy(&h.step_ns, header + 24, 8);
  if (version != kPositionsTraceVersion) {
    refuse(file, "version " + std::to_string(version) + "; this viewer reads version " +
                     std::to_string(kPositionsTraceVersion));
  }
  if (h.robots == 0 || h.steps == 0 || h.step_ns <= 0) refuse(file, "holds no robots or no steps");
  const std::uintmax_t expected = kPositionsHeaderBytes + h.steps * h.robots * 16ULL;
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec || size != expected) {
    refuse(file, "is " + std::to_string(size) + " bytes long; its header (" +
                     std::to_string(h.robots) + " robots, " + std::to_string(h.steps) +
                     " steps) needs " + std::to_string(expected) + " (truncated?)");
  }
  return h;
}

// headings.bin (outputs/headings_trace.hpp), opened and checked against positions.bin's shape;
// nullopt when the run has none (written before it existed).
std::optional<std::ifstream> open_headings(const fs::path& file, const PositionsHeader& positions) {
  if (!fs::exists(file)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  char header[kHeadingsHeaderBytes];
  if (!in.read(header, sizeof header))
    refuse(file, "is truncated: shorter than its 32-byte header");
  if (std::memcmp(header, "SNHDG\0\0\0", 8) != 0)
    refuse(file, "is not a headings trace (bad magic)");
  std::uint32_t version = 0;
  std::uint32_t robots = 0;
  std::uint64_t steps = 0;
  std::memcpy(&version, header + 8, 4);
  std::memcpy(&robots, header + 12, 4);
  std::memcpy(&steps, header + 16, 8);
  if (version != kHeadingsTraceVersion)
    refuse(file, "version " + std::to_string(version) + "; expected 1");
  if (robots != positions.robots || steps != positions.steps) {
    refuse(file, "holds " + std::to_string(robots) + " robots x " + std::to_string(steps) +
                     " steps; positions.bin holds " + std::to_string(positions.robots) + " x " +
                     std::to_string(positions.steps));
  }
  std::error_code ec;
  const std::uintmax_t expected = kHeadingsHeaderBytes + steps * robots;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec || size != expected) {
    refuse(file, "is " + std::to_string(size) + " bytes long; its header needs " +
                     std::to_string(expected) + " (truncated?)");
  }
  return in;
}

std::uint16_t quantize(double value, double extent) {
  const double q = std::round(value / extent * 65535.0);
  return static_cast<std::uint16_t>(std::clamp(std::isfinite(q) ? q : 0.0, 0.0, 65535.0));
}

std::uint8_t motion_heading(double x, double y) {
  double a = std::atan2(y, x);
  if (a < 0) a += 2.0 * std::numbers::pi;
  return static_cast<std::uint8_t>(
      static_cast<int>(std::lround(a * 256.0 / (2.0 * std::numbers::pi))) & 255);
}

// Labels to small indices, in order of first appearance; index 0 is "" (none).
class LabelTable {
 public:
  LabelTable() { index(""); }
  std::uint16_t index(std::string_view label) {
    const auto it = indices_.find(label);
    if (it != indices_.end()) return it->second;
    const auto i = static_cast<std::uint16_t>(labels_.size());
    labels_.emplace_back(label);
    indices_.emplace(std::string(label), i);
    return i;
  }
  [[nodiscard]] const std::vector<std::string>& labels() const { return labels_; }

 private:
  std::vector<std::string> labels_;
  std::map<std::string, std::uint16_t, std::less<>> indices_;
};

struct RobotStateChange {
  std::int64_t time_ns;
  std::uint32_t robot;
  std::uint16_t state;
};

struct ObjectRows {
  std::vector<float> t, x, y, r;
  std::vector<std::uint32_t> id;
  std::vector<std::uint16_t> kind, state;
};

constexpr std::string_view kViewStatesHeader = "time_ns,entity,id,kind,state,x_m,y_m,radius_m";

void read_view_states(const fs::path& file, std::uint32_t robots, LabelTable& states,
                      LabelTable& kinds, std::vector<RobotStateChange>& changes,
                      ObjectRows& objects) {
  CsvReader csv(file, kViewStatesHeader);
  std::vector<std::string_view> f;
  while (csv.next(f, 8)) {
    const auto time_ns = csv.number<std::int64_t>(f[0], "time_ns");
    const auto id = csv.number<std::uint32_t>(f[2], "id");
    if (f[1] == "robot") {
      if (id >= robots)
        csv.fail("robot " + std::to_string(id) + " is not one of the " + std::to_string(robots));
      changes.push_back({time_ns, id, states.index(f[4])});
    } else if (f[1] == "object" || f[1] == "hidden") {
      const bool shown = f[1] == "object";
      objects.t.push_back(static_cast<float>(static_cast<double>(time_ns) * 1e-9));
      objects.id.push_back(id);
      objects.kind.push_back(shown ? kinds.index(f[3]) : 0);
      objects.state.push_back(shown ? states.index(f[4]) : 65535);
      objects.x.push_back(shown ? static_cast<float>(csv.number<double>(f[5], "x_m")) : 0.0F);
      objects.y.push_back(shown ? static_cast<float>(csv.number<double>(f[6], "y_m")) : 0.0F);
      objects.r.push_back(shown ? static_cast<float>(csv.number<double>(f[7], "radius_m")) : 0.0F);
    } else {
      csv.fail("entity '" + std::string(f[1]) + "'; expected robot, object or hidden");
    }
  }
}

// Packet events of data messages, with the previous hop inferred; the panel's figures.
struct PacketData {
  std::vector<float> t;
  std::vector<std::uint32_t> from, to;
  std::vector<std::uint8_t> kind, reason;
  std::vector<std::string> reasons;
  std::vector<std::uint32_t> sent, received, forwarded, dropped;  // per robot
  std::size_t kept_every = 1;
  std::size_t lines = 0;
};

struct Transmitter {
  std::uint32_t node;
  std::uint32_t hops;
};

constexpr std::string_view kPacketsHeader =
    "time_ns,event,node,uid,message_id,source,destination,hops,bytes,detail";

// Robot positions at the kept frames (quantized), for inferring a copy's previous hop: the
// flooding case, where several relays at hops - 1 could have sent the copy a node received.
struct FramePositions {
  const std::vector<std::uint16_t>* pos = nullptr;
  std::uint32_t robots = 0;
  std::size_t frames = 0;
  double frame_s = 1.0;

  // Quantized units: both axes scaled alike would be better, but nearness within a few radio
  // ranges is all that is asked.
  void at(double t_s, std::uint32_t node, double& x, double& y) const {
    const auto frame =
        std::min(frames - 1, static_cast<std::size_t>(std::max(0.0, t_s / frame_s + 0.5)));
    x = (*pos)[(frame * robots + node) * 2];
    y = (*pos)[(frame * robots + node) * 2 + 1];
  }
};

// Reads positions.bin one step at a time.
class PositionsStream {
 public:
  explicit PositionsStream(const fs::path& file) : file_(file), in_(file, std::ios::binary) {
    if (!in_) refuse(file, "is missing (was output.mobility_trace off?)");
    header_ = read_positions_header(in_, file);
  }
  [[nodiscard]] const PositionsHeader& header() const { return header_; }
  // Reads the next step into `out` (robots * 2 doubles).
  void next(std::vector<double>& out) {
    out.resize(static_cast<std::size_t>(header_.robots) * 2);
    if (!in_.read(reinterpret_cast<char*>(out.data()),
                  static_cast<std::streamsize>(out.size() * 8))) {
      refuse(file_, "could not be read to its end (truncated while reading?)");
    }
  }

 private:
  fs::path file_;
  std::ifstream in_;
  PositionsHeader header_;
};

PacketData read_packets(const fs::path& file, std::uint32_t robots, double step_s,
                        double duration_s, const FramePositions& positions,
                        const ViewLimits& limits, nlohmann::ordered_json& panel) {
  PacketData data;
  data.sent.assign(robots, 0);
  data.received.assign(robots, 0);
  data.forwarded.assign(robots, 0);
  data.dropped.assign(robots, 0);
  // The panel: messages sent per interval, how many reached a destination, their mean delay.
  const double bin_s = std::max(step_s, duration_s / 200.0);
  const std::size_t bins = static_cast<std::size_t>(std::ceil(duration_s / bin_s)) + 1;
  std::vector<double> sent_per_bin(bins, 0.0), delivered_per_bin(bins, 0.0), delay_sum(bins, 0.0);
  struct Message {
    std::int64_t sent_ns;
    bool delivered;
  };
  std::unordered_map<std::uint64_t, Message> messages;
  std::unordered_map<std::uint64_t, std::vector<Transmitter>> transmitters;  // by uid
  std::map<std::string, std::uint8_t, std::less<>> reason_index;

  struct Row {
    float t;
    std::uint32_t from, to;
    std::uint8_t kind, reason;
  };
  std::vector<Row> rows;

  CsvReader csv(file, kPacketsHeader);
  std::vector<std::string_view> f;
  const auto bin_of = [&](std::int64_t ns) {
    return std::min(bins - 1, static_cast<std::size_t>(static_cast<double>(ns) * 1e-9 / bin_s));
  };
  while (csv.next(f, 10)) {
    ++data.lines;
    if (f[4].empty()) continue;  // a control packet of the routing protocol
    const auto time_ns = csv.number<std::int64_t>(f[0], "time_ns");
    const auto node = csv.number<std::uint32_t>(f[2], "node");
    const auto uid = csv.number<std::uint64_t>(f[3], "uid");
    const auto message = csv.number<std::uint64_t>(f[4], "message_id");
    const auto source = csv.number<std::uint32_t>(f[5], "source");
    const auto hops = csv.number<std::uint32_t>(f[7], "hops");
    if (node >= robots || source >= robots) {
      csv.fail("node " + std::to_string(std::max(node, source)) + " is not one of the " +
               std::to_string(robots) + " robots of positions.bin");
    }
    const float t = static_cast<float>(static_cast<double>(time_ns) * 1e-9);
    auto previous_hop = [&]() -> std::uint32_t {
      const auto it = transmitters.find(uid);
      if (it == transmitters.end()) return source;
      double nx = 0, ny = 0;
      positions.at(t, node, nx, ny);
      std::uint32_t best = source;
      double best_d = INFINITY;
      for (const Transmitter& c : it->second) {
        if (c.hops + 1 != hops || c.node == node) continue;
        double cx = 0, cy = 0;
        positions.at(t, c.node, cx, cy);
        const double d = (cx - nx) * (cx - nx) + (cy - ny) * (cy - ny);
        if (d < best_d) {
          best_d = d;
          best = c.node;
        }
      }
      return best;
    };
    auto remember = [&]() {
      auto& list = transmitters[uid];
      if (list.size() < 64) list.push_back({node, hops});
    };
    if (f[1] == "send") {
      ++data.sent[node];
      sent_per_bin[bin_of(time_ns)] += 1.0;
      messages.emplace(message, Message{time_ns, false});
      remember();
      rows.push_back({t, node, node, 0, 0});
    } else if (f[1] == "forward") {
      ++data.forwarded[node];
      rows.push_back({t, previous_hop(), node, 1, 0});
      remember();
    } else if (f[1] == "deliver") {
      ++data.received[node];
      if (auto it = messages.find(message); it != messages.end() && !it->second.delivered) {
        it->second.delivered = true;
        const std::size_t b = bin_of(it->second.sent_ns);
        delivered_per_bin[b] += 1.0;
        delay_sum[b] += static_cast<double>(time_ns - it->second.sent_ns) * 1e-9;
      }
      rows.push_back({t, previous_hop(), node, 2, 0});
    } else if (f[1] == "drop") {
      ++data.dropped[node];
      auto [it, added] = reason_index.try_emplace(std::string(f[9]),
                                                  static_cast<std::uint8_t>(reason_index.size()));
      if (added) data.reasons.emplace_back(f[9]);
      rows.push_back({t, node, node, 3, it->second});
    } else {
      csv.fail("event '" + std::string(f[1]) + "'; expected send, forward, deliver or drop");
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.t < b.t; });
  data.kept_every = rows.size() > limits.packet_events
                        ? (rows.size() + limits.packet_events - 1) / limits.packet_events
                        : 1;
  for (std::size_t i = 0; i < rows.size(); i += data.kept_every) {
    data.t.push_back(rows[i].t);
    data.from.push_back(rows[i].from);
    data.to.push_back(rows[i].to);
    data.kind.push_back(rows[i].kind);
    data.reason.push_back(rows[i].reason);
  }
  nlohmann::ordered_json ratio = nlohmann::ordered_json::array();
  nlohmann::ordered_json delay = nlohmann::ordered_json::array();
  nlohmann::ordered_json sent = nlohmann::ordered_json::array();
  for (std::size_t b = 0; b < bins; ++b) {
    sent.push_back(sent_per_bin[b]);
    ratio.push_back(sent_per_bin[b] > 0
                        ? nlohmann::ordered_json(delivered_per_bin[b] / sent_per_bin[b])
                        : nullptr);
    delay.push_back(delivered_per_bin[b] > 0
                        ? nlohmann::ordered_json(delay_sum[b] / delivered_per_bin[b])
                        : nullptr);
  }
  panel = {{"bin_s", bin_s}, {"sent", sent}, {"delivery_ratio", ratio}, {"delay_s", delay}};
  return data;
}

constexpr std::string_view kObjectsHeader = "step,time_ns,object,x_m,y_m,heading_rad";

std::vector<float> read_movables(const fs::path& file, std::size_t movables, std::uint64_t stride,
                                 std::size_t frames) {
  std::vector<float> out(frames * movables * 3, 0.0F);
  CsvReader csv(file, kObjectsHeader);
  std::vector<std::string_view> f;
  while (csv.next(f, 6)) {
    const auto step = csv.number<std::uint64_t>(f[0], "step");
    const auto object = csv.number<std::size_t>(f[2], "object");
    if (object >= movables)
      csv.fail("object " + std::to_string(object) + " is not in the scenario");
    if (step % stride != 0 || step / stride >= frames) continue;
    float* at = &out[((step / stride) * movables + object) * 3];
    at[0] = static_cast<float>(csv.number<double>(f[3], "x_m"));
    at[1] = static_cast<float>(csv.number<double>(f[4], "y_m"));
    at[2] = static_cast<float>(csv.number<double>(f[5], "heading_rad"));
  }
  return out;
}

}  // namespace

constexpr std::string_view kSeriesHeader = "time_ns,robot,series,value";

// series.csv (what plugins sampled) for the panel's chart: each series' samples in time bins,
// as the mean, least and greatest value in each bin over every robot that sampled it (null where
// none did). A world's series (no robot) is its own series, named "NAME (world)". Series in name
// order; beyond `max_series`, the rest are counted, not kept.
nlohmann::ordered_json read_series(const fs::path& file, double duration_s,
                                   std::size_t max_series) {
  constexpr std::size_t kBins = 200;
  struct Bins {
    std::vector<double> sum, low, high;
    std::vector<std::uint64_t> count;
  };
  const double bin_s = std::max(duration_s, 1e-9) / static_cast<double>(kBins);
  std::map<std::string, Bins, std::less<>> series;
  CsvReader csv(file, kSeriesHeader);
  std::vector<std::string_view> f;
  std::string name;
  while (csv.next(f, 4)) {
    const auto time_ns = csv.number<std::int64_t>(f[0], "time_ns");
    if (!f[1].empty()) (void)csv.number<std::uint32_t>(f[1], "robot");
    const auto value = csv.number<double>(f[3], "value");
    name.assign(f[2]);
    if (f[1].empty()) name += " (world)";
    auto it = series.find(name);
    if (it == series.end()) {
      it = series.emplace(name, Bins{}).first;
      it->second.sum.assign(kBins, 0.0);
      it->second.low.assign(kBins, std::numeric_limits<double>::infinity());
      it->second.high.assign(kBins, -std::numeric_limits<double>::infinity());
      it->second.count.assign(kBins, 0);
    }
    const double t = static_cast<double>(time_ns) * 1e-9;
    const auto bin = std::min(kBins - 1, static_cast<std::size_t>(std::max(0.0, t / bin_s)));
    Bins& b = it->second;
    b.sum[bin] += value;
    b.low[bin] = std::min(b.low[bin], value);
    b.high[bin] = std::max(b.high[bin], value);
    ++b.count[bin];
  }
  nlohmann::ordered_json kept = nlohmann::ordered_json::array();
  for (const auto& [label, b] : series) {
    if (kept.size() == max_series) break;
    nlohmann::ordered_json mean = nlohmann::ordered_json::array();
    nlohmann::ordered_json low = nlohmann::ordered_json::array();
    nlohmann::ordered_json high = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < kBins; ++i) {
      if (b.count[i] == 0) {
        mean.push_back(nullptr);
        low.push_back(nullptr);
        high.push_back(nullptr);
      } else {
        mean.push_back(b.sum[i] / static_cast<double>(b.count[i]));
        low.push_back(b.low[i]);
        high.push_back(b.high[i]);
      }
    }
    kept.push_back({{"name", label}, {"mean", mean}, {"low", low}, {"high", high}});
  }
  return {{"bin_s", bin_s}, {"series", kept}, {"not_shown", series.size() - kept.size()}};
}

ViewData read_view_data(const fs::path& run_dir, const ViewLimits& limits) {
  if (!fs::is_directory(run_dir)) throw RunError(run_dir.string() + ": not a directory");
  const Scene scene = read_scene(run_dir / kResolvedScenarioFile);
  const nlohmann::ordered_json summary = read_summary(run_dir / kSummaryFile);

  const fs::path positions_file = run_dir / kPositionsTraceFile;
  PositionsStream positions(positions_file);
  const PositionsHeader& header = positions.header();
  const std::uint32_t robots = header.robots;
  if (summary["robots"].is_number() && summary["robots"].get<std::uint64_t>() != robots) {
    refuse(positions_file, "holds " + std::to_string(robots) + " robots; summary.json says " +
                               summary["robots"].dump());
  }
  const double step_s = static_cast<double>(header.step_ns) * 1e-9;
  const double duration_s = static_cast<double>(header.steps) * step_s;

  // Decimation in time.
  const std::uint64_t max_frames = std::max<std::uint64_t>(
      2, std::min<std::uint64_t>(limits.max_frames, limits.robot_frames / robots));
  const std::uint64_t stride =
      std::max<std::uint64_t>(1, (header.steps + max_frames - 1) / max_frames);
  const std::size_t frames = static_cast<std::size_t>((header.steps - 1) / stride + 1);

  // Robot states (view_states.csv) as a per-frame matrix, objects as changes.
  LabelTable states;
  LabelTable kinds;
  std::vector<RobotStateChange> changes;
  ObjectRows objects;
  const fs::path states_file = run_dir / kViewStatesFile;
  const bool has_states = fs::exists(states_file);
  if (has_states) read_view_states(states_file, robots, states, kinds, changes, objects);
  std::stable_sort(
      changes.begin(), changes.end(),
      [](const RobotStateChange& a, const RobotStateChange& b) { return a.time_ns < b.time_ns; });
  const bool robot_states = !changes.empty();

  std::vector<std::uint16_t> pos(frames * robots * 2);
  std::vector<std::uint8_t> heading(frames * robots);
  std::vector<std::uint8_t> state(robot_states ? frames * robots : 0);
  std::vector<std::uint8_t> current_state(robots, 0);
  std::vector<double> now;
  std::vector<double> before;
  std::vector<double> motion(static_cast<std::size_t>(robots) * 2, 0.0);
  std::size_t next_change = 0;
  std::optional<std::ifstream> headings = open_headings(run_dir / kHeadingsTraceFile, header);
  for (std::uint64_t step = 0; step < header.steps; ++step) {
    positions.next(now);
    if (step > 0) {
      for (std::size_t r = 0; r < robots; ++r) {
        const double dx = now[2 * r] - before[2 * r];
        const double dy = now[2 * r + 1] - before[2 * r + 1];
        if (dx * dx + dy * dy > 1e-12) {
          motion[2 * r] = dx;
          motion[2 * r + 1] = dy;
        }
      }
    }
    std::swap(now, before);
    if (step % stride != 0) continue;
    const std::size_t frame = step / stride;
    const std::int64_t at_ns = static_cast<std::int64_t>(step) * header.step_ns;
    while (next_change < changes.size() && changes[next_change].time_ns <= at_ns) {
      current_state[changes[next_change].robot] =
          static_cast<std::uint8_t>(std::min<std::uint16_t>(changes[next_change].state, 255));
      ++next_change;
    }
    if (headings) {
      headings->seekg(static_cast<std::streamoff>(kHeadingsHeaderBytes + step * robots));
      if (!headings->read(reinterpret_cast<char*>(&heading[frame * robots]), robots)) {
        refuse(run_dir / kHeadingsTraceFile,
               "could not be read to its end (truncated while reading?)");
      }
    }
    for (std::size_t r = 0; r < robots; ++r) {
      pos[(frame * robots + r) * 2] = quantize(before[2 * r], scene.width_m);
      pos[(frame * robots + r) * 2 + 1] = quantize(before[2 * r + 1], scene.height_m);
      if (!headings) heading[frame * robots + r] = motion_heading(motion[2 * r], motion[2 * r + 1]);
      if (robot_states) state[frame * robots + r] = current_state[r];
    }
  }

  BlobWriter blob;
  blob.add("pos", pos, "Uint16");
  blob.add("heading", heading, "Uint8");
  if (robot_states) blob.add("state", state, "Uint8");
  if (!objects.t.empty()) {
    blob.add("obj_t", objects.t, "Float32");
    blob.add("obj_x", objects.x, "Float32");
    blob.add("obj_y", objects.y, "Float32");
    blob.add("obj_r", objects.r, "Float32");
    blob.add("obj_id", objects.id, "Uint32");
    blob.add("obj_kind", objects.kind, "Uint16");
    blob.add("obj_state", objects.state, "Uint16");
  }
  if (!scene.movables.empty() && fs::exists(run_dir / kObjectTraceFile)) {
    blob.add("mov",
             read_movables(run_dir / kObjectTraceFile, scene.movables.size(), stride, frames),
             "Float32");
  }

  ViewData view;
  auto& meta = view.meta;
  meta["format"] = 1;
  meta["name"] = scene.name;
  meta["run_dir"] = fs::absolute(run_dir).lexically_normal().filename().string();
  meta["arena"] = {{"width_m", scene.width_m},
                   {"height_m", scene.height_m},
                   {"obstacles", scene.obstacles},
                   {"movables", scene.movables}};
  meta["robots"] = robots;
  meta["robot_radius_m"] = scene.robot_radius_m;
  meta["link_range_m"] = scene.link_range_m > 0.0 ? nlohmann::ordered_json(scene.link_range_m)
                                                  : nlohmann::ordered_json();
  meta["steps"] = header.steps;
  meta["step_s"] = step_s;
  meta["duration_s"] = duration_s;
  meta["frames"] = frames;
  meta["frame_s"] = step_s * static_cast<double>(stride);
  meta["headings"] = headings ? "recorded" : "direction of motion";
  meta["states"] = states.labels();
  meta["kinds"] = kinds.labels();
  meta["summary"] = {{"pdr", summary.value("pdr", nlohmann::ordered_json())},
                     {"packets", summary.value("packets", nlohmann::ordered_json())},
                     {"sim_time_s", summary.value("sim_time_s", nlohmann::ordered_json())}};

  const fs::path packets_file = run_dir / kPacketTraceFile;
  if (fs::exists(packets_file)) {
    nlohmann::ordered_json panel;
    const FramePositions lookup{&pos, robots, frames, step_s * static_cast<double>(stride)};
    const PacketData packets =
        read_packets(packets_file, robots, step_s, duration_s, lookup, limits, panel);
    blob.add("ev_t", packets.t, "Float32");
    blob.add("ev_from", packets.from, "Uint32");
    blob.add("ev_to", packets.to, "Uint32");
    blob.add("ev_kind", packets.kind, "Uint8");
    blob.add("ev_reason", packets.reason, "Uint8");
    blob.add("r_sent", packets.sent, "Uint32");
    blob.add("r_recv", packets.received, "Uint32");
    blob.add("r_fwd", packets.forwarded, "Uint32");
    blob.add("r_drop", packets.dropped, "Uint32");
    meta["events"] = {
        {"reasons", packets.reasons}, {"kept_every", packets.kept_every}, {"lines", packets.lines}};
    meta["panel"] = panel;
  }
  const fs::path series_file = run_dir / kSeriesFile;
  if (fs::exists(series_file)) meta["series"] = read_series(series_file, duration_s, limits.series);
  meta["arrays"] = blob.arrays();
  view.blob = std::move(blob.bytes());
  return view;
}

}  // namespace swarmnet
