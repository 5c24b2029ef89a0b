// Helpers for widgets and models that set their words again when the language changes.
#pragma once

#include <QAbstractButton>
#include <QAbstractItemModel>
#include <QEvent>

namespace armtrack::ui {

// Table models whose header and cells are words: when the language changes (the model is a
// child of a widget, which passes the LanguageChange event on to it), their views must ask for
// the words again.

/// Emits headerDataChanged and dataChanged over the whole model, so its views fetch the header
/// and every cell again.
inline void refreshModelTexts(QAbstractItemModel* model) {
  const int rows = model->rowCount(), columns = model->columnCount();
  if (columns > 0) emit model->headerDataChanged(Qt::Horizontal, 0, columns - 1);
  if (rows > 0) emit model->headerDataChanged(Qt::Vertical, 0, rows - 1);
  if (rows > 0 && columns > 0)
    emit model->dataChanged(model->index(0, 0), model->index(rows - 1, columns - 1));
}

/// For a model's event(): refreshes its texts on a LanguageChange.
inline void refreshOnLanguageChange(QAbstractItemModel* model, const QEvent* event) {
  if (event->type() == QEvent::LanguageChange) refreshModelTexts(model);
}

/// Sets a button's text and keeps its shortcut (QAbstractButton::setText replaces the shortcut
/// with the text's mnemonic, so a Ctrl+R button would lose Ctrl+R at every change of text).
inline void setButtonText(QAbstractButton* button, const QString& text) {
  const QKeySequence shortcut = button->shortcut();
  button->setText(text);
  if (!shortcut.isEmpty()) button->setShortcut(shortcut);
}

}  // namespace armtrack::ui
