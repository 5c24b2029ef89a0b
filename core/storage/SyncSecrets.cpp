#include "core/storage/SyncSecrets.h"

#include <sodium.h>

#include <QByteArray>
#include <array>
#include <stdexcept>

namespace armtrack::storage {

namespace {

constexpr char kCrockford[] = "0123456789ABCDEFGHJKMNPQRSTVWXYZ";
constexpr int kCodeLength = 12;

void initSodium() {
  static const bool ready = sodium_init() >= 0;
  if (!ready) throw std::runtime_error("libsodium could not be initialised");
}

}  // namespace

QString newEnrolmentCode() {
  initSodium();
  QString code;
  for (int i = 0; i < kCodeLength; ++i) {
    if (i > 0 && i % 4 == 0) code += '-';
    code += QChar(kCrockford[randombytes_uniform(32)]);
  }
  return code;
}

QString normalisedEnrolmentCode(const QString& code) {
  QString out;
  for (QChar c : code) {
    if (c == '-' || c == ' ') continue;
    c = c.toUpper();
    if (c == 'O') c = '0';
    if (c == 'I' || c == 'L') c = '1';
    if (c.unicode() > 127 || !QByteArray(kCrockford).contains(static_cast<char>(c.unicode())))
      return {};
    out += c;
    if (out.size() > kCodeLength) return {};
  }
  return out.size() == kCodeLength ? out : QString();
}

QString newDeviceToken() {
  initSodium();
  std::array<unsigned char, 32> bytes{};
  randombytes_buf(bytes.data(), bytes.size());
  return QString::fromLatin1(
      QByteArray(reinterpret_cast<const char*>(bytes.data()), bytes.size())
          .toBase64(QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals));
}

bool looksLikeDeviceToken(const QString& token) {
  if (token.size() != 43) return false;
  for (QChar c : token)
    if (!(c.isDigit() || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '-' || c == '_'))
      return false;
  return true;
}

QString secretHash(const QString& purpose, const QString& secret) {
  initSodium();
  const QByteArray input = "armtrack-" + purpose.toUtf8() + '\0' + secret.toUtf8();
  std::array<unsigned char, 32> out{};
  crypto_generichash(out.data(), out.size(), reinterpret_cast<const unsigned char*>(input.data()),
                     static_cast<unsigned long long>(input.size()), nullptr, 0);
  return QString::fromLatin1(
      QByteArray(reinterpret_cast<const char*>(out.data()), out.size()).toHex());
}

}  // namespace armtrack::storage
