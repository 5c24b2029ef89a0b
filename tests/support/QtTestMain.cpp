// main() for GoogleTest programs that need a Qt event loop (QSignalSpy::wait, queued signals,
// QSerialPort, QUdpSocket). Link it in place of gtest_main.
#include <gtest/gtest.h>

#include <QCoreApplication>

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
