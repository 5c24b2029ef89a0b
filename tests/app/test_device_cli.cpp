// armtrack-cli device (docs/sync.md): a therapist makes a one-time enrolment code for a home
// account, the code enrols a device once, the device is listed and revoked; home accounts and
// absurd values are refused.
#include <gtest/gtest.h>

#include "core/storage/ClinicalStore.h"
#include "tests/app/StorageCliFixture.h"

using namespace armtrack::test;
namespace storage = armtrack::storage;

TEST_P(StorageCli, DeviceCodeEnrolsOnceAndRevokeStopsTheDevice) {
  addPatients();
  ::setenv("ARMTRACK_NEW_PASSWORD", "home-pass-1", 1);
  ASSERT_EQ(run({"user", "add", "home1", "--role", "home", "--patient", "P01"}).code, 0);
  Result r = run({"device", "code", "--account", "home1", "--hours", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string code = r.out.substr(0, r.out.find('\n'));
  EXPECT_EQ(code.size(), 14u) << code;
  EXPECT_NE(r.err.find("valid until"), std::string::npos) << r.err;

  std::string token;
  {
    storage::Database db(storage::DatabaseUrl::parse(QString::fromStdString(m_db)), {});
    storage::ClinicalStore device(db);
    const storage::DeviceEnrolment e = device.enrolDevice(QString::fromStdString(code), "tablet");
    EXPECT_EQ(e.patientCode, "P01");
    token = e.token.toStdString();
    storage::ClinicalStore again(db);
    EXPECT_THROW(again.enrolDevice(QString::fromStdString(code), {}), storage::StorageError);
  }
  r = run({"device", "list", "--account", "home1"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("1\ttablet\t", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("active"), std::string::npos) << r.out;
  ASSERT_EQ(run({"device", "revoke", "1"}).code, 0);
  EXPECT_NE(run({"device", "list", "--account", "home1"}).out.find("revoked"), std::string::npos);
  EXPECT_EQ(run({"device", "revoke", "1"}).code, 1);  // revoked already: nothing to revoke
  {
    storage::Database db(storage::DatabaseUrl::parse(QString::fromStdString(m_db)), {});
    storage::ClinicalStore later(db);
    EXPECT_THROW(later.signInWithDeviceToken(QString::fromStdString(token)), storage::StorageError);
  }
  // Refusals: a home account, an absurd validity, a staff account, garbage.
  EXPECT_EQ(run({"device", "code", "--account", "home1"}, "home1", "home-pass-1").code, 1);
  EXPECT_EQ(run({"device", "code", "--account", "home1", "--hours", "0"}).code, 2);
  EXPECT_EQ(run({"device", "code", "--account", "home1", "--hours", "99999"}).code, 2);
  EXPECT_EQ(run({"device", "code", "--account", "boss"}).code, 1);
  EXPECT_EQ(run({"device", "revoke", "x"}).code, 2);
  EXPECT_EQ(run({"device", "revoke", "-3"}).code, 2);
  EXPECT_EQ(run({"device", "code"}).code, 2);
}

INSTANTIATE_TEST_SUITE_P(Engines, StorageCli, testing::Values(Engine::Sqlite, Engine::Postgres),
                         armtrack::test::engineName);
