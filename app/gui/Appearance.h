// How the application looks and speaks: light or dark palette, and the translators.
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

/// Installs Qt's own and ArmTrack's translators for language (e.g. "de"; empty: the system's
/// locale), replacing earlier ones. Returns false when ArmTrack has no translation for it (the
/// text stays English).
bool installTranslators(const QString& language);

}  // namespace armtrack::gui
