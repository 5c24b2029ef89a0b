#include "app/cli/ClinicalContext.h"

#include <termios.h>
#include <unistd.h>

#include <charconv>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace armtrack::cli {

namespace {
thread_local std::ostream* t_notices = nullptr;
}  // namespace

std::ostream& noticeStream() {
  return t_notices ? *t_notices : std::cerr;
}

ScopedNoticeStream::ScopedNoticeStream(std::ostream& err) : m_previous(t_notices) {
  t_notices = &err;
}

ScopedNoticeStream::~ScopedNoticeStream() {
  t_notices = m_previous;
}

ClinicalContext::ClinicalContext(const Args& a, storage::Database::Options options, bool signIn,
                                 bool runPending) {
  if (!QCoreApplication::instance()) {
    static int argc = 1;
    static char name[] = "armtrack-cli";
    static char* argv[] = {name, nullptr};
    m_app = std::make_unique<QCoreApplication>(argc, argv);
  }
  // The default database lives in ~/.local/share/ArmTrack/ArmTrack/armtrack.db on Linux.
  QCoreApplication::setOrganizationName("ArmTrack");
  QCoreApplication::setApplicationName("ArmTrack");
  std::string user;
  if (signIn) user = a.required("--user");  // a usage error before any file is touched
  m_url = a.value("--db") ? storage::DatabaseUrl::parse(qs(*a.value("--db")))
                          : storage::DatabaseUrl::defaultLocation();
  m_db = std::make_unique<storage::Database>(m_url, options);
  m_store = std::make_unique<storage::ClinicalStore>(*m_db);
  if (const int kept = m_store->staleRecordingsKept(); kept > 0)
    noticeStream()
        << "armtrack-cli: note: database '" << ss(m_url.display()) << "' is read-only ("
        << ss(m_db->readOnlyReason()) << "): " << kept
        << " session(s) left in 'recording' by a process that has ended stay so until it "
           "is opened with write access, which marks them interrupted\n";
  if (signIn) {
    m_password = passwordFromUser("account '" + user + "'");
    m_store->signIn(qs(user), m_password);
    m_user = user;
    // Nothing can be stored in a read-only database: its pending analyses wait for write access.
    if (runPending && !m_db->isReadOnly()) analysePendingSessions(*m_store, noticeStream());
  }
}

ClinicalContext::Connection ClinicalContext::connectAgain() const {
  Connection c;
  c.db = std::make_unique<storage::Database>(m_url, storage::Database::Options{});
  c.store = std::make_unique<storage::ClinicalStore>(*c.db);
  if (!m_user.empty()) c.store->signIn(qs(m_user), m_password);
  return c;
}

qint64 sessionIdArgument(const Args& a) {
  return sessionIdFrom(a, a.single("session id"));
}

qint64 sessionIdFrom(const Args& a, const std::string& text) {
  qint64 id = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), id);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || id <= 0)
    a.fail("session id: expected a positive whole number, got \"" + text + "\"");
  return id;
}

std::string passwordFromUser(const std::string& what) {
  if (const char* env = std::getenv("ARMTRACK_PASSWORD")) return env;
  if (!::isatty(STDIN_FILENO))
    throw std::runtime_error("no password for " + what +
                             ": set ARMTRACK_PASSWORD or run on a terminal to be asked");
  std::cerr << "password for " << what << ": " << std::flush;
  termios old{};
  const bool hide = ::tcgetattr(STDIN_FILENO, &old) == 0;
  if (hide) {
    termios quiet = old;
    quiet.c_lflag &= ~static_cast<tcflag_t>(ECHO);
    ::tcsetattr(STDIN_FILENO, TCSANOW, &quiet);
  }
  std::string password;
  std::getline(std::cin, password);
  if (hide) ::tcsetattr(STDIN_FILENO, TCSANOW, &old);
  std::cerr << "\n";
  return password;
}

}  // namespace armtrack::cli
