// Precompiled for the GUI libraries (armtrack_ui and app/gui's targets; app/gui/CMakeLists.txt,
// ARMTRACK_GUI_PCH): the Qt Widgets, Eigen and standard headers most of their sources include,
// parsed once per build instead of once per source. Only headers that do not depend on the
// project's own macros belong here; every source still includes what it uses.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <QPushButton>
#include <QString>
#include <QStringList>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>
