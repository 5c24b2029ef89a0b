// Home devices in the records (issue 28; docs/sync.md): enrolment codes used once and within
// their time, device tokens stored hashed and revocable, uploads idempotent and kept per patient,
// every enrolment, refusal and revocation audited; and schema 9 added to a version 8 database.
#include <gtest/gtest.h>

#include <QUuid>

#include "core/storage/SyncSecrets.h"
#include "core/storage/SyncUploads.h"
#include "tests/core/storage/StorageTestSupport.h"

using namespace armtrack;
using namespace armtrack::storage;
using namespace armtrack::storage::test;

namespace {

using SyncStorage = Engines;
using MigrationToSync = Engines;

constexpr const char* kHomePassword = "home password 123";

/// A fixture with patients P1 and P2, each with a home account (home1, home2).
struct HomeFixture : Fixture {
  explicit HomeFixture(Engine e) : Fixture(e) {
    store->addPatient(makePatient("P1"));
    store->addPatient(makePatient("P2"));
    store->addUser("home1", Role::Home, kHomePassword, "P1");
    store->addUser("home2", Role::Home, kHomePassword, "P2");
  }
  int count(const QString& action) {
    int n = 0;
    for (const AuditEntry& e : store->auditLog()) n += e.action == action;
    return n;
  }
};

}  // namespace

TEST(SyncSecrets, CodesAndTokensHaveTheirFormAndAreReadForgivingly) {
  const QString code = newEnrolmentCode();
  ASSERT_EQ(code.size(), 14);
  EXPECT_EQ(code[4], '-');
  EXPECT_EQ(normalisedEnrolmentCode(code).size(), 12);
  EXPECT_EQ(normalisedEnrolmentCode(code.toLower()), normalisedEnrolmentCode(code));
  EXPECT_EQ(normalisedEnrolmentCode("abcd efgh-jkmo"), "ABCDEFGHJKM0");
  EXPECT_EQ(normalisedEnrolmentCode("ilIL-0000-0000"), "111100000000");
  EXPECT_TRUE(normalisedEnrolmentCode("").isEmpty());
  EXPECT_TRUE(normalisedEnrolmentCode("UUUU-0000-0000").isEmpty());  // U is not Crockford
  EXPECT_TRUE(normalisedEnrolmentCode("0000-0000-00000").isEmpty());
  EXPECT_TRUE(normalisedEnrolmentCode(QString::fromUtf8("ÄÄÄÄ-0000-0000")).isEmpty());
  const QString token = newDeviceToken();
  EXPECT_TRUE(looksLikeDeviceToken(token)) << token.toStdString();
  EXPECT_NE(token, newDeviceToken());
  EXPECT_FALSE(looksLikeDeviceToken(token + "x"));
  EXPECT_FALSE(looksLikeDeviceToken(QString(43, '/')));
  // Hashes differ by purpose and secret; the same input always gives the same hash.
  EXPECT_EQ(secretHash("device-token", token), secretHash("device-token", token));
  EXPECT_NE(secretHash("device-token", token), secretHash("enrolment-code", token));
  EXPECT_EQ(secretHash("device-token", token).size(), 64);
}

TEST_P(SyncStorage, AValidCodeEnrolsOnceAndOnlyItsHashIsStored) {
  HomeFixture f(GetParam());
  const EnrolmentCode code = f.store->createEnrolmentCode("home1", 3600);
  EXPECT_GT(code.expiresAt, utcNow());
  ClinicalStore device(*f.db);
  const DeviceEnrolment e = device.enrolDevice(code.code.toLower(), "tablet");
  EXPECT_EQ(e.patientCode, "P1");
  EXPECT_GT(e.deviceId, 0);
  EXPECT_EQ(device.user().name, "home1");
  EXPECT_EQ(device.deviceId(), e.deviceId);
  // Neither the code nor the token is anywhere in the database, only their hashes.
  const auto codes = rawQuery(f.path, "SELECT code_hash FROM enrolment_codes");
  ASSERT_EQ(codes.size(), 1u);
  EXPECT_EQ(codes[0][0].toString(),
            secretHash("enrolment-code", normalisedEnrolmentCode(code.code)));
  const auto tokens = rawQuery(f.path, "SELECT token_hash FROM devices");
  ASSERT_EQ(tokens.size(), 1u);
  EXPECT_EQ(tokens[0][0].toString(), secretHash("device-token", e.token));
  // Used once only.
  ClinicalStore again(*f.db);
  expectError([&] { again.enrolDevice(code.code, "second"); }, Kind::Authentication,
              "wrong, used or expired");
  EXPECT_EQ(f.count("enrol"), 1);
  EXPECT_EQ(f.count("enrol-refused"), 1);
  // The token signs in as the home account, and sees only its patient.
  ClinicalStore later(*f.db);
  EXPECT_EQ(later.signInWithDeviceToken(e.token).name, "home1");
  expectError([&] { later.programme("P2"); }, Kind::NotFound);
}

TEST_P(SyncStorage, WrongExpiredAndMalformedCodesAreRefusedAlikeAndAudited) {
  HomeFixture f(GetParam());
  const EnrolmentCode code = f.store->createEnrolmentCode("home1", 60);
  f.db->exec("UPDATE enrolment_codes SET expires_at = '2020-01-01T00:00:00.000Z'");
  const auto refused = [&](const QString& text) {
    ClinicalStore s(*f.db);
    return std::string(expectError([&] { s.enrolDevice(text, {}); }, Kind::Authentication).what());
  };
  const std::string expired = refused(code.code);
  EXPECT_EQ(refused(newEnrolmentCode()), expired);  // wrong: the same words
  EXPECT_EQ(refused("not a code at all"), expired);
  EXPECT_EQ(refused(""), expired);
  EXPECT_EQ(f.count("enrol-refused"), 4);
  bool sawExpired = false;
  for (const AuditEntry& e : f.store->auditLog())
    sawExpired |= e.action == "enrol-refused" && e.detail.contains("expired");
  EXPECT_TRUE(sawExpired);
  EXPECT_TRUE(rawQuery(f.path, "SELECT id FROM devices").empty());
}

TEST_P(SyncStorage, CodesAreMadeByStaffForHomeAccountsOnly) {
  HomeFixture f(GetParam());
  expectError([&] { f.store->createEnrolmentCode("admin", 3600); }, Kind::Usage, "home accounts");
  expectError([&] { f.store->createEnrolmentCode("nobody", 3600); }, Kind::NotFound);
  expectError([&] { f.store->createEnrolmentCode("home1", 10); }, Kind::Usage);
  expectError([&] { f.store->createEnrolmentCode("home1", 31 * 24 * 3600); }, Kind::Usage);
  ClinicalStore home(*f.db);
  home.signIn("home1", kHomePassword);
  expectError([&] { home.createEnrolmentCode("home1", 3600); }, Kind::AccessDenied);
  // A disabled account's code does not enrol.
  const EnrolmentCode code = f.store->createEnrolmentCode("home2", 3600);
  f.store->setUserDisabled("home2", true);
  ClinicalStore device(*f.db);
  expectError([&] { device.enrolDevice(code.code, {}); }, Kind::Authentication);
}

TEST_P(SyncStorage, APatientsHomeAccountsAreListedForStaffOnly) {
  HomeFixture f(GetParam());
  f.store->addUser("Home1b", Role::Home, kHomePassword, "P1");
  f.store->addUser("carer", Role::Therapist, kHomePassword);
  f.store->setUserDisabled("home1", true);
  ClinicalStore therapist(*f.db);
  therapist.signIn("carer", kHomePassword);
  const std::vector<User> p1 = therapist.listHomeAccounts("p1");  // codes found in any case
  ASSERT_EQ(p1.size(), 2u);
  EXPECT_EQ(p1[0].name, "home1");
  EXPECT_TRUE(p1[0].disabled);
  EXPECT_EQ(p1[1].name, "Home1b");
  EXPECT_FALSE(p1[1].disabled);
  EXPECT_EQ(p1[1].role, Role::Home);
  ASSERT_EQ(f.store->listHomeAccounts("P2").size(), 1u);
  EXPECT_EQ(f.store->listHomeAccounts("P2")[0].name, "home2");
  EXPECT_TRUE(f.store->listHomeAccounts("P9").empty());
  ClinicalStore home(*f.db);
  home.signIn("home2", kHomePassword);
  expectError([&] { home.listHomeAccounts("P2"); }, Kind::AccessDenied);
}

TEST_P(SyncStorage, ARevokedTokenNoLongerSignsIn) {
  HomeFixture f(GetParam());
  ClinicalStore device(*f.db);
  const DeviceEnrolment e =
      device.enrolDevice(f.store->createEnrolmentCode("home1", 3600).code, "phone");
  const std::vector<DeviceInfo> devices = f.store->listDevices("home1");
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0].label, "phone");
  EXPECT_FALSE(devices[0].lastSeenAt.isEmpty());
  f.store->revokeDevice(e.deviceId);
  EXPECT_FALSE(f.store->listDevices("home1")[0].revokedAt.isEmpty());
  ClinicalStore later(*f.db);
  expectError([&] { later.signInWithDeviceToken(e.token); }, Kind::Authentication, "revoked");
  expectError([&] { f.store->revokeDevice(e.deviceId); }, Kind::NotFound);
  EXPECT_EQ(f.count("revoke"), 1);
  EXPECT_EQ(f.count("sync-refused"), 1);
}

TEST_P(SyncStorage, UploadsAreIdempotentAndInvisibleToAnotherPatient) {
  HomeFixture f(GetParam());
  const std::filesystem::path csv = f.file("rec.csv");
  simulateTo(csv, 3.0, 100.0);
  const QByteArray bytes = QByteArray::fromStdString(fileBytes(csv));
  ClinicalStore d1(*f.db), d2(*f.db);
  d1.enrolDevice(f.store->createEnrolmentCode("home1", 3600).code, {});
  d2.enrolDevice(f.store->createEnrolmentCode("home2", 3600).code, {});
  SyncUploads up1(d1), up2(d2);
  const QString uuid = QUuid::createUuid().toString(QUuid::WithoutBraces);
  const qsizetype half = bytes.size() / 2;
  const QList<QByteArray> chunks{bytes.left(half), bytes.mid(half)};
  UploadMeta meta;
  meta.sha256 = sha256Hex(bytes);
  meta.sizeBytes = bytes.size();
  meta.chunkCount = 2;
  meta.metaJson = R"({"outcome":{"pain_score":3,"comment":"tired","summary":{"sets":2}}})";
  EXPECT_TRUE(up1.declare(uuid, meta).created);
  const UploadState again = up1.declare(uuid, meta);
  EXPECT_FALSE(again.created);
  EXPECT_EQ(again.missing, (std::vector<int>{0, 1}));
  UploadMeta other = meta;
  other.sha256 = sha256Hex("other");
  expectError([&] { up1.declare(uuid, other); }, Kind::Exists);
  // Another patient's device: as if there were no such upload.
  const std::string absent =
      expectError([&] { up2.state(QUuid::createUuid().toString(QUuid::WithoutBraces)); },
                  Kind::NotFound)
          .what();
  EXPECT_EQ(expectError([&] { up2.state(uuid); }, Kind::NotFound).what(), absent);
  expectError([&] { up2.declare(uuid, meta); }, Kind::NotFound);
  expectError([&] { up2.putChunk(uuid, 0, chunks[0], sha256Hex(chunks[0])); }, Kind::NotFound);
  // A chunk that does not match its checksum is not kept.
  QByteArray tampered = chunks[0];
  tampered[10] = tampered[10] == 'x' ? 'y' : 'x';
  expectError([&] { up1.putChunk(uuid, 0, tampered, sha256Hex(chunks[0])); }, Kind::Corrupt);
  EXPECT_EQ(up1.state(uuid).missing.size(), 2u);
  up1.putChunk(uuid, 0, chunks[0], sha256Hex(chunks[0]));
  up1.putChunk(uuid, 0, chunks[0], sha256Hex(chunks[0]));  // again: nothing to do
  expectError([&] { up1.putChunk(uuid, 5, chunks[0], sha256Hex(chunks[0])); }, Kind::Usage);
  expectError([&] { up1.complete(uuid, {}); }, Kind::Usage, "missing");
  up1.putChunk(uuid, 1, chunks[1], sha256Hex(chunks[1]));
  const qint64 id = up1.complete(uuid, {});
  EXPECT_EQ(up1.complete(uuid, {}), id);
  EXPECT_EQ(f.store->listSessions("P1").size(), 1u);
  EXPECT_TRUE(f.store->listSessions("P2").empty());
  const SessionInfo stored = f.store->session(id);
  EXPECT_EQ(stored.setting, kSettingHome);
  EXPECT_EQ(stored.painScore, 3);
  EXPECT_EQ(stored.patientComment, "tired");
  EXPECT_EQ(stored.homeSummaryJson, R"({"sets":2})");
  // Outcomes and protocols are checked when declared, before any chunk is sent.
  for (const char* bad : {R"({"outcome":{"pain_score":11}})", R"({"outcome":{"pain_score":2.5}})",
                          R"({"outcome":"bad"})", R"({"outcome":{"summary":[1]}})",
                          R"({"protocol":"no such protocol"})"}) {
    UploadMeta m = meta;
    m.metaJson = bad;
    expectError([&] { up1.declare(QUuid::createUuid().toString(QUuid::WithoutBraces), m); },
                Kind::Usage);
  }
  UploadMeta longComment = meta;
  longComment.metaJson = QString(R"({"outcome":{"comment":"%1"}})").arg(QString(2001, 'x'));
  expectError([&] { up1.declare(QUuid::createUuid().toString(QUuid::WithoutBraces), longComment); },
              Kind::Usage);
  EXPECT_EQ(rawQuery(f.path, "SELECT count(*) FROM sync_upload_chunks")[0][0].toInt(), 0);
}

// The version before sync's step (8 on this branch) with a home account: made by dropping the
// new tables and setting the version back one step, so the test holds whatever number the step
// takes.
TEST_P(MigrationToSync, FromTheVersionBeforeKeepsEverythingAndEnrols) {
  Fixture f(GetParam());
  f.store->addPatient(makePatient("OLD"));
  f.store->addUser("oldhome", Role::Home, kHomePassword, "OLD");
  f.close();
  rawSql(f.path,
         {"DROP TABLE sync_upload_chunks", "DROP TABLE sync_uploads", "DROP TABLE devices",
          "DROP TABLE enrolment_codes",
          "UPDATE schema_version SET version = " + QString::number(latestSchemaVersion() - 1)});
  expectError([&] { Database db(DatabaseUrl::parse(f.path), {}); }, Kind::OlderSchema);
  Database db(DatabaseUrl::parse(f.path), {false, true});
  EXPECT_EQ(db.migrationsApplied(), 1);
  EXPECT_EQ(db.schemaVersion(), latestSchemaVersion());
  ClinicalStore store(db);
  store.signIn("admin", kAdminPassword);
  EXPECT_EQ(store.patient("OLD").name, "Name of OLD");
  ClinicalStore device(db);
  EXPECT_EQ(device.enrolDevice(store.createEnrolmentCode("oldhome", 600).code, {}).patientCode,
            "OLD");
}

INSTANTIATE_TEST_SUITE_P(Engines, SyncStorage, testing::Values(Engine::Sqlite, Engine::Postgres),
                         engineName);
INSTANTIATE_TEST_SUITE_P(Engines, MigrationToSync,
                         testing::Values(Engine::Sqlite, Engine::Postgres), engineName);
