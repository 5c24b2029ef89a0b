// Internal to the clinical-records commands: opening the database and signing in.
#pragma once

#include <QCoreApplication>
#include <memory>
#include <string>

#include "app/cli/Args.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::cli {

/// The options every database command accepts (besides its own).
inline const std::vector<OptionSpec> kDbOptions{{"--db", true}, {"--user", true}};

/// An open database with its signed-in store, and the QCoreApplication Qt Sql needs to load its
/// driver when the caller has none.
class ClinicalContext {
 public:
  /// Opens --db with options; with signIn, signs in as --user (password: passwordFromUser()).
  ClinicalContext(const Args& a, storage::Database::Options options, bool signIn);
  storage::Database& db() { return *m_db; }
  storage::ClinicalStore& store() { return *m_store; }

 private:
  std::unique_ptr<QCoreApplication> m_app;
  std::unique_ptr<storage::Database> m_db;
  std::unique_ptr<storage::ClinicalStore> m_store;
};

/// ARMTRACK_PASSWORD, else a prompt on the terminal (echo off) when standard input is one; throws
/// std::runtime_error saying how to give it otherwise. what names the account, for the prompt.
std::string passwordFromUser(const std::string& what);

/// QString from a std::string and back.
inline QString qs(const std::string& s) { return QString::fromStdString(s); }
inline std::string ss(const QString& s) { return s.toStdString(); }

}  // namespace armtrack::cli
