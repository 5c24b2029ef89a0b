#include "app/gui/newsession/NewSessionSteps.h"

#include <QCheckBox>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace armtrack::gui {

WidgetStep::WidgetStep(TextFn title, TextFn subTitle, Make make, Check complete, Check leave,
                       TextFn skipText, QWidget* parent)
    : QWizardPage(parent),
      m_title(std::move(title)),
      m_subTitle(std::move(subTitle)),
      m_skipText(std::move(skipText)),
      m_make(std::move(make)),
      m_complete(std::move(complete)),
      m_leave(std::move(leave)),
      m_layout(new QVBoxLayout(this)) {
  if (m_skipText) {
    m_skip = new QCheckBox(this);
    m_layout->addWidget(m_skip);
    connect(m_skip, &QCheckBox::toggled, this, [this](bool skip) {
      if (m_page) m_page->setEnabled(!skip);
      emit completeChanged();
    });
  }
  retranslateUi();
}

void WidgetStep::retranslateUi() {
  setTitle(m_title ? m_title() : QString());
  setSubTitle(m_subTitle ? m_subTitle() : QString());
  if (m_skip) {
    m_skip->setText(m_skipText());
    m_skip->setAccessibleName(m_skip->text());
  }
}

void WidgetStep::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWizardPage::changeEvent(event);
}

void WidgetStep::initializePage() {
  // Built afresh from the choices of the steps before.
  delete m_page;
  m_page = m_make();
  m_page->setParent(this);
  m_layout->addWidget(m_page, 1);
  m_page->setEnabled(!skipped());
  if (m_page->metaObject()->indexOfSignal("completeChanged()") >= 0)
    connect(m_page, SIGNAL(completeChanged()), this, SIGNAL(completeChanged()));
  setFocusProxy(m_page);
  emit completeChanged();
}

void WidgetStep::cleanupPage() {
  delete m_page;  // Back: stops what the page runs (a device check, a protocol)
  m_page = nullptr;
}

bool WidgetStep::isComplete() const {
  return skipped() || (m_page && m_complete(m_page));
}

bool WidgetStep::validatePage() {
  return !m_leave || m_leave(skipped() ? nullptr : m_page);
}

bool WidgetStep::skipped() const {
  return m_skip && m_skip->isChecked();
}

void WidgetStep::setSkipped(bool skip) {
  if (m_skip) m_skip->setChecked(skip);
}

QStringList calibrationDevices(const QStringList& devices) {
  static const QRegularExpression trajectory(QStringLiteral(",?trajectory=[^,]*"));
  QStringList out;
  for (QString spec : devices) {
    if (spec.startsWith(QLatin1String("virtual-arm"))) {
      spec.remove(trajectory);
      spec += spec.contains(u':') ? QStringLiteral(",trajectory=calibration")
                                  : QStringLiteral(":trajectory=calibration");
      spec.replace(QLatin1String(":,"), QLatin1String(":"));
    }
    out << spec;
  }
  return out;
}

}  // namespace armtrack::gui
