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

/// Every read and write of the records goes through here, as the signed-in user. Access rules:
/// administrators may do everything; therapists everything but managing accounts and reading the
/// audit log; a home account sees and records only its own patient (another patient is reported
/// as not found, so its existence does not leak). Exports and changes are written to the audit
/// log. Throws StorageError. Same thread as the Database.
class ClinicalStore {
 public:
  /// Wraps an open database. Sessions left in "recording" by a process of this host that no
  /// longer runs are marked "interrupted" here (see interruptedOnOpen()).
  explicit ClinicalStore(Database& db);

  /// Creates the first administrator of an empty database; refused when any account exists.
  void initialise(const QString& adminName, const std::string& password);
  /// Signs in. After 3 consecutive wrong passwords each attempt must wait 2^(n-3) s (at most
  /// 300 s) after the last failure; an early attempt is refused without checking the password.
  /// Throws StorageError(Authentication) with the same text for an unknown name and a wrong
  /// password.
  const User& signIn(const QString& name, const std::string& password);
  const User& user() const;
  int interruptedOnOpen() const { return m_interruptedOnOpen; }

  // Accounts (administrators).
  qint64 addUser(const QString& name, Role role, const std::string& password,
                 const QString& patientCode = {});
  std::vector<User> listUsers();
  void setPassword(const QString& name, const std::string& password);
  void removeUser(const QString& name);

  // Patients (create/update: administrators and therapists; delete: administrators).
  qint64 addPatient(const Patient& patient);
  std::vector<Patient> listPatients();
  Patient patient(const QString& code);
  void updatePatient(const Patient& patient);  ///< by code
  void removePatient(const QString& code);     ///< with its sessions

  // Protocols (everyone reads; administrators and therapists write).
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
  /// An account's name, for reports (administrators and therapists). Throws NotFound.
  QString userName(qint64 userId);
  /// Stores samples as the session's next chunk in one transaction (a chunk is ~1 s).
  void appendChunk(qint64 sessionId, std::span<const ArmSample> samples);
  void finishSession(qint64 sessionId, const QString& status = kStatusComplete);
  /// Reads a recording file (CSV and sidecar) into a new complete session, ~1 s per chunk.
  qint64 importRecording(const std::filesystem::path& csv, const QString& patientCode,
                         const QString& protocolName = {});
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

  // Estimates and metrics: each save is a new version; earlier ones stay as history.
  int saveEstimates(qint64 sessionId, const QString& paramsJson, const QString& codec,
                    const QByteArray& data);
  int saveMetrics(qint64 sessionId, const QString& perAngleJson, const QString& perRepetitionJson);
  /// The newest metrics (per-angle JSON, per-repetition JSON), if any.
  std::optional<std::pair<QString, QString>> latestMetrics(qint64 sessionId);
  int estimateVersions(qint64 sessionId);
  /// One stored version of the estimates (0 = the newest), if there is one.
  std::optional<EstimateRecord> estimates(qint64 sessionId, int version = 0);

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
  void require(bool allowed, const QString& what) const;
  bool isStaff() const;
  qint64 visiblePatientId(const QString& code);  // NotFound for invisible ones
  SessionInfo visibleSession(qint64 sessionId);  // NotFound for invisible ones
  std::optional<qint64> protocolId(const QString& name);
  int markDeadRecordingsInterrupted();
  void renumberProgramme(qint64 patientId);  // positions 1, 2, ... in their order; in a transaction

  Database& m_db;
  std::optional<User> m_user;
  int m_interruptedOnOpen = 0;
};

}  // namespace armtrack::storage
