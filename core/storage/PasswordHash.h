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
  /// An Argon2id hash with hash()'s parameters of a random password no one knows: a sign-in
  /// with an unknown account name is verified against it, so that it costs what a wrong
  /// password costs. Made once (a constant, checked against this libsodium's parameters with
  /// crypto_pwhash_str_needs_rehash, and made anew once per process if they differ).
  static const std::string& dummyHash();
};

}  // namespace armtrack::storage
