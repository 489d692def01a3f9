// A network half started with --listen trusts no peer: it serves only peers that prove they know
// its token, never loads code from a peer's plugin_paths (under any spelling, repeated or not),
// never writes where a peer says, serves a real robot half in time under a flood of silent or
// reconnecting peers, refuses a step that is not the next one, and stops on SIGTERM mid-run.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <regex>
#include <thread>
#include <tuple>

#include "command_runner.hpp"
#include "coupling/memory_budget.hpp"
#include "coupling/peer_authentication.hpp"
#include "protocol/step_channel.hpp"
#include "socket_transport.hpp"

namespace swarmnet::testing {
namespace {

void write_token(const std::filesystem::path& path, const std::string& text, unsigned mode) {
  std::ofstream(path) << text << "\n";
  ::chmod(path.c_str(), mode);
}

// `swarmnet net --listen 127.0.0.1:0 ...` in the background; its port read from its log.
class Server {
 public:
  Server(const std::filesystem::path& dir, const std::vector<std::string>& extra)
      : log_(dir / "server.log") {
    std::vector<std::string> args = {"net",
                                     "--listen",
                                     "127.0.0.1:0",
                                     "--token-file",
                                     (dir / "token").string(),
                                     "--out",
                                     (dir / "served").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    pid_ = spawn_swarmnet(args, log_);
    const std::regex serving(R"(serving robot halves on 127\.0\.0\.1:(\d+))");
    for (int i = 0; i < 500 && port_ == 0; ++i) {
      std::smatch m;
      const std::string text = read_file(log_);
      if (std::regex_search(text, m, serving)) port_ = std::stoi(m[1]);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  ~Server() {
    if (!exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  [[nodiscard]] pid_t pid() const { return pid_; }

  [[nodiscard]] int port() const { return port_; }
  [[nodiscard]] std::string address() const { return "tcp://127.0.0.1:" + std::to_string(port_); }
  [[nodiscard]] std::string log() const { return read_file(log_); }
  // Waits up to 10 s for the server to exit by itself; its exit status, or -1.
  int wait_exit() {
    for (int i = 0; i < 1000; ++i) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return -1;
  }

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
  int port_ = 0;
  bool exited_ = false;
};

class RemoteNetworkHalf : public ::testing::Test {
 protected:
  RemoteNetworkHalf() {
    write_token(dir_.path() / "token", "correct horse battery staple 42", 0600);
  }

  // A real robot half; `extra` are further options (a shorter --step-timeout makes a robot half
  // that is kept waiting give up, and so fail the test, in seconds).
  CommandResult run_robot_half(const Server& server, const std::string& token_file,
                               const std::string& out, const std::string& extra = "") {
    return run_swarmnet("run " + std::string(SWARMNET_SOURCE_DIR) +
                        "/configs/quickstart.yaml --set duration_s=2 --set robots.count=10 -q "
                        "--net " +
                        server.address() + " --token-file " + token_file + " --out " +
                        (dir_.path() / out).string() + " " + extra);
  }

  // An authenticated peer's channel after a welcome for `scenario` (`robots`, 0.1 s steps).
  struct Session {
    std::unique_ptr<SocketTransport> transport;
    std::unique_ptr<StepChannel> channel;
    std::string error;  // why there is no session
  };
  Session hand_made_session(const Server& server, const std::string& scenario,
                            std::uint32_t robots = 2) {
    Session s;
    WaitPolicy policy;
    policy.timeout = std::chrono::seconds(10);
    s.transport = std::make_unique<SocketTransport>(
        connect_tcp("127.0.0.1", static_cast<std::uint16_t>(server.port())), policy, "TCP");
    if (std::string why =
            authenticate_to_acceptor(*s.transport, PeerSecret::from_file(dir_.path() / "token"));
        !why.empty()) {
      s.error = why;
      return s;
    }
    s.channel = std::make_unique<StepChannel>(*s.transport, "the network half");
    Hello hello;
    hello.scenario_yaml = scenario;
    if (auto r = s.channel->send_hello(hello); !r.ok()) s.error = r.error;
    if (auto r = s.channel->receive_welcome(Welcome{1, robots, 100'000'000});
        s.error.empty() && !r.ok()) {
      s.error = r.error;
    }
    return s;
  }

  // A peer written by hand: it knows the token and sends `scenario` in its hello, asking for
  // outputs in `run_dir`; then finishes at once. Returns what the server answered.
  std::string hand_made_peer(const Server& server, const std::string& scenario,
                             const std::string& run_dir = "") {
    WaitPolicy policy;
    policy.timeout = std::chrono::seconds(10);
    SocketTransport transport(connect_tcp("127.0.0.1", static_cast<std::uint16_t>(server.port())),
                              policy, "TCP");
    const PeerSecret secret = PeerSecret::from_file(dir_.path() / "token");
    if (std::string why = authenticate_to_acceptor(transport, secret); !why.empty()) return why;
    StepChannel channel(transport, "the network half");
    Hello hello;
    hello.scenario_yaml = scenario;
    hello.run_dir = run_dir;
    if (auto r = channel.send_hello(hello); !r.ok()) return r.error;
    if (auto r = channel.receive_welcome(Welcome{1, 2, 100'000'000}); !r.ok()) return r.error;
    if (auto r = channel.send_finish(); !r.ok()) return r.error;
    NetworkReport report;
    if (auto r = channel.receive_report(report); !r.ok()) return r.error;
    return "ok";
  }

  // The quickstart for two robots, one simulated second, with `edit` applied.
  static std::string scenario(const std::function<void(YAML::Node&)>& edit = [](YAML::Node&) {}) {
    YAML::Node tree = YAML::LoadFile(std::string(SWARMNET_SOURCE_DIR) + "/configs/quickstart.yaml");
    tree["robots"]["count"] = 2;
    tree["duration_s"] = 1.0;
    edit(tree);
    YAML::Emitter out;
    out << tree;
    return out.c_str();
  }

  TempDir dir_;
};

TEST_F(RemoteNetworkHalf, ARobotHalfWithTheTokenRunsAndOutputsStayOnTheServer) {
  Server server(dir_.path(), {});
  ASSERT_NE(server.port(), 0) << server.log();
  const CommandResult run = run_robot_half(server, (dir_.path() / "token").string(), "run");
  ASSERT_EQ(run.exit_code, 0) << run.output << server.log();
  EXPECT_TRUE(std::filesystem::exists(dir_.path() / "served" / "run-0001" / "packets.csv"));
  EXPECT_EQ(server.wait_exit(), 0) << server.log();
}

TEST_F(RemoteNetworkHalf, AWrongTokenIsRefusedAndTheServerServesTheNextPeer) {
  Server server(dir_.path(), {});
  write_token(dir_.path() / "wrong", "a token the server never heard of", 0600);
  const CommandResult refused = run_robot_half(server, (dir_.path() / "wrong").string(), "a");
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.output.find("refused the token"), std::string::npos) << refused.output;
  const CommandResult served = run_robot_half(server, (dir_.path() / "token").string(), "b");
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  EXPECT_NE(server.log().find("did not prove that it knows the token"), std::string::npos);
}

// The silent peer no longer holds the door: the real robot half is served beside it, and the
// silent one is dropped at its own deadline.
TEST_F(RemoteNetworkHalf, ASilentPeerIsDroppedAtTheHandshakeDeadline) {
  Server server(dir_.path(), {"--handshake-timeout", "0.5", "--serve-forever"});
  const int silent = connect_tcp("127.0.0.1", static_cast<std::uint16_t>(server.port()));
  const CommandResult served = run_robot_half(server, (dir_.path() / "token").string(), "run");
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  for (int i = 0; i < 500 && server.log().find("timed out") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_NE(server.log().find("timed out"), std::string::npos) << server.log();
  ::close(silent);
}

TEST_F(RemoteNetworkHalf, GarbageBeforeTheHandshakeIsRefusedWithoutParsing) {
  Server server(dir_.path(), {});
  const int fd = connect_tcp("127.0.0.1", static_cast<std::uint16_t>(server.port()));
  const char garbage[] = "\xff\xff\xff\x7fGET / HTTP/1.0\r\n\r\n";
  ASSERT_GT(::write(fd, garbage, sizeof garbage), 0);
  const CommandResult served = run_robot_half(server, (dir_.path() / "token").string(), "run");
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  EXPECT_NE(server.log().find("refused"), std::string::npos) << server.log();
  ::close(fd);
}

TEST_F(RemoteNetworkHalf, ItServesTheRunsAskedForOneAfterAnother) {
  Server server(dir_.path(), {"--runs", "2"});
  EXPECT_EQ(run_robot_half(server, (dir_.path() / "token").string(), "one").exit_code, 0);
  EXPECT_EQ(run_robot_half(server, (dir_.path() / "token").string(), "two").exit_code, 0);
  EXPECT_EQ(server.wait_exit(), 0) << server.log();
  EXPECT_TRUE(std::filesystem::exists(dir_.path() / "served" / "run-0002" / "packets.csv"));
}

TEST_F(RemoteNetworkHalf, APeersPluginPathsAreNeverLoadedNorTheServersFoldersDisclosed) {
  const std::filesystem::path marker = dir_.path() / "marker";
  ::setenv("SWARMNET_TEST_MARKER", marker.c_str(), 1);
  Server server(dir_.path(), {});
  ::unsetenv("SWARMNET_TEST_MARKER");
  const std::string answer =
      hand_made_peer(server, scenario([](YAML::Node& tree) {
                       tree["plugin_paths"].push_back(SWARMNET_TEST_FIXTURE_DIR "/untrusted");
                       tree["network"]["routing"]["plugin"] = "marker_routing";
                     }),
                     (dir_.path() / "victim").string());
  EXPECT_NE(answer.find("marker_routing"), std::string::npos) << answer;
  EXPECT_FALSE(std::filesystem::exists(marker)) << "the server ran the peer's plugin";
  EXPECT_EQ(answer.find(SWARMNET_TEST_FIXTURE_DIR), std::string::npos) << answer;
  EXPECT_EQ(answer.find(std::string(SWARMNET_SOURCE_DIR)), std::string::npos) << answer;
  EXPECT_EQ(answer.find((dir_.path() / "served").string()), std::string::npos) << answer;
}

TEST_F(RemoteNetworkHalf, APeersRunDirectoryIsNeverWritten) {
  const std::filesystem::path victim = dir_.path() / "victim";
  std::filesystem::create_directories(victim);
  std::ofstream(victim / "packets.csv") << "precious\n";
  Server server(dir_.path(), {});
  EXPECT_EQ(hand_made_peer(server, scenario([](YAML::Node&) {}), victim.string()), "ok");
  EXPECT_EQ(read_file(victim / "packets.csv"), "precious\n");
  EXPECT_EQ(server.wait_exit(), 0) << server.log();
  EXPECT_TRUE(std::filesystem::exists(dir_.path() / "served" / "run-0001" / "packets.csv"));
}

TEST_F(RemoteNetworkHalf, ListeningNeedsAPrivateToken) {
  const CommandResult no_token =
      run_swarmnet("net --listen 0.0.0.0:0 --out " + (dir_.path() / "o").string());
  EXPECT_EQ(no_token.exit_code, 1);
  EXPECT_NE(no_token.output.find("--listen needs a token"), std::string::npos) << no_token.output;
  write_token(dir_.path() / "open", "a token anyone on this machine can read", 0644);
  const CommandResult readable =
      run_swarmnet("net --listen 0 --token-file " + (dir_.path() / "open").string());
  EXPECT_EQ(readable.exit_code, 1);
  EXPECT_NE(readable.output.find("chmod 600"), std::string::npos) << readable.output;
}

// Validation suggests plugin names from file names: a misspelled name must not make it open (and
// so run) every library in the scenario's plugin_paths.
TEST_F(RemoteNetworkHalf, AMisspelledPluginIsAnsweredWithoutLoadingAnyLibrary) {
  const std::filesystem::path file = dir_.path() / "misspelled.yaml";
  std::ofstream(file) << scenario([](YAML::Node& tree) {
    tree["plugin_paths"].push_back(SWARMNET_TEST_FIXTURE_DIR "/untrusted");
    tree["network"]["routing"]["plugin"] = "floodnig";
  });
  const std::filesystem::path marker = dir_.path() / "marker";
  ::setenv("SWARMNET_TEST_MARKER", marker.c_str(), 1);
  const CommandResult validated = run_swarmnet("validate " + file.string());
  ::unsetenv("SWARMNET_TEST_MARKER");
  EXPECT_EQ(validated.exit_code, 2) << validated.output;
  EXPECT_NE(validated.output.find("marker_routing"), std::string::npos) << validated.output;
  EXPECT_NE(validated.output.find("flooding"), std::string::npos) << validated.output;
  EXPECT_FALSE(std::filesystem::exists(marker)) << "validate ran a library's code to list names";
}

// yaml-cpp answers a lookup with the first of two equal keys: a server that removed "the"
// plugin_paths once left the second in place, and loaded the peer's library from it.
TEST_F(RemoteNetworkHalf, ARepeatedPluginPathsKeyIsRefusedAtItsLineAndUsesNoRun) {
  const std::filesystem::path marker = dir_.path() / "marker";
  ::setenv("SWARMNET_TEST_MARKER", marker.c_str(), 1);
  Server server(dir_.path(), {"--runs", "1"});
  ::unsetenv("SWARMNET_TEST_MARKER");
  const std::string text =
      "plugin_paths: []\nplugin_paths: [" SWARMNET_TEST_FIXTURE_DIR "/untrusted]\n" +
      scenario([](YAML::Node& tree) { tree["network"]["routing"]["plugin"] = "marker_routing"; });
  const std::string answer = hand_made_peer(server, text);
  EXPECT_NE(answer.find(":2:1: plugin_paths: is given twice (first at line 1:1)"),
            std::string::npos)
      << answer;
  EXPECT_FALSE(std::filesystem::exists(marker)) << "the server ran the peer's plugin";
  EXPECT_EQ(answer.find(SWARMNET_TEST_FIXTURE_DIR), std::string::npos) << answer;
  // The refusal did not use up the server's only run: a real robot half is served after it.
  const CommandResult served = run_robot_half(server, (dir_.path() / "token").string(), "run");
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  EXPECT_EQ(server.wait_exit(), 0) << server.log();
}

// Quoted, tagged or anchored, the key is plugin_paths to YAML; none of its folders is looked up
// on the server (the old reply told the peer which of its guesses existed there).
TEST_F(RemoteNetworkHalf, PluginPathsUnderAnySpellingAreNeverLookedUpOnTheServer) {
  Server server(dir_.path(), {"--runs", "3"});
  for (const std::string key : {"\"plugin_paths\"", "!!str plugin_paths", "? plugin_paths\n"}) {
    const std::string text = key + (key.back() == '\n' ? ": " : ": ") + "[/nonexistent/dir, " +
                             std::string(SWARMNET_TEST_FIXTURE_DIR) + "/untrusted]\n" + scenario();
    EXPECT_EQ(hand_made_peer(server, text), "ok") << key << "\n" << server.log();
  }
  EXPECT_EQ(server.wait_exit(), 0) << server.log();
  EXPECT_EQ(server.log().find("is not a directory"), std::string::npos) << server.log();
}

// 100 connections that never speak, more than the handshakes allowed in flight, opened before
// the real robot half; the silent peers' own deadline (30 s) is far beyond the robot half's
// patience (--step-timeout 10): it is served only if the server meets it beside them.
TEST_F(RemoteNetworkHalf, AFloodOfSilentPeersDoesNotKeepARealRobotHalfWaiting) {
  Server server(dir_.path(), {"--handshake-timeout", "30"});
  std::vector<int> silent;
  for (int i = 0; i < 100; ++i) {
    silent.push_back(connect_tcp("127.0.0.1", static_cast<std::uint16_t>(server.port())));
  }
  const CommandResult served =
      run_robot_half(server, (dir_.path() / "token").string(), "run", "--step-timeout 10");
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  EXPECT_NE(server.log().find("handshakes were pending"), std::string::npos) << server.log();
  for (const int fd : silent) ::close(fd);
  EXPECT_EQ(server.wait_exit(), 0) << server.log();
}

// 40 attackers that reconnect as soon as they are dropped (at a 1 s deadline), with the default
// 64 handshakes in flight: the old server, one handshake at a time, kept a real robot half out
// for good.
TEST_F(RemoteNetworkHalf, ReconnectingAttackersDoNotKeepARealRobotHalfOut) {
  Server server(dir_.path(), {"--handshake-timeout", "1"});
  std::atomic<bool> attacking{true};
  std::vector<std::thread> attackers;
  const auto port = static_cast<std::uint16_t>(server.port());
  for (int i = 0; i < 40; ++i) {
    attackers.emplace_back([&attacking, port] {
      while (attacking.load()) {
        int fd = -1;
        try {
          fd = connect_tcp("127.0.0.1", port);
        } catch (const std::exception&) {
          continue;  // the server is gone: the test's end
        }
        char byte = 0;
        pollfd p{fd, POLLIN, 0};
        // Silent until the server drops us (its challenge is read and ignored), then again.
        while (attacking.load() && ::poll(&p, 1, 50) >= 0) {
          if ((p.revents & POLLIN) != 0 && ::read(fd, &byte, 1) <= 0) break;
        }
        ::close(fd);
      }
    });
  }
  const CommandResult served =
      run_robot_half(server, (dir_.path() / "token").string(), "run", "--step-timeout 10");
  attacking.store(false);
  for (auto& attacker : attackers) attacker.join();
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  EXPECT_EQ(server.wait_exit(), 0) << server.log();
}

// A step_begin whose start is 2^62 ns had the server simulate toward it, deaf to SIGTERM.
TEST_F(RemoteNetworkHalf, AStepThatIsNotTheNextOneIsRefusedAndTheServerServesOn) {
  Server server(dir_.path(), {"--runs", "3"});
  for (const auto& [step, start_ns, expected] :
       {std::tuple<std::uint64_t, std::int64_t, std::string>{0, std::int64_t{1} << 62,
                                                             "said step 0 starts at"},
        std::tuple<std::uint64_t, std::int64_t, std::string>{5, 500'000'000,
                                                             "sent step 5 where step 0 was due"}}) {
    Session session = hand_made_session(server, scenario());
    ASSERT_EQ(session.error, "") << server.log();
    StepBatch batch;
    batch.step = step;
    batch.start = SimTime{start_ns};
    batch.positions = {Vec2(1.0, 1.0), Vec2(2.0, 2.0)};
    ASSERT_TRUE(session.channel->send_batch(batch).ok());
    StepResult result;
    const ProtocolResult answer = session.channel->receive_result(result);
    EXPECT_FALSE(answer.ok());
    EXPECT_NE(answer.error.find(expected), std::string::npos) << answer.error;
  }
  const CommandResult served = run_robot_half(server, (dir_.path() / "token").string(), "run");
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  EXPECT_EQ(server.wait_exit(), 1) << server.log();  // two of its three runs failed
}

TEST_F(RemoteNetworkHalf, SigtermStopsTheServerMidRunAndTheRobotHalfSaysWhy) {
  Server server(dir_.path(), {"--serve-forever"});
  const std::filesystem::path robot_log = dir_.path() / "robot.log";
  const pid_t robot =
      spawn_swarmnet({"run", std::string(SWARMNET_SOURCE_DIR) + "/configs/quickstart.yaml", "--set",
                      "duration_s=100000", "-q", "--net", server.address(), "--token-file",
                      (dir_.path() / "token").string(), "--out", (dir_.path() / "run").string()},
                     robot_log);
  for (int i = 0; i < 1000 && server.log().find("run run-0001") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_NE(server.log().find("run run-0001"), std::string::npos) << server.log();
  ::kill(server.pid(), SIGTERM);
  EXPECT_EQ(server.wait_exit(), 1) << server.log();
  int status = 0;
  ASSERT_EQ(::waitpid(robot, &status, 0), robot);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0);
  EXPECT_NE(read_file(robot_log).find("stopped by SIGTERM on the network half's host"),
            std::string::npos)
      << read_file(robot_log);
}

// "key: value" lines of /proc/PID/status, in kB.
std::uint64_t status_kb(pid_t pid, const std::string& key) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(key + ":", 0) == 0) return std::stoull(line.substr(key.size() + 1));
  }
  return 0;
}

// Under a budget the kernel enforces, a swarm whose network does not fit is refused before its
// first step, the server serves on, and what a run took goes back to the system after it.
TEST_F(RemoteNetworkHalf, AScenarioBeyondTheMemoryBudgetIsRefusedBeforeItsFirstStep) {
  if (!kernel_memory_limit_available()) {
    GTEST_SKIP() << "AddressSanitizer build: the server sets no kernel memory limit";
  }
  Server server(dir_.path(), {"--max-memory", "4M", "--runs", "1"});
  Session big = hand_made_session(server, scenario([](YAML::Node& tree) {
                                    tree["robots"]["count"] = 100000;
                                    tree["arena"]["width_m"] = 20000;
                                    tree["arena"]["height_m"] = 20000;
                                  }),
                                  100000);
  EXPECT_NE(big.error.find("the network of 100000 robots needs more memory than the server's "
                           "memory budget of 4 MiB (--max-memory) allows"),
            std::string::npos)
      << big.error << server.log();
  big = Session{};
  const CommandResult served = run_robot_half(server, (dir_.path() / "token").string(), "run");
  EXPECT_EQ(served.exit_code, 0) << served.output << server.log();
  EXPECT_EQ(server.wait_exit(), 0) << server.log();  // a refused scenario is not one of --runs
}

TEST_F(RemoteNetworkHalf, OneStepsPayloadIsBoundedByTheMemoryBudget) {
  Server server(dir_.path(), {"--max-memory", "256K"});  // a step may carry 64 KiB
  Session session = hand_made_session(server, scenario());
  ASSERT_EQ(session.error, "") << server.log();
  StepBatch batch;
  batch.positions = {Vec2(1.0, 1.0), Vec2(2.0, 2.0)};
  for (std::uint64_t m = 0; m < 100; ++m) {
    batch.messages.push_back({m, 0, 1, 0, Payload(kMaxPayloadBytes, std::byte{7})});
  }
  ASSERT_TRUE(session.channel->send_batch(batch).ok());
  StepResult result;
  const ProtocolResult answer = session.channel->receive_result(result);
  EXPECT_NE(answer.error.find("sent more than 0 MiB of payload in step 0"), std::string::npos)
      << answer.error;
  EXPECT_EQ(server.wait_exit(), 1) << server.log();
}

TEST_F(RemoteNetworkHalf, TheServerGivesARunsMemoryBackWhenItEnds) {
  if (!kernel_memory_limit_available()) {
    GTEST_SKIP() << "AddressSanitizer build: its quarantine holds freed memory on purpose";
  }
  Server server(dir_.path(), {"--serve-forever"});
  Session session = hand_made_session(server, scenario([](YAML::Node& tree) {
                                        tree["robots"]["count"] = 50000;
                                        tree["arena"]["width_m"] = 10000;
                                        tree["arena"]["height_m"] = 10000;
                                      }),
                                      50000);
  ASSERT_EQ(session.error, "") << server.log();
  ASSERT_TRUE(session.channel->send_finish().ok());
  NetworkReport report;
  ASSERT_TRUE(session.channel->receive_report(report).ok());
  for (int i = 0; i < 500 && server.log().find("idle;") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const std::uint64_t peak_kb = status_kb(server.pid(), "VmHWM");
  const std::uint64_t idle_kb = status_kb(server.pid(), "VmRSS");
  EXPECT_LT(idle_kb * 2, peak_kb) << "idle " << idle_kb << " kB after a peak of " << peak_kb
                                  << " kB\n"
                                  << server.log();
}

// The server's output directory holds every peer's runs: it is created private, and an
// existing one that others may enter is refused with the fix.
TEST_F(RemoteNetworkHalf, TheOutputDirectoryIsPrivate) {
  const std::filesystem::path out = dir_.path() / "deep" / "served";
  const std::filesystem::path log = dir_.path() / "server.log";
  const pid_t server = spawn_swarmnet({"net", "--listen", "127.0.0.1:0", "--token-file",
                                       (dir_.path() / "token").string(), "--out", out.string()},
                                      log);
  for (int i = 0; i < 500 && read_file(log).find("serving") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(server, SIGKILL);
  ::waitpid(server, nullptr, 0);
  ASSERT_NE(read_file(log).find("serving"), std::string::npos) << read_file(log);
  struct stat info {};
  ASSERT_EQ(::stat(out.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777U, 0700U);
  const std::filesystem::path open_dir = dir_.path() / "open";
  std::filesystem::create_directories(open_dir);
  ::chmod(open_dir.c_str(), 0755);
  const CommandResult refused =
      run_swarmnet("net --listen 127.0.0.1:0 --token-file " + (dir_.path() / "token").string() +
                   " --out " + open_dir.string());
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.output.find("may be entered by other users (mode 0755); make it private with "
                                "'chmod 700 " +
                                open_dir.string() + "'"),
            std::string::npos)
      << refused.output;
}

}  // namespace
}  // namespace swarmnet::testing
