// The home window's look: large text (scaled from the user's own font, so it follows the
// system's size and the screen's DPI), high contrast, big buttons with a thick focus ring, and a
// banner for feedback and problems.
#pragma once

#include <QColor>
#include <QFont>
#include <QString>

class QLabel;
class QPushButton;
class QWidget;

namespace armtrack::gui::home {

/// How a banner reads: good news, a hint to do better, a problem.
enum class Tone { Neutral, Good, Hint, Problem };

/// The home window's font: 1.5 times the user's, times scale (bold unless said otherwise).
QFont homeFont(double scale = 1.0, bool bold = false);
/// Gives w and the widgets under it that have no font of their own the home font times scale.
void setHomeFont(QWidget* w, double scale = 1.0, bool bold = false);
/// Applies the palette, the font (1.5 times the user's) and the style sheet to the window.
void applyHomeStyle(QWidget* window);
/// A large button; primary ones stand out (the one that goes on).
QPushButton* bigButton(const QString& text, QWidget* parent, bool primary = false);
/// A heading label (1.6 times the window's font, bold) or body text (word-wrapped).
QLabel* heading(const QString& text, QWidget* parent);
QLabel* bodyText(const QString& text, QWidget* parent);
/// Shows text on label in the tone's colours (empty text hides it). The tone is also said in
/// the accessible description, so it does not rest on colour alone.
void setBanner(QLabel* label, const QString& text, Tone tone);
/// The background of a tone (high contrast with black text).
QColor toneColour(Tone tone);

}  // namespace armtrack::gui::home
