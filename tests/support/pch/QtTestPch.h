// Precompiled for the GoogleTest programs that run a Qt event loop (armtrack_add_test QT,
// POSTGRES or PLUGINS): TestPch.h and the Qt Core headers they share.
#pragma once

#include "TestPch.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>
