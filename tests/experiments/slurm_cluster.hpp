// A one-node Slurm cluster on localhost, for tests: munged, slurmctld and slurmd from Debian's
// packages, run as root from a temporary directory with a generated key and slurm.conf (no
// system file is read or written: every path is in the directory, the ports are free ones).
// start() says why it could not start (missing binaries, a daemon that did not come up, with its
// log); the destructor cancels every job, stops every daemon it started by its pid file and
// removes the directory. SLURM_CONF is set for this process (and so for the commands it runs)
// while the cluster is up.
#pragma once

#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace swarmnet::testing {

class SlurmCluster {
 public:
  SlurmCluster() = default;
  SlurmCluster(const SlurmCluster&) = delete;
  SlurmCluster& operator=(const SlurmCluster&) = delete;
  ~SlurmCluster() { stop(); }

  // Starts the cluster and waits (at most `timeout`) until its node is idle. Returns "" when it
  // is up, else why not.
  std::string start(std::chrono::seconds timeout = std::chrono::seconds(60)) {
    for (const char* program :
         {"munged", "slurmctld", "slurmd", "sbatch", "squeue", "scontrol", "sinfo", "scancel"}) {
      if (find_program(program).empty()) {
        return std::string(program) + " is not installed (apt-get install slurm-wlm munge)";
      }
    }
    if (::geteuid() != 0) return "the daemons run as root here, and this test is not root";
    std::string pattern = "/tmp/swarmnet-slurm-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) return "cannot create a temporary directory";
    dir_ = pattern;
    // munged wants its socket's directory searchable by all, and no one else writing there.
    ::chmod(dir_.c_str(), 0711);

    std::string error = start_munge();
    if (!error.empty()) return error;
    error = write_config();
    if (!error.empty()) return error;
    ::setenv("SLURM_CONF", config().c_str(), 1);
    if (const auto r = run({find_program("slurmctld"), "-f", config().string()}); r.first != 0) {
      return "slurmctld did not start: " + r.second + tail(dir_ / "slurmctld.log");
    }
    if (const auto r = run({find_program("slurmd"), "-f", config().string()}); r.first != 0) {
      return "slurmd did not start: " + r.second + tail(dir_ / "slurmd.log");
    }
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    std::string state;
    while (std::chrono::steady_clock::now() < deadline) {
      const auto r = run({"sinfo", "-h", "-N", "-o", "%t"});
      state = r.second;
      if (r.first == 0 && state.starts_with("idle")) return "";
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    return "the node did not become idle within " + std::to_string(timeout.count()) +
           " s (sinfo: " + state + ")" + tail(dir_ / "slurmctld.log") + tail(dir_ / "slurmd.log");
  }

  // slurm.conf's MaxArraySize (set before start()): a small one makes a sweep several arrays.
  void set_max_array_size(std::size_t size) { max_array_size_ = size; }

  [[nodiscard]] std::filesystem::path config() const { return dir_ / "slurm.conf"; }
  [[nodiscard]] const std::filesystem::path& directory() const { return dir_; }

  // Cancels every job, stops the daemons (slurmd, slurmctld, munged) and removes the directory.
  void stop() {
    if (dir_.empty()) return;
    if (std::filesystem::exists(dir_ / "slurmctld.pid")) {
      (void)run({"scancel", "--full", "--quiet", "--user=root"});
      for (int i = 0; i < 100; ++i) {
        const auto r = run({"squeue", "-h"});
        if (r.first != 0 || r.second.empty()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    }
    for (const char* daemon : {"slurmd", "slurmctld", "munged"}) stop_daemon(dir_ / daemon);
    ::unsetenv("SLURM_CONF");
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
    dir_.clear();
  }

  // Runs a command (no shell), returning its exit code and its output (stdout and stderr).
  static std::pair<int, std::string> run(const std::vector<std::string>& arguments) {
    std::string command;
    for (const auto& argument : arguments) command += quoted(argument) + " ";
    command += "2>&1 </dev/null";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return {-1, "cannot run " + arguments.front()};
    std::string output;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
      output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
  }

  // Processes (not ended) whose command line names `dir`: "PID command" lines.
  static std::string processes_using(const std::filesystem::path& dir) {
    std::string found;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
      const std::string name = entry.path().filename().string();
      if (name.find_first_not_of("0123456789") != std::string::npos) continue;
      std::ifstream in(entry.path() / "cmdline", std::ios::binary);
      std::string command((std::istreambuf_iterator<char>(in)), {});
      std::replace(command.begin(), command.end(), '\0', ' ');
      if (command.find(dir.string()) != std::string::npos && !is_zombie(std::stoi(name))) {
        found += name + " " + command + "\n";
      }
    }
    return found;
  }

  // The program's path on PATH or in an sbin directory ("" when absent).
  static std::string find_program(const std::string& name) {
    std::string path = std::getenv("PATH") != nullptr ? std::getenv("PATH") : "";
    path += ":/usr/sbin:/sbin:/usr/local/sbin";
    std::stringstream dirs(path);
    for (std::string dir; std::getline(dirs, dir, ':');) {
      if (dir.empty()) continue;
      const auto candidate = std::filesystem::path(dir) / name;
      if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    return "";
  }

 private:
  static std::string quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
  }

  static std::string tail(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::string text = "\n--- last lines of " + log.string() + ":";
    for (std::size_t i = lines.size() > 8 ? lines.size() - 8 : 0; i < lines.size(); ++i) {
      text += "\n" + lines[i];
    }
    return text;
  }

  // Two ports nobody listens on now: bound to port 0 together, then released.
  static std::optional<std::pair<int, int>> free_ports() {
    std::array<int, 2> sockets = {-1, -1};
    std::array<int, 2> ports = {0, 0};
    for (std::size_t i = 0; i < 2; ++i) {
      sockets[i] = ::socket(AF_INET, SOCK_STREAM, 0);
      sockaddr_in address{};
      address.sin_family = AF_INET;
      address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      socklen_t length = sizeof address;
      if (sockets[i] < 0 ||
          ::bind(sockets[i], reinterpret_cast<sockaddr*>(&address), length) != 0 ||
          ::getsockname(sockets[i], reinterpret_cast<sockaddr*>(&address), &length) != 0) {
        for (const int s : sockets) {
          if (s >= 0) ::close(s);
        }
        return std::nullopt;
      }
      ports[i] = ntohs(address.sin_port);
    }
    for (const int s : sockets) ::close(s);
    return std::make_pair(ports[0], ports[1]);
  }

  std::string start_munge() {
    const auto key = dir_ / "munge.key";
    {
      std::ifstream random("/dev/urandom", std::ios::binary);
      std::array<char, 1024> bytes{};
      random.read(bytes.data(), bytes.size());
      std::ofstream(key, std::ios::binary).write(bytes.data(), bytes.size());
    }
    ::chmod(key.c_str(), 0400);
    const auto r = run({find_program("munged"), "--key-file=" + key.string(),
                        "--socket=" + (dir_ / "munge.sock").string(),
                        "--pid-file=" + (dir_ / "munged.pid").string(),
                        "--log-file=" + (dir_ / "munged.log").string(),
                        "--seed-file=" + (dir_ / "munged.seed").string()});
    if (r.first != 0) return "munged did not start: " + r.second + tail(dir_ / "munged.log");
    return "";
  }

  std::string write_config() {
    const auto ports = free_ports();
    if (!ports) return "no free TCP port on 127.0.0.1";
    std::array<char, 256> name{};
    ::gethostname(name.data(), name.size() - 1);
    std::string host = name.data();
    host = host.substr(0, host.find('.'));
    const unsigned cpus = std::max(1U, std::thread::hardware_concurrency());
    const std::string d = dir_.string();
    std::filesystem::create_directories(dir_ / "state");
    std::filesystem::create_directories(dir_ / "spool");
    std::ofstream conf(config());
    conf << "ClusterName=swarmnet-test\n"
         << "SlurmctldHost=" << host << "(127.0.0.1)\n"
         << "SlurmctldPort=" << ports->first << "\nSlurmdPort=" << ports->second << "\n"
         << "AuthType=auth/munge\nAuthInfo=socket=" << d << "/munge.sock\nCredType=cred/munge\n"
         << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
         << "SelectType=select/cons_tres\nSelectTypeParameters=CR_CPU\n"
         << "SlurmUser=root\nSlurmdUser=root\nMpiDefault=none\nReturnToService=2\n"
         << "JobAcctGatherType=jobacct_gather/none\n"
         << "AccountingStorageType=accounting_storage/none\nJobCompType=jobcomp/none\n"
         << "StateSaveLocation=" << d << "/state\nSlurmdSpoolDir=" << d << "/spool\n"
         << "SlurmctldPidFile=" << d << "/slurmctld.pid\nSlurmdPidFile=" << d << "/slurmd.pid\n"
         << "SlurmctldLogFile=" << d << "/slurmctld.log\nSlurmdLogFile=" << d << "/slurmd.log\n"
         << "NodeName=" << host << " NodeAddr=127.0.0.1 CPUs=" << cpus << " State=UNKNOWN\n"
         << "PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n"
         << "MaxArraySize=" << max_array_size_ << "\n";
    return conf ? "" : "cannot write " + config().string();
  }

  // An ended process its parent has not reaped yet (PID 1 of a container may never reap it).
  static bool is_zombie(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    std::getline(stat, line);
    const auto paren = line.rfind(')');
    return paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] == 'Z';
  }

  // SIGTERM by the daemon's pid file, then SIGKILL if it is still there after 10 s.
  static void stop_daemon(const std::filesystem::path& base) {
    std::ifstream in(base.string() + ".pid");
    pid_t pid = 0;
    if (!(in >> pid) || pid <= 1) return;
    if (::kill(pid, SIGTERM) != 0) return;
    for (int i = 0; i < 100; ++i) {
      if (::kill(pid, 0) != 0 || is_zombie(pid)) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ::kill(pid, SIGKILL);
  }

  std::filesystem::path dir_;
  std::size_t max_array_size_ = 1001;  // Slurm's default
};

}  // namespace swarmnet::testing
