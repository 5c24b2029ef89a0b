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

const std::string& PasswordHash::dummyHash() {
  // Made once with crypto_pwhash_str at the interactive limits (64 MiB, 2 passes) from 32
  // random bytes that were then thrown away.
  static const std::string hash = [] {
    ensureInit();
    std::string made =
        "$argon2id$v=19$m=65536,t=2,p=1$Tr/KCRm6pHrWQ1hKyCVLFw$"
        "Qgg1s1n6TO/jH2UGiD7IAZKCS1CyZMrAOcXhKsNFmGU";
    if (crypto_pwhash_str_needs_rehash(made.c_str(), crypto_pwhash_OPSLIMIT_INTERACTIVE,
                                       crypto_pwhash_MEMLIMIT_INTERACTIVE) != 0) {
      unsigned char secret[32];
      randombytes_buf(secret, sizeof secret);
      made = PasswordHash::hash(std::string(reinterpret_cast<const char*>(secret), sizeof secret));
      sodium_memzero(secret, sizeof secret);
    }
    return made;
  }();
  return hash;
}

bool PasswordHash::verify(const std::string& hash, const std::string& password) {
  ensureInit();
  if (hash.size() >= crypto_pwhash_STRBYTES) return false;
  return crypto_pwhash_str_verify(hash.c_str(), password.data(), password.size()) == 0;
}

}  // namespace armtrack::storage
