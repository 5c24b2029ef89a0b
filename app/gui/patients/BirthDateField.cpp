#include "app/gui/patients/BirthDateField.h"

#include <QCalendarWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLineEdit>
#include <QRegularExpression>
#include <QScreen>
#include <QToolButton>

#include "core/reports/ReportText.h"

namespace armtrack::gui {

namespace {

/// The order of day, month and year in the locale's numeric date format ("dd.MM.yy": d, M, y).
QString fieldOrder(const QLocale& locale) {
  QString order;
  for (const QChar c : locale.dateFormat(QLocale::ShortFormat))
    if ((c == u'd' || c == u'M' || c == u'y') && !order.contains(c)) order += c;
  return order.size() == 3 ? order : QStringLiteral("dMy");
}

QString shown(const QDate& date) {
  const QLocale locale;
  return locale.toString(date, reports::fullYearDateFormat(locale));
}

}  // namespace

BirthDateField::BirthDateField(QWidget* parent)
    : QWidget(parent), m_edit(new QLineEdit(this)), m_calendarButton(new QToolButton(this)) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(m_edit, 1);
  layout->addWidget(m_calendarButton);
  m_edit->setClearButtonEnabled(true);
  m_edit->installEventFilter(this);
  m_calendarButton->setText(QStringLiteral("..."));
  m_calendarButton->setFocusPolicy(Qt::ClickFocus);  // Alt+Down opens it from the keyboard
  setFocusProxy(m_edit);
  setFocusPolicy(m_edit->focusPolicy());
  connect(m_edit, &QLineEdit::editingFinished, this, &BirthDateField::normalise);
  connect(m_calendarButton, &QToolButton::clicked, this, &BirthDateField::showCalendar);
  retranslateUi();
}

void BirthDateField::retranslateUi() {
  const QLocale locale;
  const QDate example(1947, 11, 2);
  m_edit->setPlaceholderText(tr("not given"));
  m_edit->setAccessibleName(tr("Birth date"));
  m_edit->setToolTip(tr("Type the date as %1 or %2; leave it empty when not given. Up and Down "
                        "change it by a day, Alt+Down opens a calendar.")
                         .arg(example.toString(Qt::ISODate), shown(example)));
  m_calendarButton->setAccessibleName(tr("Choose the birth date from a calendar"));
  m_calendarButton->setToolTip(m_calendarButton->accessibleName() + QStringLiteral(" (Alt+Down)"));
}

void BirthDateField::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

void BirthDateField::setDate(const QDate& date) {
  m_edit->setText(date.isValid() ? shown(date) : QString());
}

QString BirthDateField::text() const {
  return m_edit->text();
}

bool BirthDateField::isEmpty() const {
  return m_edit->text().trimmed().isEmpty();
}

QDate BirthDateField::date() const {
  return parse(m_edit->text(), QLocale(), QDate::currentDate());
}

QDate BirthDateField::parse(const QString& raw, const QLocale& locale, const QDate& today) {
  const QString text = raw.trimmed();
  static const QRegularExpression compact(QStringLiteral("^(\\d{4})(\\d{2})(\\d{2})$"));
  if (const auto m = compact.match(text); m.hasMatch())
    return QDate(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3).toInt());
  // Three groups of digits between separators; anything else is not a date.
  static const QRegularExpression parts(
      QStringLiteral("^(\\d{1,4})\\s*[./\\-]\\s*(\\d{1,4})\\s*[./\\-]\\s*(\\d{1,4})\\.?$"));
  const auto m = parts.match(text);
  if (!m.hasMatch()) return {};
  const QString a = m.captured(1), b = m.captured(2), c = m.captured(3);
  QString day, month, year;
  if (a.size() == 4) {  // ISO order whatever the language: year, month, day
    year = a, month = b, day = c;
  } else {
    const QString order = fieldOrder(locale);
    const QString values[] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      if (order[i] == u'd') day = values[i];
      if (order[i] == u'M') month = values[i];
      if (order[i] == u'y') year = values[i];
    }
  }
  if (day.size() > 2 || month.size() > 2 || (year.size() != 4 && year.size() != 2)) return {};
  const int d = day.toInt(), mo = month.toInt();
  if (year.size() == 4) return QDate(year.toInt(), mo, d);
  // A two-digit year: the latest century that does not put the date after today.
  const QDate recent(2000 + year.toInt(), mo, d);
  if (!recent.isValid()) return {};
  return recent > today ? recent.addYears(-100) : recent;
}

QString BirthDateField::problem(const QDate& today) const {
  if (isEmpty()) return {};
  const QDate d = parse(m_edit->text(), QLocale(), today);
  const QString range =
      tr("a birth date from %1 up to today, %2").arg(shown(earliest()), shown(today));
  if (!d.isValid())
    return tr("Born: \"%1\" is not a date. Type %2 as %3 or %4, or leave the field empty when "
              "the birth date is not given.")
        .arg(m_edit->text().trimmed(), range, QDate(1947, 11, 2).toString(Qt::ISODate),
             shown(QDate(1947, 11, 2)));
  if (d < earliest() || d > today)
    return tr("Born: %1 is not possible. Type %2.").arg(shown(d), range);
  return {};
}

void BirthDateField::normalise() {
  // Shows how a possible date was read; anything else stays as typed for problem() to name.
  const QDate d = date();
  if (d.isValid() && problem(QDate::currentDate()).isEmpty()) m_edit->setText(shown(d));
}

void BirthDateField::step(int days) {
  const QDate d = date();
  if (!d.isValid()) return;
  m_edit->setText(shown(d.addDays(days)));
}

bool BirthDateField::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() == QEvent::KeyPress) {
    auto* key = static_cast<QKeyEvent*>(event);
    if (watched == m_edit) {
      if ((key->key() == Qt::Key_Down && (key->modifiers() & Qt::AltModifier)) ||
          key->key() == Qt::Key_F4) {
        showCalendar();
        return true;
      }
      if (key->key() == Qt::Key_Up || key->key() == Qt::Key_Down) {
        step(key->key() == Qt::Key_Up ? 1 : -1);
        return true;
      }
    } else if (watched == m_calendar && key->key() == Qt::Key_Escape) {
      m_calendar->hide();
      m_edit->setFocus();
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

void BirthDateField::showCalendar() {
  if (!m_calendar) {
    m_calendar = new QCalendarWidget(this);
    m_calendar->setWindowFlags(Qt::Popup);
    m_calendar->setAccessibleName(tr("Calendar"));
    m_calendar->installEventFilter(this);
    const auto pick = [this](const QDate& d) {
      setDate(d);
      m_calendar->hide();
      m_edit->setFocus();
      m_edit->selectAll();
    };
    connect(m_calendar, &QCalendarWidget::activated, this, pick);
    connect(m_calendar, &QCalendarWidget::clicked, this, pick);
  }
  const QDate today = QDate::currentDate();
  m_calendar->setDateRange(earliest(), today);
  const QDate d = date();
  m_calendar->setSelectedDate(d.isValid() ? d : QDate(today.year() - 60, 1, 1));
  QPoint at = mapToGlobal(QPoint(0, height()));
  const QSize size = m_calendar->sizeHint();
  if (const QScreen* s = screen()) {
    const QRect area = s->availableGeometry();
    at.setX(std::clamp(at.x(), area.left(), std::max(area.left(), area.right() - size.width())));
    if (at.y() + size.height() > area.bottom())
      at.setY(mapToGlobal(QPoint(0, 0)).y() - size.height());
  }
  m_calendar->move(at);
  m_calendar->show();
  m_calendar->setFocus();
}

}  // namespace armtrack::gui
