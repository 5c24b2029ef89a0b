// The devices' own words in the user's language. The device plugins have no translator of their
// own (they are loaded without Qt's translation machinery and speak English to logs and the
// command line), so the user interface translates what it knows at its boundary: the states a
// stream goes through, the shipped plugins' descriptions, and the session's event lines built
// from them ("virtual-arm#1: streaming"). Anything else is shown as it came.
#pragma once

#include <QString>

namespace armtrack::ui {

/// "streaming", "connecting", "disconnected", "error" in the user's language; other text as is.
QString deviceStateText(const QString& english);

/// A shipped plugin's description in the user's language; another plugin's as it came.
QString pluginDescriptionText(const QString& english);

/// A session event line "<device>: <state>[ (<reason>)]" with the state translated; any other
/// line as it came.
QString sessionEventText(const QString& line);

}  // namespace armtrack::ui
