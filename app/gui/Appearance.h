// How the application looks: a light or dark palette. (How it speaks: app/i18n/Language.h.)
#pragma once

#include <QString>

namespace armtrack::gui {

enum class Theme { System, Light, Dark };

/// "system", "light" or "dark" (anything else: System).
Theme parseTheme(const QString& name);
QString themeName(Theme theme);

/// Applies the Fusion style with a light or dark palette (System: the platform's palette).
/// Call after QApplication exists.
void applyTheme(Theme theme);

}  // namespace armtrack::gui
