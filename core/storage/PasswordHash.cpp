#include "core/storage/PasswordHash.h"

#include <sodium.h>

#include <stdexcept>

namespace armtrack::storage {

namespace {

void ensureInit() {
  static const int rc = sodium_init();  // thread-safe static; 1 = already initialised
  if (rc < 0) throw std::runtime_error("libsodium could not be initialised");
}

}  // namespace

std::string PasswordHash::hash(const std::string& password) {
  ensureInit();
  char out[crypto_pwhash_STRBYTES];
  if (crypto_pwhash_str(out, password.data(), password.size(), crypto_pwhash_OPSLIMIT_INTERACTIVE,
                        crypto_pwhash_MEMLIMIT_INTERACTIVE) != 0)
    throw std::runtime_error("out of memory while hashing a password");
  return out;
}

bool PasswordHash::verify(const std::string& hash, const std::string& password) {
  ensureInit();
  if (hash.size() >= crypto_pwhash_STRBYTES) return false;
  return crypto_pwhash_str_verify(hash.c_str(), password.data(), password.size()) == 0;
}

}  // namespace armtrack::storage
