// Before any step-protocol record is parsed, a peer on a socket proves that it knows the shared
// secret, and the side it connected to proves the same back (mutual challenge and response; the
// secret itself never crosses the wire):
//
//   acceptor  -> connector  challenge: "SWNC", version, 32-byte nonce A
//   connector -> acceptor   answer:    "SWNA", 32-byte nonce C, HMAC-SHA256(secret, "connector" A
//   C) acceptor  -> connector  proof:     "SWNP", HMAC-SHA256(secret, "acceptor" C A)
//
// Answers are compared in constant time (CRYPTO_memcmp). A record of the wrong size or kind ends
// the exchange; the acceptor tells a refused peer nothing about why.
#pragma once

#include <string>

#include "coupling/peer_secret.hpp"
#include "transport.hpp"

namespace swarmnet {

// The side that accepted the connection. Returns "" when the peer proved it knows `secret`,
// else what went wrong, for this side's log.
std::string authenticate_connector(Transport& transport, const PeerSecret& secret);

// The side that connected. Returns "" when both proofs held, else the reason.
std::string authenticate_to_acceptor(Transport& transport, const PeerSecret& secret);

}  // namespace swarmnet
