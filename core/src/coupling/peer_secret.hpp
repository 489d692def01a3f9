// The secret two halves share when they meet over a socket: read from a token file that only
// its owner can read (a remote network half and the robot halves allowed to use it), or drawn
// at random by a robot half for the child it starts (handed over in the child's environment,
// which other users cannot read).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace swarmnet {

// The environment variable that names the token file when --token-file is not given.
inline constexpr const char* kTokenFileVariable = "SWARMNET_NET_TOKEN_FILE";
// The environment variable through which a robot half hands its child a one-time secret.
inline constexpr const char* kChildSecretVariable = "SWARMNET_NET_SECRET";

class PeerSecret {
 public:
  // The file's bytes, trailing white space removed. Refused (RunError naming the file and the
  // reason and how to fix it) unless it is a regular file (not a symbolic link, FIFO or device)
  // owned by this user, unreadable by group and others, and holds 16 to 4096 bytes.
  static PeerSecret from_file(const std::filesystem::path& path);
  // 32 bytes from the system's random source.
  static PeerSecret random();
  // The form hex() gives, as handed to a child; refused if malformed.
  static PeerSecret from_hex(std::string_view hex);

  [[nodiscard]] std::string hex() const;
  [[nodiscard]] std::span<const std::byte> bytes() const { return bytes_; }

 private:
  explicit PeerSecret(std::vector<std::byte> bytes) : bytes_(std::move(bytes)) {}
  std::vector<std::byte> bytes_;
};

// The token file the command line or the environment names; empty when neither does.
std::filesystem::path token_file_from(const std::string& option);

}  // namespace swarmnet
