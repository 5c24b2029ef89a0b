// The clinical records service: signed-in access to users, patients, protocols, sessions and
// their recordings, with access control and the audit log (docs/storage.md).
#pragma once

#include <QString>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/ArmSample.h"
#include "core/io/Recording.h"
#include "core/storage/AuditLog.h"
#include "core/storage/Database.h"
#include "core/storage/Records.h"
#include "core/storage/RecordsCheck.h"

namespace armtrack::storage {

/// The column groups of a session's stored columns mask (SessionInfo::columnsMask).
RecordingColumns columnsOf(int columnsMask);

/// Throws StorageError (Usage) unless the trunk limit is empty or 1-90 deg, saying so.
void checkTrunkLimit(const std::optional<double>& limitDeg);
/// The trunk limit as the audit log names it: "trunk limit 15 deg", "trunk limit off".
QString trunkLimitText(const std::optional<double>& limitDeg);

/// Every read and write of the records goes through here, as the signed-in user. Access rules:
/// administrators may do everything; therapists everything but managing accounts, backups,
/// migrations and reading the audit log; a home account sees and records only its own patient
/// (another patient is reported as not found, so its existence does not leak). Exports, changes
/// and refusals are written to the audit log. Throws StorageError. Same thread as the Database.
class ClinicalStore {
 public:
  /// Wraps an open database. Sessions left in "recording" by a process of this host that no
  /// longer runs are marked "interrupted" here (see interruptedOnOpen()); on a read-only database
  /// they are left as they are and counted (staleRecordingsKept()).
  explicit ClinicalStore(Database& db);

  /// Creates the first administrator of an empty database; refused when any account exists.
  /// The name follows checkName (TextRules.h), the password checkNewPassword.
  void initialise(const QString& adminName, const std::string& password);
  /// Signs in; the name is found without regard to case (nameKey). After 3 consecutive wrong
  /// passwords each attempt must wait 2^(n-3) s (at most 300 s) after the last failure; an
  /// early attempt is refused without checking the password. A name without an account gets the
  /// same answers, at the same cost (verified against PasswordHash::dummyHash(), its failures
  /// counted in sign_in_failures). Throws StorageError(Authentication) with the same text for
  /// an unknown name and a wrong password. Every failure is audited.
  const User& signIn(const QString& name, const std::string& password);
  const User& user() const;
  int interruptedOnOpen() const { return m_interruptedOnOpen; }
  /// Imports whose process had died, removed when this store was made.
  int removedImportsOnOpen() const { return m_removedImportsOnOpen; }
  /// Sessions left in "recording" by a process of this host that has ended, which were not
  /// marked "interrupted" because the database is read-only (Database::readOnlyReason()); the
  /// next opening with write access marks them.
  int staleRecordingsKept() const { return m_staleRecordingsKept; }
  /// The database this store reads and writes, for the checks of callers that write files
  /// (Database::refuseOwnFile, isReadOnly).
  Database& database() const { return m_db; }

  // Accounts (administrators; ClinicalStoreAccounts.cpp). Names are unique and found without
  // regard to case; a new name follows checkName, a new password checkNewPassword
  // (TextRules.h): StorageError(Usage) otherwise, Exists for a name taken in any case.
  qint64 addUser(const QString& name, Role role, const std::string& password,
                 const QString& patientCode = {});
  std::vector<User> listUsers();
  /// An administrator's, or the account's own, password change.
  void setPassword(const QString& name, const std::string& password);
  /// Admin only. A disabled account keeps its name, sessions and audit entries but cannot sign
  /// in (signIn refuses it after checking the password); enabling it lets it in again. An
  /// administrator cannot disable itself. Audited when it changes something.
  void setUserDisabled(const QString& name, bool disabled);
  void removeUser(const QString& name);

  // The whole database (administrators), audited.
  /// Database::backup to outPath: every patient, recording, account and the audit log, so an
  /// administrator's act. Throws AccessDenied for others, and as Database::backup.
  void backup(const QString& outPath);
  /// Audits the migration that opening the database applied (`db migrate`). Throws
  /// AccessDenied for others than administrators.
  void confirmMigration(int stepsApplied);

  /// Refuses the signed-in account what it asked for: writes an "access-denied" audit entry
  /// (after the transaction the caller may be in, so that a rollback keeps it) and throws
  /// StorageError(AccessDenied) with message, or "account 'NAME' (ROLE) may not WHAT".
  [[noreturn]] void deny(const QString& what, const std::string& message = {}) const;

  // Home devices that sync with armtrack-server (ClinicalStoreDevices.cpp, docs/sync.md).
  /// A one-time enrolment code for a home account (administrators and therapists), valid for
  /// validForS seconds (1 minute to 30 days). Only its hash is stored (SyncSecrets.h). Audited.
  EnrolmentCode createEnrolmentCode(const QString& homeAccount, qint64 validForS);
  /// Enrols a device with a code, signed in or not: the code is used up, a new device token is
  /// made (only its hash stored) and this store is then signed in as the code's home account,
  /// as that device. A wrong, used or expired code, or a disabled account, throws
  /// StorageError(Authentication) with one message for all (the audit log says which).
  DeviceEnrolment enrolDevice(const QString& code, const QString& deviceLabel);
  /// Signs in as the home account of the device with this token (not revoked, account not
  /// disabled); throws StorageError(Authentication) otherwise, audited.
  const User& signInWithDeviceToken(const QString& token);
  /// The device signed in with (enrolDevice, signInWithDeviceToken); 0 otherwise.
  qint64 deviceId() const { return m_deviceId; }
  /// The home accounts of the patient with this code, by name, disabled ones too
  /// (administrators and therapists: whom to make an enrolment code for).
  std::vector<User> listHomeAccounts(const QString& patientCode);
  /// The devices of a home account, revoked ones too (administrators and therapists).
  std::vector<DeviceInfo> listDevices(const QString& homeAccount);
  /// Revokes a device's token for good (administrators and therapists). Audited.
  void revokeDevice(qint64 deviceId);
  /// Acts as a clinic service (armtrack-server) with a therapist's rights and no account: for a
  /// process that already holds the database's own credentials, to analyse what a device sent.
  /// The audit log names it by serviceName.
  void signInAsService(const QString& serviceName);

  // Patients (create/update: administrators and therapists; delete: administrators). Codes are
  // unique and found without regard to case; codes, names and free text follow TextRules.h.
  qint64 addPatient(const Patient& patient);
  std::vector<Patient> listPatients();
  Patient patient(const QString& code);
  void updatePatient(const Patient& patient);  ///< by code
  void removePatient(const QString& code);     ///< with its sessions

  // Protocols (everyone reads; administrators and therapists write). Names as patient codes.
  qint64 addProtocol(const Protocol& protocol);
  std::vector<Protocol> listProtocols();
  Protocol protocol(const QString& name);
  void updateProtocol(const Protocol& protocol);  ///< by name
  void removeProtocol(const QString& name);

  // Home programmes (ClinicalStoreProgrammes.cpp; change: administrators and therapists; read:
  // as the patient).
  /// Puts the protocol in the patient's programme with sessions per week and notes, its other
  /// values at their defaults (one set, the protocol's repetitions and target, 60 s rest). An
  /// entry for the same protocol is replaced and keeps its place.
  void assignProtocol(const QString& patientCode, const QString& protocolName, int sessionsPerWeek,
                      const QString& notes = {});
  /// Puts item's protocol in the patient's programme as an exercise, replacing the entry for the
  /// same protocol. item.position 0 puts it after the last; another position puts it there and
  /// moves the later ones down (positions stay 1, 2, ...). Throws StorageError(Usage) for a value
  /// out of range (ProgrammeItem says which), NotFound for an unknown patient or protocol.
  void setProgrammeExercise(const QString& patientCode, const ProgrammeItem& item);
  void unassignProtocol(const QString& patientCode, const QString& protocolName);
  /// The programme in its order.
  std::vector<ProgrammeItem> programme(const QString& patientCode);
  /// The patient's own outcome of a home session: the pain score (0-10, or none), a comment (at
  /// most 2000 characters) and the summary of what the home window counted (a JSON object,
  /// docs/storage.md). Only a home account writes it, for its own patient's home sessions: the
  /// words are the patient's. Throws AccessDenied, NotFound, Usage.
  void saveHomeOutcome(qint64 sessionId, std::optional<int> painScore, const QString& comment,
                       const QString& summaryJson);

  // Sessions and recordings (ClinicalStoreSessions.cpp).
  /// Starts a session in status "recording" owned by this process, marked as recorded at home when
  /// a home account begins it (kSettingHome), else at the clinic. calibrationJson is the
  /// recording's sidecar text; settings says what it is recorded with (StorageError(Usage) when
  /// either is not a JSON object).
  qint64 beginSession(const QString& patientCode, const QString& protocolName,
                      const QString& calibrationJson, int columnsMask,
                      const SessionSettings& settings = {});
  /// beginSession for a recording with this sidecar and these columns (a live session recording
  /// into the records, see DatabaseRecordingSink).
  qint64 beginRecording(const QString& patientCode, const QString& protocolName,
                        const RecordingMeta& meta, const RecordingColumns& columns,
                        const SessionSettings& settings = {});
  /// The session's stored sidecar (geometry, gravity, side, camera). Throws NotFound, Corrupt.
  RecordingMeta recordingMeta(qint64 sessionId);
  /// The time of the session's first stored row (s, the session clock), where recording time
  /// begins (core/metrics/SessionTime.h); nothing before a row is stored. Throws NotFound.
  std::optional<double> recordingStartS(qint64 sessionId);
  /// An account's name, for reports (administrators and therapists). Throws NotFound.
  QString userName(qint64 userId);
  /// Stores samples as the session's next chunk in one transaction (a chunk is ~1 s).
  void appendChunk(qint64 sessionId, std::span<const ArmSample> samples);
  void finishSession(qint64 sessionId, const QString& status = kStatusComplete);
  /// What importRecording saw in the file.
  struct ImportReport {
    std::vector<std::string> warnings;  ///< the reader's: a missing sidecar, a cut line, gaps
    bool cutShort = false;              ///< the last line was incomplete: stored as interrupted
    std::uint64_t rows = 0;
    TimeGaps gaps;  ///< jumps in time, stored as they are
  };
  /// Told of each chunk of an import once it is committed: the new session's id, the chunk's
  /// samples (valid during the call) and the fraction of the file read. It may throw to stop the
  /// import (which is then removed).
  using ImportObserver =
      std::function<void(qint64 sessionId, std::span<const ArmSample> samples, double fraction)>;
  /// Reads a recording file (CSV and sidecar) into a new session, ~1 s per chunk: complete, or
  /// interrupted when the file was cut short. All or nothing: a file refused half-way, a full
  /// disk or a lock leaves no session (one that cannot be removed at once, e.g. under a lock,
  /// is removed when the database is next opened after this process has ended).
  qint64 importRecording(const std::filesystem::path& csv, const QString& patientCode,
                         const QString& protocolName = {}, ImportReport* report = nullptr,
                         const ImportObserver& stored = {});
  std::vector<SessionInfo> listSessions(const QString& patientCode);
  SessionInfo session(qint64 sessionId);
  void updateSessionNotes(qint64 sessionId, const QString& notes);
  /// Sets the filter settings the session's analyses use (filter_json; administrators and
  /// therapists). Throws StorageError(Usage) when json is not a JSON object.
  void updateSessionFilterSettings(qint64 sessionId, const QString& json);
  void removeSession(qint64 sessionId);
  /// The stored recording. Throws StorageError(Corrupt) naming the session and chunk when a
  /// chunk cannot be decoded.
  Recording readRecording(qint64 sessionId);
  /// The stored recording chunk by chunk, for work that must not hold it whole (an hour at 1 kHz
  /// is 1.3 GB as samples): chunk gets each chunk's samples in time order (valid during the call)
  /// and returns false to stop; the result is then false. Checks and throws as readRecording,
  /// the row count after the last chunk.
  bool readRecordingChunks(qint64 sessionId,
                           const std::function<bool(std::span<const ArmSample>)>& chunk);
  /// Writes the stored recording in the open format (CSV + sidecar) and audits the export.
  void exportRecording(qint64 sessionId, const std::filesystem::path& csv);

  // Estimates, metrics and the analysis state (ClinicalStoreAnalysis.cpp): each analysis is a
  // new version; earlier ones stay as history.
  int saveEstimates(qint64 sessionId, const QString& paramsJson, const QString& codec,
                    const QByteArray& data);
  int saveMetrics(qint64 sessionId, const QString& perAngleJson, const QString& perRepetitionJson);
  /// The newest metrics (per-angle JSON, per-repetition JSON), if any.
  std::optional<std::pair<QString, QString>> latestMetrics(qint64 sessionId);
  /// The number of finished versions of the session's estimates (they are numbered 1, 2, ...).
  int estimateVersions(qint64 sessionId);
  /// One finished version of the estimates (0 = the newest), if there is one.
  std::optional<EstimateRecord> estimates(qint64 sessionId, int version = 0);
  /// The chunks of a version stored in chunks, in order: chunk gets each one's sequence number,
  /// row count and blob.
  void readEstimateChunks(
      const EstimateRecord& record,
      const std::function<void(int seq, std::uint64_t rows, const QByteArray& data)>& chunk);

  /// A version of the estimates being written chunk by chunk (an hour at 1 kHz is about 190 MB
  /// compressed, too much to hold and write as one value). Readers do not see it until
  /// finishAnalysis; one left by a process that died is removed by the session's next analysis.
  struct EstimatesDraft {
    qint64 id = 0;  ///< the estimates row
    qint64 sessionId = 0;
    int version = 0;  ///< negative until finished
  };
  /// Starts a draft (administrators and therapists) and marks the session's analysis as being
  /// run by this process.
  EstimatesDraft beginEstimates(qint64 sessionId, const QString& codec);
  /// Stores one chunk of the draft (rows rows, an EstimateCodec blob) in a transaction of its own.
  void appendEstimateChunk(const EstimatesDraft& draft, int seq, qint64 rows,
                           const QByteArray& blob);
  struct AnalysisVersions {
    int estimates = 0;
    int metrics = 0;
  };
  /// The rows a version of the metrics was computed from, encoded (SessionAnalysis.h).
  struct StoredSeries {
    QString codec;  ///< empty: none stored
    QByteArray data;
  };
  /// The newest metrics' series, when they have one (analyses before schema 6 have none).
  std::optional<StoredSeries> latestMetricSeries(qint64 sessionId);
  /// In one transaction: the draft becomes the newest version with its parameters, the metrics
  /// are stored (perRepetitionJson is given the estimates' version), the session's analysis is
  /// done, and it is audited.
  AnalysisVersions finishAnalysis(
      const EstimatesDraft& draft, const QString& paramsJson, const QString& perAngleJson,
      const std::function<QString(int estimateVersion)>& perRepetitionJson,
      const StoredSeries& series = {});
  /// Removes an unfinished draft (a cancelled or failed analysis); the session's analysis stays
  /// as it was.
  void abandonEstimates(const EstimatesDraft& draft);
  /// Marks the session's analysis failed: its recording cannot be analysed, for reason why.
  void markAnalysisFailed(qint64 sessionId, const QString& why);
  /// Complete sessions visible to the user whose analysis is pending and not being run by a
  /// live process of this host, oldest first.
  std::vector<qint64> pendingAnalyses();

  // Audit log (administrators read it).
  std::vector<AuditEntry> auditLog();
  void audit(const QString& action, const QString& objectType, const QString& objectId,
             const QString& detail = {});

  // Checks (RecordsCheck.cpp; docs/storage.md, "Checks").
  /// db check's check of the recordings and estimates: every session the user sees (a home
  /// account: its patient's) that is not being recorded, decoded chunk by chunk
  /// (recordingProblems(Decode), estimateProblems). Throws StorageError(Io).
  RecordsCheckReport checkRecords();
  /// What exports and reports call before writing anything: throws StorageError(Corrupt) with
  /// damagedRecordingMessage() when the session's recording fails
  /// recordingProblems(Checksums); NotFound for a session the user does not see.
  void requireIntactRecording(qint64 sessionId);
  /// The audit log's hash chain verified (administrators; verifyAuditChain).
  AuditChainReport verifyAuditLog(const std::optional<AuditAnchor>& expect = {});

 private:
  void require(bool allowed, const QString& what) const;  // deny(what) unless allowed
  /// Throws StorageError(Exists) when a row of table has key in keyColumn (what names it).
  void refuseTakenKey(const QString& table, const QString& column, const QString& keyColumn,
                      const QString& key, const QString& what, const QString& value);
  bool isStaff() const;
  qint64 visiblePatientId(const QString& code);  // NotFound for invisible ones
  SessionInfo visibleSession(qint64 sessionId);  // NotFound for invisible ones
  /// The session's status after the same check, from its row alone (no chunk totals): for the
  /// calls that only need to know the session is there for this account.
  QString visibleSessionStatus(qint64 sessionId);
  void requireVisible(bool found, qint64 patientId, qint64 sessionId) const;
  std::optional<qint64> protocolId(const QString& name);
  int markDeadRecordingsInterrupted();
  void removeFailedImport(qint64 sessionId);
  void removeDeadDrafts(qint64 sessionId);  // in a transaction
  void lockSessionRow(qint64 sessionId);    // in a transaction: PostgreSQL's row lock
  int insertMetrics(qint64 sessionId, const QString& perAngleJson, const QString& perRepetitionJson,
                    const StoredSeries& series = {});  // in a transaction; the version
  void renumberProgramme(qint64 patientId);  // positions 1, 2, ... in their order; in a transaction

  Database& m_db;
  std::optional<User> m_user;
  int m_interruptedOnOpen = 0;
  int m_removedImportsOnOpen = 0;
  int m_staleRecordingsKept = 0;
  qint64 m_deviceId = 0;
};

}  // namespace armtrack::storage
