#include "app/gui/HelpWindow.h"

#include <QAbstractTextDocumentLayout>
#include <QEvent>
#include <QFile>
#include <QLabel>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QUrl>
#include <QVBoxLayout>

#include "app/gui/common/Forms.h"
#include "app/i18n/Language.h"

namespace armtrack::gui {

ScreenHelp screenHelp(const QWidget* screen) {
  const QString name =
      screen ? QString::fromLatin1(screen->metaObject()->className()).section(u':', -1) : QString();
  // The headings are the English guide's and the German guide's (docs/user-guide.de.md).
  if (name == QLatin1String("FirstRunScreen"))
    return {HelpWindow::tr("Choose where the records are kept and name the administrator; then "
                           "press Create."),
            {QStringLiteral("The first start"), QStringLiteral("Der erste Start")}};
  if (name == QLatin1String("SignInScreen"))
    return {HelpWindow::tr("Type your account name and password, then press Sign in."),
            {QStringLiteral("Signing in"), QStringLiteral("Anmelden")}};
  if (name == QLatin1String("PatientListScreen"))
    return {HelpWindow::tr("Find a patient by name or code and open their page (Enter), or add "
                           "a new patient (Ctrl+N)."),
            {QStringLiteral("Patients"), QStringLiteral("Patienten")}};
  if (name == QLatin1String("PatientScreen"))
    return {HelpWindow::tr("See the patient's sessions and progress; start a new session "
                           "(Ctrl+R) or open a session to review it (Enter)."),
            {QStringLiteral("The patient's page"), QStringLiteral("Die Seite eines Patienten")}};
  if (name == QLatin1String("NewSessionScreen"))
    return {HelpWindow::tr("Go through the steps: protocol and arm, the device check, the "
                           "sensors' calibration and the camera; Finish starts the session."),
            {QStringLiteral("A session"), QStringLiteral("Eine Sitzung")}};
  if (name == QLatin1String("LiveSessionScreen"))
    return {HelpWindow::tr("Watch the arm and the angles; press Record (Ctrl+R) to keep the "
                           "movement and Stop (Ctrl+E) when the exercise is done."),
            {QStringLiteral("A session"), QStringLiteral("Eine Sitzung")}};
  if (name == QLatin1String("ReviewScreen"))
    return {HelpWindow::tr("Move through the session with the slider or by clicking a plot; "
                           "compare, re-estimate or write a report."),
            {QStringLiteral("Reviewing a session"), QStringLiteral("Eine Sitzung auswerten")}};
  return {HelpWindow::tr("The guide describes every screen; its contents are at the top."), {}};
}

QString HelpWindow::guideFor(const QString& language) {
  const QString translated = QStringLiteral(":/help/user-guide.%1.md").arg(language);
  if (language != QLatin1String("en") && QFile::exists(translated)) return translated;
  return QStringLiteral(":/help/user-guide.md");
}

HelpWindow::HelpWindow(QWidget* parent)
    : QWidget(parent, Qt::Window), m_hint(new QLabel(this)), m_browser(new QTextBrowser(this)) {
  auto* layout = new QVBoxLayout(this);
  m_hint->setWordWrap(true);
  m_hint->setTextFormat(Qt::PlainText);
  m_browser->setOpenExternalLinks(true);
  layout->addWidget(m_hint);
  layout->addWidget(m_browser, 1);
  resize(820, 640);
  retranslateUi();
}

void HelpWindow::retranslateUi() {
  setWindowTitle(tr("ArmTrack user guide"));
  m_browser->setAccessibleName(tr("User guide"));
  m_hint->setAccessibleName(tr("What to do here"));
}

QString HelpWindow::hintText() const {
  return m_hint->text();
}

void HelpWindow::showFor(const QString& hint, const QStringList& headings) {
  m_hintText = hint;
  m_headings = headings;
  load();
}

void HelpWindow::load() {
  const QString language = i18n::currentLanguage();
  const QString guide = guideFor(language);
  QString line = m_hintText;
  if (language != QLatin1String("en") && guide.endsWith(QLatin1String("user-guide.md")))
    line += QLatin1Char('\n') + tr("The guide is not yet translated into your language; it is "
                                   "shown in English.");
  m_hint->setText(line.trimmed());
  m_hint->setVisible(!m_hint->text().isEmpty());
  if (guide != m_loaded) {
    // The pictures' relative paths (images/...) resolve beside the guide in the resources.
    m_browser->setSource(QUrl(QStringLiteral("qrc") + guide), QTextDocument::MarkdownResource);
    m_loaded = guide;
  }
  // The section about the screen: the first heading that matches, at the top of the view.
  for (const QString& heading : m_headings)
    for (QTextBlock b = m_browser->document()->begin(); b.isValid(); b = b.next()) {
      if (b.blockFormat().headingLevel() == 0 || b.text().trimmed() != heading) continue;
      QTextCursor at(b);
      m_browser->setTextCursor(at);
      const QRectF r = m_browser->document()->documentLayout()->blockBoundingRect(b);
      m_browser->verticalScrollBar()->setValue(static_cast<int>(r.top()));
      return;
    }
  m_browser->verticalScrollBar()->setValue(0);
}

void HelpWindow::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) {
    retranslateUi();
    if (!m_loaded.isEmpty()) load();
  }
  QWidget::changeEvent(event);
}

}  // namespace armtrack::gui
