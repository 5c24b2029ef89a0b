// ProblemLimiter: a flood of problems becomes one message per window, nothing is lost from the
// count, and a quiet spell lets the next problem through at once.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QObject>
#include <QStringList>
#include <memory>

#include "devices/api/ProblemLimiter.h"

using armtrack::devices::ProblemLimiter;

namespace {

// Runs the event loop until `done` holds or two seconds pass (a generous bound, not a timing
// check: the windows below are 30 ms).
template <typename Pred>
bool spinUntil(Pred done) {
  const QDeadlineTimer deadline(2000);
  while (!done() && !deadline.hasExpired())
    QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
  return done();
}

void spinFor(int ms) {
  const QDeadlineTimer deadline(ms);
  while (!deadline.hasExpired()) QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
}

}  // namespace

TEST(ProblemLimiter, FloodBecomesOneMessagePerWindowAndCountsEverything) {
  QObject owner;
  QStringList reports;
  ProblemLimiter limiter(
      &owner, [&](const QString& m) { reports << m; }, 30);

  limiter.note(1, QStringLiteral("bad checksum #1"));
  ASSERT_EQ(reports.size(), 1);  // the first problem of a quiet window goes out at once
  EXPECT_EQ(reports[0], QStringLiteral("bad checksum #1"));

  for (int i = 2; i <= 50; ++i) limiter.note(1, QStringLiteral("bad checksum #%1").arg(i));
  limiter.note(3, QStringLiteral("short packet"));
  EXPECT_EQ(reports.size(), 1);  // held while the window is open
  EXPECT_EQ(limiter.held(), 52u);

  ASSERT_TRUE(spinUntil([&] { return reports.size() == 2; }));
  EXPECT_EQ(reports[1],
            QStringLiteral("52 more problems in the last 30 ms; the latest: short packet"));
  EXPECT_EQ(limiter.held(), 0u);

  // The summary opened another window: a problem now is held, not shown at once.
  limiter.note(1, QStringLiteral("late one"));
  EXPECT_EQ(reports.size(), 2);
  ASSERT_TRUE(spinUntil([&] { return reports.size() == 3; }));
  EXPECT_EQ(reports[2], QStringLiteral("1 more problem in the last 30 ms; the latest: late one"));

  // A window that closes with nothing held ends the flood; the next problem goes out at once,
  // with the size of its batch.
  spinFor(100);
  EXPECT_EQ(reports.size(), 3);
  limiter.note(4, QStringLiteral("garbage"));
  ASSERT_EQ(reports.size(), 4);
  EXPECT_EQ(reports[3], QStringLiteral("garbage (and 3 more problems)"));
}

TEST(ProblemLimiter, FlushReportsWhatIsHeldAndEndsTheWindow) {
  QObject owner;
  QStringList reports;
  ProblemLimiter limiter(&owner, [&](const QString& m) { reports << m; });  // 1 s window
  EXPECT_EQ(reports.size(), 0);
  limiter.note(0, QStringLiteral("nothing"));
  EXPECT_EQ(reports.size(), 0);
  limiter.note(1, QStringLiteral("first"));
  limiter.note(2, QStringLiteral("second"));
  ASSERT_EQ(reports.size(), 1);
  limiter.flush();  // the device stops: nothing held may be lost
  ASSERT_EQ(reports.size(), 2);
  EXPECT_EQ(reports[1], QStringLiteral("2 more problems in the last second; the latest: second"));
  limiter.flush();
  EXPECT_EQ(reports.size(), 2);
  limiter.note(1, QStringLiteral("after stop"));  // the window was ended: shown at once
  ASSERT_EQ(reports.size(), 3);
  EXPECT_EQ(reports[2], QStringLiteral("after stop"));
}

TEST(ProblemLimiter, OwnerMayGoFirstOrLast) {
  {
    auto owner = std::make_unique<QObject>();
    QStringList reports;
    ProblemLimiter limiter(
        owner.get(), [&](const QString& m) { reports << m; }, 30);
    limiter.note(1, QStringLiteral("a"));
    limiter.note(1, QStringLiteral("b"));
    owner.reset();  // deletes the timer; without it every problem goes straight out
    limiter.note(1, QStringLiteral("c"));
    limiter.flush();
    EXPECT_EQ(reports,
              (QStringList{QStringLiteral("a"), QStringLiteral("c"),
                           QStringLiteral("1 more problem in the last 30 ms; the latest: b")}));
  }
  {
    QObject owner;
    auto limiter = std::make_unique<ProblemLimiter>(
        &owner, [](const QString&) {}, 30);
    limiter->note(1, QStringLiteral("x"));
    limiter.reset();  // its timer goes with it and cannot fire into a dead limiter
    EXPECT_TRUE(owner.children().isEmpty());
    spinFor(60);
  }
}
