#include "scenario/scenario_schema.hpp"

#include <algorithm>

#include "swarmnet/range_and_bearing.hpp"
#include "text/text_join.hpp"

namespace swarmnet {

namespace {

KeySpec scalar_key(std::string name, ScalarType type, std::string unit, std::string help) {
  KeySpec spec;
  spec.name = std::move(name);
  spec.rule.type = type;
  spec.rule.unit = std::move(unit);
  spec.help = std::move(help);
  return spec;
}

KeySpec container_key(std::string name, KeyForm form, std::string help,
                      std::vector<KeySpec> keys = {}) {
  KeySpec spec;
  spec.name = std::move(name);
  spec.form = form;
  spec.help = std::move(help);
  spec.keys = std::move(keys);
  return spec;
}

// An axis-aligned rectangle in arena coordinates.
std::vector<KeySpec> rect_keys(const std::string& what) {
  return {
      real_key("x_min_m", "m", "Left edge of the " + what + ".").need(),
      real_key("y_min_m", "m", "Bottom edge of the " + what + ".").need(),
      real_key("x_max_m", "m", "Right edge of the " + what + "; greater than x_min_m.").need(),
      real_key("y_max_m", "m", "Top edge of the " + what + "; greater than y_min_m.").need(),
  };
}

}  // namespace

KeySpec real_key(std::string name, std::string unit, std::string help) {
  return scalar_key(std::move(name), ScalarType::real, std::move(unit), std::move(help));
}
KeySpec integer_key(std::string name, std::string help) {
  return scalar_key(std::move(name), ScalarType::integer, "", std::move(help));
}
KeySpec boolean_key(std::string name, std::string help) {
  return scalar_key(std::move(name), ScalarType::boolean, "", std::move(help));
}
KeySpec text_key(std::string name, std::string help) {
  return scalar_key(std::move(name), ScalarType::text, "", std::move(help));
}
KeySpec name_key(std::string name, std::string help) {
  return scalar_key(std::move(name), ScalarType::name, "", std::move(help));
}
KeySpec choice_key(std::string name, std::vector<std::string> choices, std::string help) {
  KeySpec spec = scalar_key(std::move(name), ScalarType::choice, "", std::move(help));
  spec.rule.choices = std::move(choices);
  return spec;
}
KeySpec directory_list_key(std::string name, std::string help) {
  return container_key(std::move(name), KeyForm::directory_list, std::move(help));
}
KeySpec map_key(std::string name, std::string help, std::vector<KeySpec> keys) {
  return container_key(std::move(name), KeyForm::map, std::move(help), std::move(keys));
}
KeySpec map_list_key(std::string name, std::string help, std::vector<KeySpec> keys) {
  return container_key(std::move(name), KeyForm::map_list, std::move(help), std::move(keys));
}
KeySpec plugin_key(std::string name, PluginKind kind, std::string help) {
  KeySpec spec = container_key(std::move(name), KeyForm::plugin, std::move(help));
  spec.plugin_kind = kind;
  return spec;
}
KeySpec plugin_list_key(std::string name, PluginKind kind, std::string help) {
  KeySpec spec = container_key(std::move(name), KeyForm::plugin_list, std::move(help));
  spec.plugin_kind = kind;
  return spec;
}

bool KeySpec::is_required() const {
  if (required) return true;
  if (form != KeyForm::map || !computed.empty()) return false;
  return std::any_of(keys.begin(), keys.end(),
                     [](const KeySpec& key) { return key.is_required(); });
}

const KeySpec* KeySpec::find(const std::string& key) const {
  for (const auto& spec : keys) {
    if (spec.name == key) return &spec;
  }
  return nullptr;
}

std::vector<std::string> KeySpec::key_names() const {
  std::vector<std::string> names;
  for (const auto& spec : keys) names.push_back(spec.name);
  return names;
}

std::string KeySpec::describe() const {
  const std::string kind = to_string(plugin_kind);
  switch (form) {
    case KeyForm::scalar:
      return rule.describe();
    case KeyForm::directory_list:
      return "a list of directories";
    case KeyForm::map:
      return "a mapping with keys " + join(key_names(), ", ");
    case KeyForm::map_list:
      return std::string(min_items > 0 ? "a non-empty" : "a") + " list of mappings with keys " +
             join(key_names(), ", ");
    case KeyForm::plugin:
      return "{plugin: NAME, params: {...}} naming a " + kind + " plugin";
    case KeyForm::plugin_list:
      return std::string(min_items > 0 ? "a non-empty" : "a") +
             " list of {plugin: NAME, params: {...}} naming " + kind + " plugins";
  }
  return "";
}

const KeySpec& scenario_schema() {
  // clang-format off
  static const KeySpec schema = map_key("", "A SwarmNet scenario.", {
    name_key("name", "Scenario name; names the default output directory.").need(),
    integer_key("seed", "Master random seed; every model's random streams derive from it.")
        .at_least(0).defaults("1"),
    real_key("duration_s", "s", "Simulated time to run; a whole number of steps.").above(0).need(),
    real_key("step_s", "s", "Robot step length dt; one batch is exchanged per step.")
        .at_least(1e-9).defaults("0.1"),  // the network half counts time in whole ns
    choice_key("sync", {"strict", "pipelined"},
               "strict: deliveries of step i are read at step i+1, the halves alternate; "
               "pipelined: read at step i+2, both halves run at once.").defaults("strict"),
    // Before every plugin key: the checker adds these directories to the plugin search path.
    directory_list_key("plugin_paths",
                       "Directories searched for plugins before any other, relative to the "
                       "scenario file's directory.").defaults("[]"),
    map_key("arena", "The walled rectangle [0, width_m] x [0, height_m] robots move in.", {
      real_key("width_m", "m", "Extent along x.").above(0).need(),
      real_key("height_m", "m", "Extent along y.").above(0).need(),
      map_list_key("obstacles", "Rectangular obstacles, inside the arena.", rect_keys("obstacle"))
          .one_line().defaults("[]"),
      map_list_key("objects", "Movable objects on the floor that robots can push: boxes and "
                              "upright cylinders, inside the arena. Need a physics engine with "
                              "dynamics (ode); kinematic2d refuses them.", {
        choice_key("shape", {"box", "cylinder"}, "What the object is.").need(),
        real_key("x_m", "m", "Centre, x.").need(),
        real_key("y_m", "m", "Centre, y.").need(),
        real_key("heading_rad", "rad", "box: direction of its size_x_m side, from +x.")
            .defaults("0"),
        real_key("size_x_m", "m", "box: side along its heading; positive for a box.")
            .at_least(0).defaults("0"),
        real_key("size_y_m", "m", "box: side across its heading; positive for a box.")
            .at_least(0).defaults("0"),
        real_key("radius_m", "m", "cylinder: radius; positive for a cylinder.")
            .at_least(0).defaults("0"),
        real_key("mass_kg", "kg", "Mass.").above(0).defaults("0.5"),
      }).one_line().defaults("[]"),
    }),
    map_key("robots", "The swarm: identical differential-drive discs.", {
      integer_key("count", "Number of robots.").between(1, 100000).need(),
      real_key("radius_m", "m", "Body radius.").above(0).defaults("0.085"),
      real_key("axle_m", "m", "Distance between the wheels.").above(0).defaults("0.14"),
      real_key("max_speed_mps", "m/s", "Largest wheel speed; commands are clamped to it.")
          .above(0).defaults("1.0"),
      map_key("placement", "Where robots start.", {
        map_key("region", "Rectangle robots start in, uniformly at random without overlap.",
                rect_keys("placement region")).one_line().derived("the whole arena"),
      }),
      map_key("proximity", "The proximity sensor ring.", {
        integer_key("rays", "Number of rays, evenly spaced around the body.")
            .between(0, 360).defaults("24"),
        real_key("range_m", "m", "Distance beyond which a ray sees nothing.")
            .above(0).defaults("0.3"),
      }),
      map_key("range_and_bearing", "The range-and-bearing device (RobotContext::"
                                   "range_and_bearing(), docs/plugins.md): each robot reads the "
                                   "id, range, bearing and data bytes of the robots in its line "
                                   "of sight. In the robot half; not the radio.", {
        boolean_key("enabled", "Give every robot the device (off: no cost, and "
                               "range_and_bearing() refuses).").defaults("false"),
        real_key("range_m", "m", "Centre-to-centre distance up to which a robot is seen (the "
                                 "foot-bot's 3 m).").above(0).defaults("3"),
        real_key("range_noise_sd_m", "m", "Standard deviation of the Gaussian noise added to "
                                          "each range (clamped at 0).").at_least(0).defaults("0"),
        real_key("bearing_noise_sd_rad", "rad", "Standard deviation of the Gaussian noise added "
                                                "to each bearing.").at_least(0).defaults("0"),
        real_key("loss_probability", "", "Probability that a reading is lost, independently "
                                         "for each reading.").between(0, 1).defaults("0"),
        integer_key("data_bytes", "Bytes each emitter carries (the foot-bot's 10).")
            .between(0, kMaxRangeAndBearingDataBytes).defaults("10"),
      }),
      plugin_list_key("controllers", PluginKind::controller,
                      "Controllers every robot runs, in this order, on every step.")
          .at_least_items(1).need(),
    }),
    plugin_list_key("world", PluginKind::world,
                    "World plugins (loop functions, swarmnet/world.hpp): task state the robots "
                    "act in, run before and after every step in this order; one may end the run "
                    "when its task is done.").defaults("[]"),
    plugin_key("physics", PluginKind::physics, "Moves the bodies and resolves collisions.")
        .plugin_default("kinematic2d"),
    map_key("network", "The network half: one node per robot.", {
      plugin_list_key("propagation", PluginKind::propagation,
                      "Propagation models, chained in this order (e.g. path loss, then fading).")
          .at_least_items(1).need(),
      map_key("phy", "The radio every node has.", {
        choice_key("model", {"threshold", "sinr"},
                   "threshold: a frame is received iff its power reaches rx_sensitivity_dbm; "
                   "sinr: 802.11a OFDM reception with noise, interference and SINR-based errors.")
            .defaults("threshold"),
        real_key("tx_power_dbm", "dBm", "Transmit power (16.0206 dBm = 40 mW).")
            .between(-100, 100).defaults("16.0206"),
        real_key("rx_sensitivity_dbm", "dBm", "threshold model: frames received weaker than this "
                                              "are not decoded.")
            .between(-200, 100).defaults("-96"),
        real_key("tx_gain_db", "dB", "Transmit antenna gain.").between(-100, 100).defaults("0"),
        real_key("rx_gain_db", "dB", "Receive antenna gain.").between(-100, 100).defaults("0"),
        real_key("bandwidth_hz", "Hz", "sinr model: channel bandwidth, for the thermal noise.")
            .above(0).defaults("20000000"),
        real_key("noise_figure_db", "dB", "sinr model: receiver noise figure.")
            .between(0, 100).defaults("7"),
        real_key("energy_detection_dbm", "dBm", "sinr model: total received energy at which the "
                                                "medium is busy (CCA-ED).")
            .between(-200, 100).defaults("-62"),
        real_key("cca_threshold_dbm", "dBm", "sinr model: weakest frame whose preamble is "
                                             "detected; such a frame also makes the medium busy.")
            .between(-200, 100).defaults("-82"),
        real_key("preamble_snr_db", "dB", "sinr model: SINR a preamble needs to be detected.")
            .between(-100, 100).defaults("4"),
        real_key("interference_floor_db", "dB",
                 "sinr model: signals weaker than noise floor + this are ignored (neither "
                 "interfere nor sensed). Above 0 the floor is above the noise: at "
                 "cca_threshold_dbm minus the noise floor (11.9897 by default) every signal too "
                 "weak to be detected is ignored (fast, approximate); higher still, detectable "
                 "frames are ignored too and the range shrinks.")
            .between(-100, 100).defaults("-10"),
        real_key("sensing_floor_db", "dB",
                 "sinr model: signals weaker than cca_threshold_dbm + this are quiet: they "
                 "interfere but are not carrier-sensed, and cost nothing until a reception needs "
                 "them (faster). The default leaves no signal quiet (exact).")
            .between(-200, 0).defaults("-100"),
        choice_key("header_failure_cca", {"sensed", "ns3"},
                   "sinr model: what the MAC is told after a frame's PLCP header fails. sensed: "
                   "carrier sense goes on (the frame keeps the medium busy); ns3: as ns-3.37, the "
                   "reception is aborted at the header's end, and the MAC counts the medium idle "
                   "from there when a signal joined during the preamble and none during the "
                   "header, until the next signal's detection window ends (docs/validation.md).")
            .defaults("sensed"),
      }),
      map_key("channel", "The shared medium.", {
        boolean_key("cutoff", "Visit only nodes that could possibly hear a frame (exact; turn off "
                              "to check).").defaults("true"),
        choice_key("far_signals", {"lazy", "events"},
                   "sinr model: lazy hands a signal too weak to be detected or sensed alone to a "
                   "receiver only when it can matter there (receiving, judging a preamble, or "
                   "when such signals could add up to the carrier-sense threshold); events hands "
                   "every signal over as events. Same results to the bit; lazy is faster "
                   "(docs/performance.md). Fading models that draw per frame always use "
                   "events.")
            .defaults("lazy"),
      }),
      map_key("neighbors", "Radio neighbour tables for controllers (RobotContext::neighbors(), "
                           "docs/plugins.md): each robot's table lists the nodes its PHY decoded "
                           "frames from lately, with RSSI, SINR and frame counts, returned with "
                           "the step's deliveries.", {
        boolean_key("enabled", "Keep and send the tables (off: no cost, and neighbors() "
                               "refuses).").defaults("false"),
        real_key("window_s", "s", "A node not heard for this long leaves the table; frames are "
                                  "counted over it.").between(0, 3600).above(0).defaults("1"),
        integer_key("max_per_robot", "Neighbours a table holds at most; the most recently heard "
                                     "are kept.").between(1, 1024).defaults("32"),
        real_key("rssi_smoothing", "", "Weight of a new frame's RSSI in the smoothed RSSI "
                                       "(exponential smoothing; 1: the last frame only).")
            .between(0, 1).above(0).defaults("0.25"),
      }),
      plugin_key("mac", PluginKind::mac, "Medium access control.").plugin_default("ideal_mac"),
      plugin_key("routing", PluginKind::routing, "Routing protocol.").need(),
      choice_key("arp", {"ns3", "static"},
                 "ns3: ARP as ns-3.37 runs it (a broadcast request, a unicast reply, 3 packets "
                 "held per unresolved neighbour, 3 retries a second apart, entries alive 120 s; "
                 "docs/arp.md); static: every neighbour's address known before the run, no ARP "
                 "frame (the aligned setup of docs/validation.md).")
          .defaults("ns3"),
      integer_key("seed", "Seed of the network half's own random streams (backoff, reception "
                          "draws, ARP and routing jitter, fading). The traffic and the robots keep "
                          "the master seed, so runs that differ only here replay the same "
                          "mobility and messages over other channel realizations.")
          .at_least(0).derived("the master seed"),
      choice_key("engine", {"native", "ns3"},
                 "Which simulator is the network half: SwarmNet's own (native) or ns-3.37 "
                 "(ns3: every key above mapped onto ns-3's models, docs/ns3-engine.md).")
          .defaults("native"),
      map_key("ns3", "ns-3 engine only: choices SwarmNet's own engine has no counterpart for.", {
        choice_key("standard", {"80211a", "80211b", "80211g", "80211n", "80211ac"},
                   "Wi-Fi standard (802.11n and ac in the 5 GHz band).").defaults("80211a"),
        choice_key("rate_manager", {"constant", "arf", "aarf", "minstrel", "minstrel_ht",
                                    "ideal"},
                   "Rate adaptation: constant uses data_mode and control_mode; the others are "
                   "ns-3's managers of those names.").defaults("constant"),
        text_key("data_mode", "constant: ns-3 WifiMode of data frames (e.g. OfdmRate54Mbps, "
                              "HtMcs7).").derived("the MAC's data_rate_bps (802.11a/b/g)"),
        text_key("control_mode", "constant: ns-3 WifiMode of control frames.")
            .derived("the MAC's control_rate_bps (802.11a/b/g)"),
        choice_key("error_rate_model", {"nist", "table", "yans"},
                   "Frame error rates from SINR: nist (what SwarmNet's sinr PHY implements), "
                   "table (ns-3.37's default) or yans.").defaults("nist"),
        choice_key("ip_routing", {"none", "olsr", "dsdv"},
                   "IP routing under network.routing `direct`: none (one hop), or ns-3's OLSR or "
                   "DSDV finding multi-hop routes.").defaults("none"),
        real_key("olsr_hello_interval_s", "s", "olsr: HELLO interval.").above(0).defaults("2"),
        real_key("olsr_tc_interval_s", "s", "olsr: topology control interval.")
            .above(0).defaults("5"),
        real_key("dsdv_periodic_update_interval_s", "s", "dsdv: full table update interval.")
            .above(0).defaults("15"),
        real_key("dsdv_settling_time_s", "s", "dsdv: wait before advertising a changed route.")
            .above(0).defaults("5"),
      }),
    }),
    map_key("output", "What a run writes, and where.", {
      text_key("dir", "Run directory; relative to the current working directory. --out wins.")
          .derived("runs/<name>-seed<seed>"),
      boolean_key("packet_trace", "Write packet events (send, forward, drop, deliver).")
          .defaults("true"),
      boolean_key("frame_trace", "Write every frame put on the air (frames.csv).")
          .defaults("false"),
      boolean_key("sensing_trace",
                  "Write the neighbour tables, send reports and route answers the network half "
                  "gave the controllers, per step (sensing.csv).")
          .defaults("false"),
      boolean_key("mobility_trace", "Write the ns-2 mobility trace.").defaults("true"),
      real_key("mobility_interval_s", "s", "Mobility trace sampling interval; 0 = every step.")
          .at_least(0).defaults("0"),
      boolean_key("traffic_schedule", "Write the traffic schedule (for replay).")
          .defaults("true"),
    }),
  });
  // clang-format on
  return schema;
}

}  // namespace swarmnet
