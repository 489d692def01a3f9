#include "coupling/peer_authentication.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/rand.h>

#include <array>
#include <cstring>
#include <string_view>
#include <vector>

namespace swarmnet {

namespace {

constexpr std::size_t kNonceBytes = 32;
constexpr std::size_t kMacBytes = 32;  // SHA-256
constexpr std::uint32_t kVersion = 1;
constexpr std::string_view kChallenge = "SWNC";
constexpr std::string_view kAnswer = "SWNA";
constexpr std::string_view kProof = "SWNP";

using Nonce = std::array<unsigned char, kNonceBytes>;
using Mac = std::array<unsigned char, kMacBytes>;

bool draw(Nonce& nonce) { return RAND_bytes(nonce.data(), static_cast<int>(nonce.size())) == 1; }

// HMAC-SHA256(secret, role || first || second).
Mac mac(const PeerSecret& secret, std::string_view role, const Nonce& first, const Nonce& second) {
  std::vector<unsigned char> message(role.begin(), role.end());
  message.insert(message.end(), first.begin(), first.end());
  message.insert(message.end(), second.begin(), second.end());
  Mac out{};
  unsigned int length = 0;
  HMAC(EVP_sha256(), secret.bytes().data(), static_cast<int>(secret.bytes().size()), message.data(),
       message.size(), out.data(), &length);
  return out;
}

void append(std::vector<std::byte>& record, const void* data, std::size_t bytes) {
  const auto* begin = static_cast<const std::byte*>(data);
  record.insert(record.end(), begin, begin + bytes);
}

IoStatus send(Transport& transport, const std::vector<std::byte>& record) {
  const IoStatus status = transport.send(record);
  return status == IoStatus::ok ? transport.flush() : status;
}

// Receives one record of exactly `bytes` bytes starting with `tag`; "" or why not.
std::string receive(Transport& transport, std::string_view tag, std::size_t bytes,
                    std::vector<std::byte>& record) {
  const IoStatus status = transport.receive(record);
  if (status != IoStatus::ok)
    return std::string("no ") + std::string(tag) + " record: " + to_string(status);
  if (record.size() != bytes || std::memcmp(record.data(), tag.data(), tag.size()) != 0) {
    return "a malformed authentication record (" + std::to_string(record.size()) + " bytes)";
  }
  return "";
}

}  // namespace

std::string authenticate_connector(Transport& transport, const PeerSecret& secret) {
  Nonce ours{};
  if (!draw(ours)) return "cannot draw a random challenge";
  std::vector<std::byte> record;
  append(record, kChallenge.data(), kChallenge.size());
  append(record, &kVersion, sizeof kVersion);
  append(record, ours.data(), ours.size());
  if (const IoStatus s = send(transport, record); s != IoStatus::ok) {
    return std::string("cannot send the challenge: ") + to_string(s);
  }
  if (std::string why =
          receive(transport, kAnswer, kAnswer.size() + kNonceBytes + kMacBytes, record);
      !why.empty()) {
    return why;
  }
  Nonce theirs{};
  std::memcpy(theirs.data(), record.data() + kAnswer.size(), kNonceBytes);
  const Mac expected = mac(secret, "connector", ours, theirs);
  if (CRYPTO_memcmp(expected.data(), record.data() + kAnswer.size() + kNonceBytes, kMacBytes) !=
      0) {
    return "the peer did not prove that it knows the token";
  }
  const Mac proof = mac(secret, "acceptor", theirs, ours);
  record.clear();
  append(record, kProof.data(), kProof.size());
  append(record, proof.data(), proof.size());
  if (const IoStatus s = send(transport, record); s != IoStatus::ok) {
    return std::string("cannot send the proof: ") + to_string(s);
  }
  return "";
}

std::string authenticate_to_acceptor(Transport& transport, const PeerSecret& secret) {
  std::vector<std::byte> record;
  if (std::string why =
          receive(transport, kChallenge, kChallenge.size() + sizeof kVersion + kNonceBytes, record);
      !why.empty()) {
    return "the network half did not authenticate: " + why;
  }
  std::uint32_t version = 0;
  std::memcpy(&version, record.data() + kChallenge.size(), sizeof version);
  if (version != kVersion) {
    return "the network half speaks authentication version " + std::to_string(version) +
           ", this one version " + std::to_string(kVersion);
  }
  Nonce theirs{};
  std::memcpy(theirs.data(), record.data() + kChallenge.size() + sizeof version, kNonceBytes);
  Nonce ours{};
  if (!draw(ours)) return "cannot draw a random nonce";
  const Mac answer = mac(secret, "connector", theirs, ours);
  record.clear();
  append(record, kAnswer.data(), kAnswer.size());
  append(record, ours.data(), ours.size());
  append(record, answer.data(), answer.size());
  if (const IoStatus s = send(transport, record); s != IoStatus::ok) {
    return std::string("cannot answer the challenge: ") + to_string(s);
  }
  if (std::string why = receive(transport, kProof, kProof.size() + kMacBytes, record);
      !why.empty()) {
    return "the network half refused the token (is it the one the network half was started "
           "with?): " +
           why;
  }
  const Mac expected = mac(secret, "acceptor", ours, theirs);
  if (CRYPTO_memcmp(expected.data(), record.data() + kProof.size(), kMacBytes) != 0) {
    return "the network half did not prove that it knows the token";
  }
  return "";
}

}  // namespace swarmnet
