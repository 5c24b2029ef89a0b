// Where the live screen records when the user presses Record: a recording file (the open CSV
// format) or the clinical records. The session's rows reach it through a gate that drops them
// while recording is paused (GatedRecordingSink.h).
#pragma once

#include <QString>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>

#include "core/io/Recording.h"
#include "core/storage/DatabaseUrl.h"
#include "core/storage/Records.h"

class QObject;

namespace armtrack::storage {
class ClinicalStore;
}

namespace armtrack::app::gui {

class RecordingTarget {
 public:
  virtual ~RecordingTarget() = default;
  /// How the session is made, stored with it when it begins (the records; a file ignores it):
  /// the devices as `armtrack-cli record --db` stores them (app/plugins/DeviceRecord.h), the
  /// live filter and the sensor calibration's verdict. The session's control thread sets it
  /// once the devices are made; begin() reads it. Any thread.
  void setSessionSettings(const storage::SessionSettings& settings) {
    std::lock_guard lock(m_settingsMutex);
    m_settings = settings;
  }
  storage::SessionSettings sessionSettings() const {
    std::lock_guard lock(m_settingsMutex);
    return m_settings;
  }
  /// Where, in words, for the screen ("recording.csv", "the records of patient P01").
  virtual QString describe() const = 0;
  /// GUI thread, when Record is first pressed: what must happen before rows flow (the records:
  /// the session's row, one short insert). Returns an empty string, or what is wrong.
  virtual QString begin(const RecordingMeta& meta, const RecordingColumns& columns) = 0;
  /// The session's recorder thread, with the first row to record: opens the sink. Throws
  /// RecordingError with a message a user can act on.
  virtual std::unique_ptr<RecordingSink> open(const RecordingMeta& meta,
                                              const RecordingColumns& columns) = 0;
  /// GUI thread, after the session has stopped (the sink is closed): rows recorded, whether
  /// every row reached the storage, and event markers as text. Returns a line for the user.
  virtual QString finish(std::uint64_t rows, bool complete, const QString& events) = 0;

  /// What the live screen calls: begin() and finish() without waiting. done gets begin()'s
  /// error (empty: begun) or finish()'s line, later, on context's thread, and not at all when
  /// context is gone by then. By default they call begin() and finish() at once; a target whose
  /// storage lives on another thread (the GUI's records) runs them there.
  using Done = std::function<void(const QString&)>;
  virtual void beginAsync(const RecordingMeta& meta, const RecordingColumns& columns,
                          QObject* context, Done done) {
    (void)context;
    done(begin(meta, columns));
  }
  virtual void finishAsync(std::uint64_t rows, bool complete, const QString& events,
                           QObject* context, Done done) {
    (void)context;
    done(finish(rows, complete, events));
  }

 private:
  mutable std::mutex m_settingsMutex;
  storage::SessionSettings m_settings;
};

/// A recording file; never replaces one that exists (the user picks another name). open() makes
/// its folder when there is none yet.
class CsvRecordingTarget final : public RecordingTarget {
 public:
  explicit CsvRecordingTarget(std::filesystem::path csv) : m_csv(std::move(csv)) {}
  QString describe() const override;
  QString begin(const RecordingMeta& meta, const RecordingColumns& columns) override;
  std::unique_ptr<RecordingSink> open(const RecordingMeta& meta,
                                      const RecordingColumns& columns) override;
  QString finish(std::uint64_t rows, bool complete, const QString& events) override;

 private:
  std::filesystem::path m_csv;
};

/// A new session of a patient in the clinical records, as `armtrack-cli record --db` makes
/// one: begun on the store's thread (the caller's: with a store on the GUI thread, as in tests,
/// begin and finish are short calls there; the application's RecordsRecordingTarget makes
/// them on the records' own thread), its rows
/// committed by a DatabaseRecordingSink on the recorder thread, finished as complete or
/// interrupted, event markers saved in its notes.
class DatabaseRecordingTarget final : public RecordingTarget {
 public:
  /// store: signed in, on the GUI thread; url: its database (Database::url()), which the sink
  /// opens again on the recorder thread.
  DatabaseRecordingTarget(storage::ClinicalStore& store, storage::DatabaseUrl url,
                          QString patientCode, QString protocolName = {});
  QString describe() const override;
  QString begin(const RecordingMeta& meta, const RecordingColumns& columns) override;
  std::unique_ptr<RecordingSink> open(const RecordingMeta& meta,
                                      const RecordingColumns& columns) override;
  QString finish(std::uint64_t rows, bool complete, const QString& events) override;
  /// The session's id once begun (0 before).
  qint64 sessionId() const { return m_sessionId; }

 private:
  storage::ClinicalStore& m_store;
  storage::DatabaseUrl m_url;
  QString m_patient, m_protocol;
  qint64 m_sessionId = 0;
};

}  // namespace armtrack::app::gui
