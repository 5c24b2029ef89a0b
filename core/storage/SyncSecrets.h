// The secrets of home-device sync (docs/sync.md, "Enrolment"): one-time enrolment codes a
// therapist reads out or prints, per-device tokens, and the hashes the database keeps of both.
#pragma once

#include <QString>

namespace armtrack::storage {

/// A new enrolment code: 12 characters of Crockford's base32 (60 random bits) in three groups,
/// "7KQ2-M9XD-4TRA". Any thread.
QString newEnrolmentCode();
/// code as typed, in the form it is hashed in: upper case, without spaces or hyphens, with O read
/// as 0 and I, L as 1 (Crockford). Empty when it is not 12 such characters.
QString normalisedEnrolmentCode(const QString& code);
/// A new device token: 32 random bytes, base64url without padding (43 characters).
QString newDeviceToken();
/// Whether token has the form newDeviceToken() gives (checked before any database lookup).
bool looksLikeDeviceToken(const QString& token);

/// What the database keeps of a secret: BLAKE2b-256 (libsodium crypto_generichash) of a purpose
/// label ("enrolment-code", "device-token") and the secret, lower-case hex. A fast hash is right
/// here, unlike for passwords: both secrets are random with 60 and 256 bits, so no guess list
/// helps, and an unsalted hash lets the server find the row by an indexed lookup instead of
/// running Argon2id against every row (which would hand anyone a cheap way to load the server).
QString secretHash(const QString& purpose, const QString& secret);

}  // namespace armtrack::storage
