// The boundary between the kernel and the ns-3 network engine (`network.engine: ns3`).
//
// ns-3.37's headers do not compile as C++20 and the kernel is C++20, so ns-3 lives in a module of
// its own, libswarmnet_ns3_engine.so, compiled as C++17 and dlopen'd by the network half only when
// a scenario asks for ns-3 (a run with the native engine never loads ns-3's 40 libraries). This
// header is all the two sides share: plain data and two interfaces, valid C++17 and C++20.
//
// The kernel maps the scenario onto ns-3 (ns3_settings.hpp): which TypeIds and which attribute
// values. The module applies them as given and owns everything else: nodes, devices, the IP
// stack, routing, the applications that carry the robots' messages, and the traces it counts.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace swarmnet::ns3engine {

// Bumped whenever anything in this header changes; the kernel refuses a module of another one.
inline constexpr std::uint32_t kApiVersion = 4;

inline constexpr std::uint32_t kBroadcastNode = 0xFFFFFFFFU;

// An ns-3 attribute, its value as ns-3 parses it from text (DeserializeFromString).
struct Attribute {
  std::string name;
  std::string value;
};

// An ns-3 object to create: its TypeId name and the attributes to set on it.
struct ObjectSpec {
  std::string type_id;
  std::vector<Attribute> attributes;
};

enum class Routing : std::uint8_t {
  direct,    // one UDP datagram to the destination's address: one hop, as SwarmNet's `direct`
  flooding,  // an ns-3 application that floods as SwarmNet's `flooding` plugin does
  aodv,      // ns-3's AodvHelper
  olsr,      // ns-3's OlsrHelper
  dsdv,      // ns-3's DsdvHelper
};

// How nodes learn their neighbours' MAC addresses.
enum class Arp : std::uint8_t {
  dynamic,  // ns-3's ARP: requests, replies, a pending queue (ns-3 as its users run it)
  // Every neighbour's entry filled in before the run (NeighborCacheHelper), so no ARP frame is
  // sent. ns-3.37's AODV maps a MAC address back to a neighbour only through an entry that is
  // alive or permanent: `static_no_feedback` leaves the entries auto-generated, so AODV gets no
  // layer-2 feedback (the aligned setup of docs/validation.md); `static_with_feedback` marks them
  // permanent, which gives it back and changes nothing else.
  static_no_feedback,
  static_with_feedback,
};

struct FloodingParams {
  std::uint32_t ttl = 32;
  double jitter_max_s = 0.005;
  std::uint32_t cache_size = 4096;
};

// Everything the module sets up, decided by the kernel from a validated scenario.
struct Config {
  std::uint32_t nodes = 0;
  std::uint64_t run = 1;  // ns-3's RngRun (the scenario's seed); RngSeed is 1
  // WifiStandard as WifiHelper::SetStandard takes it, by name: "80211a", "80211b", "80211g",
  // "80211n" (5 GHz), "80211ac".
  std::string standard = "80211a";
  std::vector<ObjectSpec> loss_chain;         // PropagationLossModels, chained in this order
  std::vector<Attribute> phy;                 // on YansWifiPhy (TxPowerStart, CcaEdThreshold, ...)
  std::vector<Attribute> preamble_detection;  // on ThresholdPreambleDetectionModel
  ObjectSpec error_rate_model;       // the PHY's ErrorRateModel (empty type_id: ns-3's default)
  ObjectSpec rate_manager;           // a WifiRemoteStationManager and its attributes
  std::vector<Attribute> txop;       // on the ad hoc MAC's Txop (MinCw, MaxCw)
  std::vector<Attribute> mac_queue;  // on WifiMacQueue (MaxSize, MaxDelay)
  Routing routing = Routing::direct;
  std::vector<Attribute> routing_attributes;  // on the aodv, olsr or dsdv RoutingProtocol
  FloodingParams flooding;
  Arp arp = Arp::dynamic;
  // When set, asked every kInterruptSliceNs of simulated time inside a window: true ends the
  // window with Interrupted (a server's run stops on SIGTERM mid-step). Stop events the slicing
  // adds are not counted, and they change no result.
  bool (*stop_requested)() = nullptr;
};

inline constexpr std::int64_t kInterruptSliceNs = 1'000'000;  // 1 ms of simulated time

// Thrown by Network::run_window when Config::stop_requested said stop.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A robot's message, taken in by the network at `inject_ns` (inside the window it comes with).
struct Message {
  std::uint64_t message_id = 0;
  std::uint32_t source = 0;
  std::uint32_t destination = kBroadcastNode;
  std::uint16_t port = 0;
  std::int64_t inject_ns = 0;
  std::vector<std::uint8_t> payload;  // carried as the UDP payload, byte for byte
};

// A message that reached the application of node `receiver`. Every arrival is reported, a
// duplicate too; the kernel decides what the robot sees.
struct Arrival {
  std::uint64_t message_id = 0;
  std::uint32_t receiver = 0;
  std::int64_t arrived_ns = 0;
  std::uint32_t hops = 0;  // links travelled (1: straight from the source)
};

// Counters, each a (name, value) list in a fixed order. Names follow summary.json's where
// SwarmNet has the same counter (mac: tx_frames, tx_bytes, retries, ...; routing:
// control_packets, control_bytes, data_forwards, ...; drops: no_route, queue_full, ttl_expired,
// retry_limit, buffer_timeout).
using Counters = std::vector<std::pair<std::string, std::uint64_t>>;

struct Report {
  Counters mac;
  Counters routing;
  Counters drops;
  std::uint64_t events = 0;  // ns-3 events run so far
};

class Network {
 public:
  Network() = default;
  Network(const Network&) = delete;
  Network& operator=(const Network&) = delete;
  Network(Network&&) = delete;
  Network& operator=(Network&&) = delete;
  virtual ~Network() = default;

  // Simulates up to (not including) `end_ns`: first puts node i at (xy[2i], xy[2i+1], 0), held
  // there over the window, then injects every message at its inject_ns, then runs every event
  // before end_ns. Appends what reached an application in the window to `arrivals`, in arrival
  // order. Throws std::runtime_error on a malformed window (end before now, a message outside it
  // or naming an unknown node).
  virtual void run_window(std::int64_t end_ns, const std::vector<double>& xy,
                          const std::vector<Message>& messages, std::vector<Arrival>& arrivals) = 0;

  [[nodiscard]] virtual Report report() const = 0;
  // ns-3 events run so far (Report::events), without building the counters.
  [[nodiscard]] virtual std::uint64_t events() const = 0;
};

}  // namespace swarmnet::ns3engine

// The module's entry points (looked up with dlsym by these names).
//
// swarmnet_ns3_engine_api_version: kApiVersion as the module was built.
// swarmnet_ns3_engine_create: sets ns-3 up from `config` and returns the network, owned by the
// caller (delete it before unloading the module). ns-3's simulator is a process-wide singleton:
// at most one network may exist at a time. Throws std::runtime_error naming what it could not
// apply (an unknown TypeId, attribute or value), never aborts.
extern "C" {
std::uint32_t swarmnet_ns3_engine_api_version();
swarmnet::ns3engine::Network* swarmnet_ns3_engine_create(const swarmnet::ns3engine::Config& config);
}
