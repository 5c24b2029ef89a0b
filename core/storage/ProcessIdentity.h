// Internal to core/storage: the process that writes or analyses a session (its host and process
// id, stored beside the session), and whether one recorded there has ended.
#pragma once

#include <unistd.h>

#include <QString>
#include <QSysInfo>
#include <cerrno>
#include <csignal>

namespace armtrack::storage::detail {

inline QString thisHost() {
  return QSysInfo::machineHostName();
}

inline qint64 thisProcess() {
  return static_cast<qint64>(::getpid());
}

/// Whether process pid of this host runs (one of another account counts: it exists).
inline bool processAlive(qint64 pid) {
  if (pid <= 0) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

/// Whether the process recorded as (host, pid) has ended for sure: it was of this host and runs
/// no more. A process of another host cannot be asked, so it is never taken for ended.
inline bool processEnded(const QString& host, qint64 pid) {
  return host == thisHost() && !processAlive(pid);
}

}  // namespace armtrack::storage::detail
