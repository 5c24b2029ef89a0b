// armtrack_test_pg_server start|stop STATE_FILE: the PostgreSQL server CTest shares between the
// tests that need one (the fixture in tests/CMakeLists.txt). `start` never fails the fixture: a
// server that cannot start leaves its reason in the state file, and only the tests that use
// PostgreSQL fail, with that reason.
#include <QCoreApplication>
#include <cstdio>
#include <exception>

#include "tests/support/PostgresServer.h"

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);  // Qt Sql needs one
  const QStringList args = app.arguments();
  if (args.size() != 3 || (args[1] != "start" && args[1] != "stop")) {
    std::fprintf(stderr, "usage: armtrack_test_pg_server start|stop STATE_FILE\n");
    return 2;
  }
  try {
    if (args[1] == "stop") {
      armtrack::test::PostgresServer::stopDetached(args[2]);
      return 0;
    }
    if (armtrack::test::PostgresServer::startDetached(args[2]))
      std::printf("shared PostgreSQL test server started (%s)\n", qPrintable(args[2]));
    else
      std::printf("the shared PostgreSQL test server did not start; see %s\n", qPrintable(args[2]));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armtrack_test_pg_server: %s\n", e.what());
    return args[1] == "start" ? 0 : 1;
  }
}
