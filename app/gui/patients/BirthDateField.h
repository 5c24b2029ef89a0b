// The patient dialog's birth date: a line edit that takes the date however a person types or
// pastes it (ISO 2026-11-02, the language's numeric format such as 02.11.1947 or 11/2/1947,
// with a two- or four-digit year), empty for "not given", with a calendar button beside it.
// Nothing typed is changed behind the user's back: a text that is not a possible birth date is
// kept as typed and problem() says what is wrong with it.
#pragma once

#include <QDate>
#include <QLocale>
#include <QWidget>

class QCalendarWidget;
class QLineEdit;
class QToolButton;

namespace armtrack::gui {

class BirthDateField : public QWidget {
  Q_OBJECT
 public:
  explicit BirthDateField(QWidget* parent = nullptr);

  /// Shows date (an invalid date: empty, "not given").
  void setDate(const QDate& date);
  /// The date typed; invalid when empty or not a date (isEmpty() tells which).
  QDate date() const;
  bool isEmpty() const;
  /// The text as typed.
  QString text() const;
  /// What is wrong with the text, naming the field and the allowed range (empty: fine, or empty
  /// text). today: the latest birth date allowed.
  QString problem(const QDate& today) const;
  QLineEdit* lineEdit() const { return m_edit; }

  /// The date text means in locale: ISO (yyyy-m-d or yyyymmdd) or the locale's numeric format
  /// with a four- or two-digit year (a two-digit year is the latest one not after today).
  /// Invalid when it is none of them.
  static QDate parse(const QString& text, const QLocale& locale, const QDate& today);
  /// The earliest birth date allowed.
  static QDate earliest() { return QDate(1900, 1, 1); }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;
  void changeEvent(QEvent* event) override;

 private:
  void step(int days);
  void showCalendar();
  void normalise();
  void retranslateUi();

  QLineEdit* m_edit;
  QToolButton* m_calendarButton;
  QCalendarWidget* m_calendar = nullptr;
};

}  // namespace armtrack::gui
