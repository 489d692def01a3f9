#include "scenario/scenario_loader.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "scenario/ns3_engine_check.hpp"
#include "scenario/problem_list.hpp"
#include "scenario/scenario_checker.hpp"
#include "scenario/scenario_consistency.hpp"
#include "scenario/scenario_overrides.hpp"
#include "scenario/scenario_schema.hpp"
#include "scenario/yaml_hazard.hpp"
#include "text/text_join.hpp"

namespace swarmnet {

namespace {

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw ScenarioError(
        {file.string() + ": cannot read the scenario file (" + std::strerror(errno) + ")"});
  }
  // Checked before reading: a device (/dev/zero), a pipe or a huge file would be read forever.
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (std::filesystem::is_directory(status)) {
    throw ScenarioError({file.string() + ": is a directory, not a scenario file"});
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw ScenarioError({file.string() + ": is not a regular file (a device, pipe or socket); " +
                         "a scenario is a YAML file"});
  }
  const auto size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxScenarioFileBytes) {
    throw ScenarioError({file.string() + ": is " + std::to_string(size >> 20U) +
                         " MiB; a scenario file may hold at most " +
                         std::to_string(kMaxScenarioFileBytes >> 20U) + " MiB"});
  }
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The tree's maps rebuilt in schema order (values derived after the check were appended last).
// Emits the checked tree in the schema's key order. Written straight to the emitter: building a
// reordered copy made yaml-cpp merge the whole tree's node set into every new map (quadratic in
// list length: 4000 obstacles took minutes).
void emit_ordered(YAML::Emitter& out, const KeySpec& spec, const YAML::Node& node) {
  const auto emit_map = [&out](const std::vector<KeySpec>& keys, bool flow, const YAML::Node& map) {
    std::size_t present = 0;
    for (const auto& key : keys) present += map[key.name] ? 1 : 0;
    if (flow || present == 0) out << YAML::Flow;
    out << YAML::BeginMap;
    for (const auto& key : keys) {
      if (const YAML::Node value = map[key.name]) {
        out << YAML::Key << key.name << YAML::Value;
        emit_ordered(out, key, value);
      }
    }
    out << YAML::EndMap;
  };
  if (spec.form == KeyForm::map) {
    emit_map(spec.keys, spec.flow, node);
  } else if (spec.form == KeyForm::map_list) {
    if (node.size() == 0) out << YAML::Flow;
    out << YAML::BeginSeq;
    for (const auto& element : node) emit_map(spec.keys, spec.flow, element);
    out << YAML::EndSeq;
  } else {
    out << node;
  }
}

Rect rect_from(const YAML::Node& node) {
  return Rect{node["x_min_m"].as<double>(), node["y_min_m"].as<double>(),
              node["x_max_m"].as<double>(), node["y_max_m"].as<double>()};
}

ArenaObject object_from(const YAML::Node& node) {
  ArenaObject object;
  object.shape = node["shape"].as<std::string>() == "cylinder" ? ArenaObject::Shape::cylinder
                                                               : ArenaObject::Shape::box;
  object.position = Vec2(node["x_m"].as<double>(), node["y_m"].as<double>());
  object.heading_rad = node["heading_rad"].as<double>();
  object.size_x_m = node["size_x_m"].as<double>();
  object.size_y_m = node["size_y_m"].as<double>();
  object.radius_m = node["radius_m"].as<double>();
  object.mass_kg = node["mass_kg"].as<double>();
  return object;
}

// Reads the checked tree, which holds every key, into a Scenario.
Scenario build(const YAML::Node& tree, const std::map<std::string, PluginChoice>& plugins) {
  const auto plugin = [&plugins](const std::string& path) { return plugins.at(path); };
  const auto plugin_list = [&plugins](const std::string& path, std::size_t count) {
    std::vector<PluginChoice> list;
    for (std::size_t i = 0; i < count; ++i)
      list.push_back(plugins.at(path + "." + std::to_string(i)));
    return list;
  };
  Scenario s;
  s.name = tree["name"].as<std::string>();
  s.seed = tree["seed"].as<std::uint64_t>();
  s.duration_s = tree["duration_s"].as<double>();
  s.step_s = tree["step_s"].as<double>();
  s.sync = tree["sync"].as<std::string>() == "pipelined" ? SyncMode::pipelined : SyncMode::strict;
  for (const auto& dir : tree["plugin_paths"]) s.plugin_paths.emplace_back(dir.as<std::string>());

  const YAML::Node arena = tree["arena"];
  s.arena.width_m = arena["width_m"].as<double>();
  s.arena.height_m = arena["height_m"].as<double>();
  for (const auto& obstacle : arena["obstacles"]) s.arena.obstacles.push_back(rect_from(obstacle));
  for (const auto& node : arena["objects"]) s.arena.objects.push_back(object_from(node));

  const YAML::Node robots = tree["robots"];
  s.robots.count = robots["count"].as<std::uint32_t>();
  s.robots.radius_m = robots["radius_m"].as<double>();
  s.robots.axle_m = robots["axle_m"].as<double>();
  s.robots.max_speed_mps = robots["max_speed_mps"].as<double>();
  s.robots.placement = rect_from(robots["placement"]["region"]);
  s.robots.proximity.rays = robots["proximity"]["rays"].as<std::uint32_t>();
  s.robots.proximity.range_m = robots["proximity"]["range_m"].as<double>();
  const YAML::Node rab = robots["range_and_bearing"];
  s.robots.range_and_bearing.enabled = rab["enabled"].as<bool>();
  s.robots.range_and_bearing.range_m = rab["range_m"].as<double>();
  s.robots.range_and_bearing.range_noise_sd_m = rab["range_noise_sd_m"].as<double>();
  s.robots.range_and_bearing.bearing_noise_sd_rad = rab["bearing_noise_sd_rad"].as<double>();
  s.robots.range_and_bearing.loss_probability = rab["loss_probability"].as<double>();
  s.robots.range_and_bearing.data_bytes = rab["data_bytes"].as<std::uint32_t>();
  s.robots.controllers = plugin_list("robots.controllers", robots["controllers"].size());
  for (const auto& entry : robots["controllers"]) {
    s.robots.controller_ports.push_back(entry["port"].as<std::uint16_t>());
  }

  s.worlds = plugin_list("world", tree["world"].size());
  s.physics = plugin("physics");

  const YAML::Node network = tree["network"];
  s.network.propagation = plugin_list("network.propagation", network["propagation"].size());
  s.network.phy.tx_power_dbm = network["phy"]["tx_power_dbm"].as<double>();
  s.network.phy.rx_sensitivity_dbm = network["phy"]["rx_sensitivity_dbm"].as<double>();
  const YAML::Node phy = network["phy"];
  s.network.phy.model =
      phy["model"].as<std::string>() == "sinr" ? PhyModel::sinr : PhyModel::threshold;
  s.network.phy.tx_gain_db = phy["tx_gain_db"].as<double>();
  s.network.phy.rx_gain_db = phy["rx_gain_db"].as<double>();
  s.network.phy.bandwidth_hz = phy["bandwidth_hz"].as<double>();
  s.network.phy.noise_figure_db = phy["noise_figure_db"].as<double>();
  s.network.phy.energy_detection_dbm = phy["energy_detection_dbm"].as<double>();
  s.network.phy.cca_threshold_dbm = phy["cca_threshold_dbm"].as<double>();
  s.network.phy.preamble_snr_db = phy["preamble_snr_db"].as<double>();
  s.network.phy.interference_floor_db = phy["interference_floor_db"].as<double>();
  s.network.phy.sensing_floor_db = phy["sensing_floor_db"].as<double>();
  s.network.phy.header_failure_cca = phy["header_failure_cca"].as<std::string>() == "ns3"
                                         ? HeaderFailureCca::ns3
                                         : HeaderFailureCca::sensed;
  s.network.channel.cutoff = network["channel"]["cutoff"].as<bool>();
  s.network.channel.lazy_far_signals =
      network["channel"]["far_signals"].as<std::string>() == "lazy";
  s.network.mac = plugin("network.mac");
  s.network.routing = plugin("network.routing");
  if (network["arp"].as<std::string>() == "static") s.network.arp.reset();
  const YAML::Node neighbors = network["neighbors"];
  s.network.neighbors.enabled = neighbors["enabled"].as<bool>();
  s.network.neighbors.window_s = neighbors["window_s"].as<double>();
  s.network.neighbors.max_per_robot = neighbors["max_per_robot"].as<std::uint32_t>();
  s.network.neighbors.rssi_smoothing = neighbors["rssi_smoothing"].as<double>();
  if (network["seed"]) s.network.seed = network["seed"].as<std::uint64_t>();
  s.network.engine = network["engine"].as<std::string>() == "ns3" ? NetworkEngineKind::ns3
                                                                  : NetworkEngineKind::native;
  const YAML::Node ns3 = network["ns3"];
  s.network.ns3.standard = ns3["standard"].as<std::string>();
  s.network.ns3.rate_manager = ns3["rate_manager"].as<std::string>();
  if (ns3["data_mode"]) s.network.ns3.data_mode = ns3["data_mode"].as<std::string>();
  if (ns3["control_mode"]) s.network.ns3.control_mode = ns3["control_mode"].as<std::string>();
  s.network.ns3.ip_routing = ns3["ip_routing"].as<std::string>();
  s.network.ns3.error_rate_model = ns3["error_rate_model"].as<std::string>();
  s.network.ns3.olsr_hello_interval_s = ns3["olsr_hello_interval_s"].as<double>();
  s.network.ns3.olsr_tc_interval_s = ns3["olsr_tc_interval_s"].as<double>();
  s.network.ns3.dsdv_periodic_update_interval_s =
      ns3["dsdv_periodic_update_interval_s"].as<double>();
  s.network.ns3.dsdv_settling_time_s = ns3["dsdv_settling_time_s"].as<double>();

  const YAML::Node output = tree["output"];
  s.output.dir = output["dir"].as<std::string>();
  s.output.packet_trace = output["packet_trace"].as<bool>();
  s.output.frame_trace = output["frame_trace"].as<bool>();
  s.output.sensing_trace = output["sensing_trace"].as<bool>();
  s.output.mobility_trace = output["mobility_trace"].as<bool>();
  s.output.mobility_interval_s = output["mobility_interval_s"].as<double>();
  s.output.traffic_schedule = output["traffic_schedule"].as<bool>();
  return s;
}

// output.dir: --out, else the file's output.dir, else runs/<name>-seed<seed>.
void resolve_output_dir(YAML::Node& tree, const ScenarioOverrides& overrides,
                        ProblemList& problems) {
  const YAML::Node& checked = tree;
  if (!checked["output"]) return;  // output itself is invalid: already reported
  YAML::Node output = tree["output"];
  if (overrides.out_dir) {
    if (overrides.out_dir->empty()) {
      problems.add_line("--out: output.dir: is empty; expected a directory");
      return;
    }
    output["dir"] = overrides.out_dir->string();
  } else if (!checked["output"]["dir"] && checked["name"] && checked["seed"]) {
    output["dir"] =
        "runs/" + checked["name"].as<std::string>() + "-seed" + checked["seed"].as<std::string>();
  }
}

void describe_keys(const KeySpec& spec, const std::string& prefix,
                   std::vector<ScenarioKeyInfo>* rows) {
  for (const auto& key : spec.keys) {
    const std::string path = prefix.empty() ? key.name : prefix + "." + key.name;
    std::string fallback = key.default_yaml.value_or("");
    if (!key.computed.empty()) fallback = key.computed;
    if (!key.default_plugin.empty()) fallback = "{plugin: " + key.default_plugin + "}";
    if (key.form == KeyForm::map && !key.is_required() && fallback.empty()) fallback = "{}";
    rows->push_back(ScenarioKeyInfo{path, key.describe(), key.rule.unit, fallback,
                                    key.is_required(), key.help});
    if (key.form == KeyForm::map) describe_keys(key, path, rows);
    if (key.form == KeyForm::map_list) describe_keys(key, path + "[]", rows);
    if (key.form == KeyForm::plugin || key.form == KeyForm::plugin_list) {
      const std::string element = key.form == KeyForm::plugin ? path : path + "[]";
      const std::string kind = to_string(key.plugin_kind);
      rows->push_back(ScenarioKeyInfo{element + ".plugin", "the name of a " + kind + " plugin", "",
                                      key.default_plugin, key.default_plugin.empty(),
                                      "Which " + kind + " plugin."});
      rows->push_back(
          ScenarioKeyInfo{element + ".params", "a mapping of the plugin's parameters", "", "{}",
                          false, "Parameters the plugin declares; the rest take its defaults."});
    }
  }
}

// Loads scenario `text`, named `origin` in messages; relative plugin_paths start at `base_dir`.
Scenario load_text(const std::string& text, const std::string& origin,
                   const std::filesystem::path& base_dir, const ScenarioOverrides& overrides,
                   PluginLoader& loader) {
  ProblemList problems(origin);
  std::vector<YAML::Node> documents;
  if (const auto hazard = find_yaml_hazard(text)) {
    YAML::Mark mark;
    mark.line = hazard->line;
    mark.column = hazard->column;
    throw ScenarioError(
        {problems.locate(KeyPath{}, mark) + ": YAML syntax error: " + hazard->problem});
  }
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::ParserException& error) {
    throw ScenarioError(
        {problems.locate(KeyPath{}, error.mark) + ": YAML syntax error: " + error.msg});
  }
  if (documents.size() > 1) {
    problems.add(KeyPath{}, documents[1].Mark(),
                 "the file holds " + std::to_string(documents.size()) + " YAML documents",
                 "one document");
  }
  YAML::Node root = documents.empty() ? YAML::Node() : documents.front();
  if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);  // checked as an empty mapping
  if (!root.IsMap()) {
    problems.add(KeyPath{}, root.Mark(), "the file is not a mapping of keys",
                 "a mapping of scenario keys (see docs/scenario.md)");
    throw ScenarioError(problems.lines());
  }

  apply_overrides(root, overrides.set, problems);
  if (overrides.seed) {
    root["seed"] = std::to_string(*overrides.seed);
    problems.mark_overridden(KeyPath({"seed"}), "--seed");
  }

  const KeySpec& schema = scenario_schema();
  ScenarioChecker checker(problems, loader, base_dir);
  if (overrides.host_plugin_paths) checker.ignore_directory_lists();
  YAML::Node tree = checker.check_root(schema, root);
  check_consistency(tree, checker, problems);
  check_network_engine(tree, checker, problems, loader);
  resolve_output_dir(tree, overrides, problems);
  if (!problems.empty()) throw ScenarioError(problems.lines());

  Scenario scenario = build(tree, checker.plugins());
  scenario.source = origin;
  if (overrides.host_plugin_paths) scenario.plugin_paths = *overrides.host_plugin_paths;
  YAML::Emitter resolved;
  emit_ordered(resolved, schema, tree);
  scenario.resolved_yaml = std::string(resolved.c_str()) + "\n";
  return scenario;
}

}  // namespace

ScenarioError::ScenarioError(std::vector<std::string> problems)
    : std::runtime_error(join(problems, "\n")), problems_(std::move(problems)) {}

Scenario load_scenario(const std::filesystem::path& file, const ScenarioOverrides& overrides,
                       PluginLoader& loader) {
  Scenario scenario =
      load_text(read_file(file), file.string(), file.parent_path(), overrides, loader);
  scenario.source = file;
  return scenario;
}

Scenario load_scenario_text(const std::string& yaml, const std::string& origin,
                            PluginLoader& loader, const ScenarioOverrides& overrides) {
  return load_text(yaml, origin, std::filesystem::current_path(), overrides, loader);
}

Scenario load_peer_scenario_text(const std::string& yaml, const std::string& origin,
                                 PluginLoader& loader,
                                 const std::vector<std::filesystem::path>& host_plugin_paths) {
  ScenarioOverrides host;
  host.host_plugin_paths = host_plugin_paths;
  return load_text(yaml, origin, std::filesystem::current_path(), host, loader);
}

std::string resolved_yaml(const Scenario& scenario) { return scenario.resolved_yaml; }

std::vector<ScenarioKeyInfo> scenario_key_reference() {
  std::vector<ScenarioKeyInfo> rows;
  describe_keys(scenario_schema(), "", &rows);
  return rows;
}

}  // namespace swarmnet
