// Password hashing with libsodium's Argon2id (crypto_pwhash_str).
#pragma once

#include <string>

namespace armtrack::storage {

/// Argon2id hashes in libsodium's self-describing string form ("$argon2id$v=19$m=...").
/// Any thread (libsodium is initialised once, thread-safely).
class PasswordHash {
 public:
  /// A new salted hash of password with the "interactive" cost (64 MiB, ~0.1 s). Throws
  /// std::runtime_error when out of memory.
  static std::string hash(const std::string& password);
  /// Whether password matches hash; false for a malformed hash.
  static bool verify(const std::string& hash, const std::string& password);
};

}  // namespace armtrack::storage
