// Precompiled for the QtTest programs with windows (armtrack_add_gui_test): Qt Core and Widgets,
// Eigen and the standard library. Not QtTest: its users define QT_TESTCASE_BUILDDIR, each test
// folder its own, and a precompiled header must be made with the same macros as its users. Not
// GoogleTest either (these programs do not use it).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QTableView>
#include <QTemporaryDir>
#include <QTimer>
#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>
