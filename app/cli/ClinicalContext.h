// Internal to the clinical-records commands: opening the database and signing in.
#pragma once

#include <QCoreApplication>
#include <QJsonDocument>
#include <memory>
#include <ostream>
#include <string>

#include "app/cli/Args.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::cli {

/// specs plus the options every database command accepts (--db, --user).
inline std::vector<OptionSpec> withDb(std::vector<OptionSpec> specs) {
  specs.push_back({"--db", true});
  specs.push_back({"--user", true});
  return specs;
}

/// An open database with its signed-in store, and the QCoreApplication Qt Sql needs to load its
/// driver when the caller has none.
class ClinicalContext {
 public:
  /// Opens --db with options; with signIn, signs in as --user (password: passwordFromUser()).
  ClinicalContext(const Args& a, storage::Database::Options options, bool signIn);
  storage::Database& db() { return *m_db; }
  storage::ClinicalStore& store() { return *m_store; }

  /// A connection of its own, for work on another thread.
  struct Connection {
    std::unique_ptr<storage::Database> db;
    std::unique_ptr<storage::ClinicalStore> store;  // ends before db
  };
  /// Opens the same database again, signed in as the same user when this context signed in. Call
  /// it on the thread that will use the connection (Qt Sql connections belong to one thread).
  Connection connectAgain() const;

 private:
  std::unique_ptr<QCoreApplication> m_app;
  storage::DatabaseUrl m_url;
  std::string m_user, m_password;  // empty when not signed in
  std::unique_ptr<storage::Database> m_db;
  std::unique_ptr<storage::ClinicalStore> m_store;
};

/// The one positional argument, a session id (a positive whole number); a usage error otherwise.
qint64 sessionIdArgument(const Args& a);
/// text as a session id (a positive whole number); a usage error of a otherwise.
qint64 sessionIdFrom(const Args& a, const std::string& text);

/// ARMTRACK_PASSWORD, else a prompt on the terminal (echo off) when standard input is one; throws
/// std::runtime_error saying how to give it otherwise. what names the account, for the prompt.
std::string passwordFromUser(const std::string& what);

/// Estimates a session just stored (imported or recorded) and stores its metrics, telling err
/// how it went; a session that cannot be analysed stays stored, with a warning saying why. Home
/// accounts do not analyse: err says a therapist can.
void analyseNewSession(storage::ClinicalStore& store, qint64 id, const std::string& command,
                       std::ostream& err);

/// Writes doc indented, for --json.
inline void printJson(std::ostream& out, const QJsonDocument& doc) {
  out << doc.toJson(QJsonDocument::Indented).toStdString();
}

/// QString from a std::string and back.
inline QString qs(const std::string& s) {
  return QString::fromStdString(s);
}
inline std::string ss(const QString& s) {
  return s.toStdString();
}

}  // namespace armtrack::cli
