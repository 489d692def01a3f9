#include "coupling/peer_secret.hpp"

#include <fcntl.h>
#include <openssl/rand.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "outputs/run_error.hpp"

namespace swarmnet {

namespace {

constexpr std::size_t kMinSecretBytes = 16;
constexpr std::size_t kMaxSecretBytes = 4096;

}  // namespace

PeerSecret PeerSecret::from_file(const std::filesystem::path& path) {
  const std::string where = "token file " + path.string();
  // Opened once and checked through the descriptor, so the file checked is the file read. Not
  // through a symbolic link (it could be swapped between check and use), and without blocking:
  // opening a FIFO for reading would wait for a writer forever.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    struct stat link {};
    if (error == ELOOP && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
      std::error_code ec;
      const std::filesystem::path target = std::filesystem::canonical(path, ec);
      throw RunError(where + ": is a symbolic link; a token file is not read through one (the " +
                     "link could be pointed elsewhere); name the file itself" +
                     (ec ? std::string() : ": " + target.string()));
    }
    throw RunError(where + ": cannot open it: " + std::strerror(error));
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    const int error = errno;
    ::close(fd);
    throw RunError(where + ": cannot read its status: " + std::strerror(error));
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd);
    const char* kind = S_ISFIFO(info.st_mode)   ? "a FIFO"
                       : S_ISDIR(info.st_mode)  ? "a directory"
                       : S_ISCHR(info.st_mode)  ? "a character device"
                       : S_ISBLK(info.st_mode)  ? "a block device"
                       : S_ISSOCK(info.st_mode) ? "a socket"
                                                : "not a regular file";
    throw RunError(where + ": is " + kind + ", not a regular file; write the token into a " +
                   "regular file only you can read (head -c 32 /dev/urandom | base64 > FILE; " +
                   "chmod 600 FILE) and name that");
  }
  if (info.st_uid != ::geteuid()) {
    ::close(fd);
    throw RunError(where + ": owned by another user; it must be yours");
  }
  if ((info.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    ::close(fd);
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(info.st_mode & 07777U));
    throw RunError(where + ": group or others may access it (mode " + mode +
                   "); make it private with: chmod 600 " + path.string());
  }
  if (info.st_size > static_cast<off_t>(kMaxSecretBytes + 64)) {
    ::close(fd);
    throw RunError(where + ": larger than " + std::to_string(kMaxSecretBytes) + " bytes");
  }
  std::vector<std::byte> bytes(static_cast<std::size_t>(info.st_size));
  const ssize_t got = bytes.empty() ? 0 : ::read(fd, bytes.data(), bytes.size());
  const int read_error = errno;
  ::close(fd);
  if (got < 0 || static_cast<std::size_t>(got) != bytes.size()) {
    throw RunError(where + ": cannot read it: " +
                   (got < 0 ? std::strerror(read_error) : "it changed while being read"));
  }
  while (!bytes.empty()) {
    const auto last = static_cast<unsigned char>(bytes.back());
    if (last != ' ' && last != '\n' && last != '\r' && last != '\t') break;
    bytes.pop_back();
  }
  if (bytes.size() < kMinSecretBytes || bytes.size() > kMaxSecretBytes) {
    throw RunError(where + ": holds " + std::to_string(bytes.size()) + " bytes; a token needs " +
                   std::to_string(kMinSecretBytes) + " to " + std::to_string(kMaxSecretBytes) +
                   " (make one with: head -c 32 /dev/urandom | base64 > " + path.string() + ")");
  }
  return PeerSecret(std::move(bytes));
}

PeerSecret PeerSecret::random() {
  std::vector<std::byte> bytes(32);
  if (RAND_bytes(reinterpret_cast<unsigned char*>(bytes.data()), static_cast<int>(bytes.size())) !=
      1) {
    throw RunError("cannot draw a random secret for the network half");
  }
  return PeerSecret(std::move(bytes));
}

PeerSecret PeerSecret::from_hex(std::string_view hex) {
  auto digit = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
  };
  if (hex.size() % 2 != 0 || hex.size() / 2 < kMinSecretBytes || hex.size() / 2 > kMaxSecretBytes) {
    throw RunError(std::string(kChildSecretVariable) + " is not a secret this program made");
  }
  std::vector<std::byte> bytes(hex.size() / 2);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const int high = digit(hex[2 * i]);
    const int low = digit(hex[2 * i + 1]);
    if (high < 0 || low < 0) {
      throw RunError(std::string(kChildSecretVariable) + " is not a secret this program made");
    }
    bytes[i] = static_cast<std::byte>(high * 16 + low);
  }
  return PeerSecret(std::move(bytes));
}

std::string PeerSecret::hex() const {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text;
  text.reserve(bytes_.size() * 2);
  for (const std::byte b : bytes_) {
    text.push_back(kDigits[std::to_integer<unsigned>(b) >> 4U]);
    text.push_back(kDigits[std::to_integer<unsigned>(b) & 15U]);
  }
  return text;
}

std::filesystem::path token_file_from(const std::string& option) {
  if (!option.empty()) return option;
  const char* variable = std::getenv(kTokenFileVariable);
  return variable == nullptr ? std::filesystem::path() : std::filesystem::path(variable);
}

}  // namespace swarmnet
