// Internal to the clinical-records commands: opening the database and signing in.
#pragma once

#include <QCoreApplication>
#include <QJsonDocument>
#include <memory>
#include <ostream>
#include <string>

#include "app/cli/Args.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/SessionAnalysis.h"

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
  /// A staff member's sign-in first runs the analyses left pending (analysePendingSessions, told
  /// on noticeStream()) unless runPending is false (checks, backups, and commands that analyse
  /// what they are told anyway).
  ClinicalContext(const Args& a, storage::Database::Options options, bool signIn,
                  bool runPending = true);
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
/// how it went. A session whose recording cannot be analysed stays stored, with a warning
/// saying why (true); an analysis stopped by the database (a lock, a full disk) leaves the
/// session's analysis pending and returns false after saying so: the command then fails. Home
/// accounts do not analyse: err says when it will be.
bool analyseNewSession(storage::ClinicalStore& store, qint64 id, const std::string& command,
                       std::ostream& err);
/// Tells err what an analysis stored (version, filter, repetitions, smoothness), as one line.
void describeAnalysis(const storage::AnalysisResult& r, const std::string& command,
                      std::ostream& err);
/// Tells err why session id's analysis failed: true when the recording itself cannot be
/// analysed (a warning: the session is marked so), false when the database stopped it (an
/// error: the analysis stays pending for the next command).
bool reportAnalysisFailure(qint64 id, const storage::StorageError& e, std::ostream& err);
/// Analyses the complete sessions whose analysis is pending (their program ended before it was
/// stored), telling err; stops at the first that the database stops. Staff only; nothing for a
/// home account.
void analysePendingSessions(storage::ClinicalStore& store, std::ostream& err);

/// Where a ClinicalContext tells what it did on its own (pending analyses): the err stream of
/// the running command (runCli sets it), else standard error.
std::ostream& noticeStream();
/// Sets noticeStream() for the lifetime of the object.
class ScopedNoticeStream {
 public:
  explicit ScopedNoticeStream(std::ostream& err);
  ~ScopedNoticeStream();
  ScopedNoticeStream(const ScopedNoticeStream&) = delete;
  ScopedNoticeStream& operator=(const ScopedNoticeStream&) = delete;

 private:
  std::ostream* m_previous;
};

/// The subcommand (first word) and the words after it; help when there is none.
inline std::pair<std::string, std::vector<std::string>> splitSubcommand(
    const std::vector<std::string>& args) {
  if (args.empty() || args[0].starts_with("-")) return {"", args};
  return {args[0], std::vector<std::string>(args.begin() + 1, args.end())};
}

/// A subcommand's function: the words after it, standard output and error; the exit status.
using SubcommandFn = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

/// Runs the subcommand of command named by args' first word from table (name, function); prints
/// help for --help alone; UsageError for a missing or unknown one.
inline int dispatchSubcommand(const char* command, std::string_view help,
                              const std::vector<std::string>& args, std::ostream& out,
                              std::ostream& err,
                              const std::vector<std::pair<std::string, SubcommandFn>>& table) {
  const auto [sub, rest] = splitSubcommand(args);
  if (sub.empty()) {
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) return out << help, 0;
    throw UsageError(command, "missing subcommand");
  }
  for (const auto& [name, fn] : table)
    if (sub == name) return fn(rest, out, err);
  throw UsageError(command, "unknown subcommand '" + sub + "'");
}

/// Prints a patient's home programme in its order (a line per exercise, or JSON), with the
/// protocol's repetitions and target where the programme has none of its own.
void listProgramme(storage::ClinicalStore& store, const QString& patientCode, bool json,
                   std::ostream& out);
/// --trunk-limit: absent (nothing to change), a number of degrees, or emptyWord ("off" for a
/// protocol, "protocol" for an exercise: its protocol's), which gives an empty limit. The range
/// is the store's to check. ProgrammeCommands.cpp.
std::optional<std::optional<double>> trunkLimitArg(const Args& a, std::string_view emptyWord);

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
