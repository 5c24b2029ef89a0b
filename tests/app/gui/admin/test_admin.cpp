// The administrator's screens through the real window, keyboard and mouse as a person uses them,
// on a fresh clinic (one administrator, one patient): a therapist and a home account added (a
// short password, differing passwords and a taken name refused in words, nothing typed lost), a
// password reset, an account removed after a confirmation, one disabled and enabled again; a
// protocol added and edited; an exercise put in the patient's home programme. What the screens
// stored is read back with the store itself, the audit log included; then the new therapist signs
// in and the new protocol is offered in a new session. Therapists do not see the administration.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QWizard>

#include "app/gui/AppController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/admin/AdminDialogs.h"
#include "app/gui/admin/AdminScreen.h"
#include "app/gui/common/Forms.h"
#include "app/gui/newsession/NewSessionScreen.h"
#include "app/gui/patients/PatientListScreen.h"
#include "app/gui/patients/PatientScreen.h"
#include "app/gui/signin/SignInScreen.h"
#include "core/storage/Database.h"
#include "core/storage/StorageError.h"
#include "tests/app/gui/support/GuiTestSupport.h"

using namespace armtrack;
using namespace armtrack::gui;
using armtrack::gui::test::findControl;
using armtrack::gui::test::typeInto;

namespace {
const QString kAdmin = QStringLiteral("boss");
const QString kAdminPassword = QStringLiteral("boss-password-1");
const QString kTherapist = QStringLiteral("Tess Therapist");
const QString kTherapistPassword = QStringLiteral("tess-password-1");
}  // namespace

class TestAdmin : public QObject {
  Q_OBJECT

  QTemporaryDir m_dir;
  storage::DatabaseUrl m_url;
  std::unique_ptr<AppController> m_app;

  QWidget* screen() const { return m_app->window()->currentScreen(); }
  admin::AdminScreen* adminScreen() const { return qobject_cast<admin::AdminScreen*>(screen()); }

  static QStringList column(QTableWidget* table, int c) {
    QStringList out;
    for (int r = 0; r < table->rowCount(); ++r)
      out << (table->item(r, c) ? table->item(r, c)->text() : QString());
    return out;
  }
  static bool selectRow(QTableWidget* table, const QString& first) {
    for (int r = 0; r < table->rowCount(); ++r)
      if (table->item(r, 0) && table->item(r, 0)->text() == first) {
        table->setFocus();
        table->selectRow(r);
        return true;
      }
    return false;
  }
  /// The dialog of type T the page opened, active.
  template <class T>
  T* dialog() {
    T* d = nullptr;
    if (!QTest::qWaitFor([&] { return (d = screen()->findChild<T*>()) && d->isVisible(); }))
      return nullptr;
    gui::test::activate(d);
    return d;
  }
  static void save(QDialog* d) {
    QTest::mouseClick(findControl<QPushButton>(d, "Save"), Qt::LeftButton);
  }
  /// Reads the records as the administrator, apart from the application.
  template <class Fn>
  auto asAdmin(Fn fn) {
    storage::Database db(m_url, {});
    storage::ClinicalStore store(db);
    store.signIn(kAdmin, kAdminPassword.toStdString());
    return fn(store);
  }
  void signIn(const QString& name, const QString& password) {
    QTRY_VERIFY(qobject_cast<SignInScreen*>(screen()));
    auto* s = screen();
    typeInto(findControl<QLineEdit>(s, QStringLiteral("Account name")), name);
    typeInto(findControl<QLineEdit>(s, QStringLiteral("Password")), password);
    QTest::keyClick(findControl<QLineEdit>(s, QStringLiteral("Password")), Qt::Key_Return);
    QTRY_VERIFY_WITH_TIMEOUT(qobject_cast<PatientListScreen*>(screen()), 20000);
  }
  QAction* adminAction() const {
    for (QAction* a : m_app->window()->menuBar()->actions().first()->menu()->actions())
      if (a->text().remove(u'&') == QStringLiteral("Administration...")) return a;
    return nullptr;
  }

 private slots:
  void initTestCase() {
    m_url.path = m_dir.filePath(QStringLiteral("clinic.db"));
    {
      storage::Database db(m_url, {.create = true, .migrate = false});
      storage::ClinicalStore store(db);
      store.initialise(kAdmin, kAdminPassword.toStdString());
      store.signIn(kAdmin, kAdminPassword.toStdString());
      storage::Patient p;
      p.code = QStringLiteral("P001");
      p.name = QStringLiteral("Ada Example");
      store.addPatient(p);
    }
    AppOptions options;
    options.database = m_url.path;
    m_app = std::make_unique<AppController>(options);
    m_app->start();
    QVERIFY(gui::test::activate(m_app->window()));
    signIn(kAdmin, kAdminPassword);
  }

  void theAdministratorOpensTheScreenFromTheMenu() {
    QAction* action = adminAction();
    QVERIFY(action && action->isVisible() && action->isEnabled());
    QVERIFY(gui::test::activate(m_app->window()));
    QTest::keySequence(m_app->window(), action->shortcut());
    QTRY_VERIFY(adminScreen());
    QCOMPARE(adminScreen()->tabs()->currentWidget(), adminScreen()->accounts());
    QTRY_COMPARE(column(adminScreen()->accounts()->table(), 0), QStringList{kAdmin});
  }

  void addATherapistRefusingWhatTheRulesRefuse() {
    auto* page = adminScreen()->accounts();
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Add account...")),
                      Qt::LeftButton);
    auto* d = dialog<admin::AccountDialog>();
    QVERIFY(d);
    auto* name = findControl<QLineEdit>(d, QStringLiteral("Account name"));
    auto* role = findControl<QComboBox>(d, QStringLiteral("Role"));
    auto* password = findControl<QLineEdit>(d, QStringLiteral("Password"));
    auto* again = findControl<QLineEdit>(d, QStringLiteral("Password again"));
    QVERIFY(name && role && password && again);
    QCOMPARE(d->focusWidget(), name);
    QCOMPARE(role->currentText(), QStringLiteral("therapist"));
    typeInto(name, kTherapist);
    typeInto(password, QStringLiteral("short"));
    typeInto(again, QStringLiteral("short"));
    QTest::keyClick(again, Qt::Key_Return);
    QVERIFY2(armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("at least 10")),
             qPrintable(armtrack::gui::test::visibleMessage(d)));
    QCOMPARE(d->focusWidget(), password);
    typeInto(password, kTherapistPassword);
    typeInto(again, QStringLiteral("tess-password-2"));
    QTest::keyClick(again, Qt::Key_Return);
    QVERIFY2(armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("differ")),
             qPrintable(armtrack::gui::test::visibleMessage(d)));
    // The administrator's own name in other letters is taken: the records say so, the dialog
    // stays with everything typed.
    typeInto(name, QStringLiteral("BOSS"));
    typeInto(again, kTherapistPassword);
    save(d);
    QTRY_VERIFY(!armtrack::gui::test::visibleMessage(d).startsWith(QStringLiteral("Saving")));
    QVERIFY2(armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("BOSS")) ||
                 armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("boss")),
             qPrintable(armtrack::gui::test::visibleMessage(d)));
    QVERIFY(d->isVisible());
    QCOMPARE(password->text(), kTherapistPassword);
    typeInto(name, kTherapist);
    save(d);
    QTRY_VERIFY(!screen()->findChild<admin::AccountDialog*>());
    QTRY_VERIFY(column(page->table(), 0).contains(kTherapist));
    QVERIFY2(armtrack::gui::test::visibleMessage(page).contains(kTherapist),
             qPrintable(armtrack::gui::test::visibleMessage(page)));
  }

  void addAHomeAccountForThePatient() {
    auto* page = adminScreen()->accounts();
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Add account...")),
                      Qt::LeftButton);
    auto* d = dialog<admin::AccountDialog>();
    QVERIFY(d);
    auto* role = findControl<QComboBox>(d, QStringLiteral("Role"));
    auto* patient = findControl<QComboBox>(d, QStringLiteral("Patient of the home account"));
    QVERIFY(!patient->isEnabled());  // only a home account has a patient
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Account name")), QStringLiteral("ada-home"));
    role->setFocus();
    role->setCurrentIndex(role->findText(QStringLiteral("home account")));
    QVERIFY(patient->isEnabled());
    QCOMPARE(patient->currentData().toString(), QStringLiteral("P001"));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Password")),
             QStringLiteral("ada-home-pass-1"));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Password again")),
             QStringLiteral("ada-home-pass-1"));
    save(d);
    QTRY_VERIFY(!screen()->findChild<admin::AccountDialog*>());
    QTRY_VERIFY(column(page->table(), 0).contains(QStringLiteral("ada-home")));
    const int row = static_cast<int>(column(page->table(), 0).indexOf(QStringLiteral("ada-home")));
    QCOMPARE(page->table()->item(row, 2)->text(), QStringLiteral("P001 - Ada Example"));
  }

  void resetAPasswordThenRemoveTheAccount() {
    auto* page = adminScreen()->accounts();
    QVERIFY(selectRow(page->table(), QStringLiteral("ada-home")));
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Reset password...")),
                      Qt::LeftButton);
    auto* d = dialog<admin::PasswordDialog>();
    QVERIFY(d);
    typeInto(findControl<QLineEdit>(d, QStringLiteral("New password")),
             QStringLiteral("new-home-pass-9"));
    typeInto(findControl<QLineEdit>(d, QStringLiteral("New password again")),
             QStringLiteral("new-home-pass-9"));
    save(d);
    QTRY_VERIFY(!screen()->findChild<admin::PasswordDialog*>());
    QVERIFY(asAdmin([](storage::ClinicalStore&) { return true; }));
    {
      storage::Database db(m_url, {});
      storage::ClinicalStore store(db);
      QCOMPARE(store.signIn(QStringLiteral("ada-home"), "new-home-pass-9").role,
               storage::Role::Home);
    }
    // Removal asks first; Cancel keeps the account.
    QVERIFY(selectRow(page->table(), QStringLiteral("ada-home")));
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Remove account...")),
                      Qt::LeftButton);
    QMessageBox* box = nullptr;
    QTRY_VERIFY((box = page->findChild<QMessageBox*>()) && box->isVisible());
    QVERIFY(box->text().contains(QStringLiteral("ada-home")));
    box->button(QMessageBox::Cancel)->click();
    QTest::qWait(200);
    QVERIFY(column(page->table(), 0).contains(QStringLiteral("ada-home")));
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Remove account...")),
                      Qt::LeftButton);
    QTRY_VERIFY((box = page->findChild<QMessageBox*>()) && box->isVisible());
    box->button(QMessageBox::Yes)->click();
    QTRY_VERIFY(!column(page->table(), 0).contains(QStringLiteral("ada-home")));
    // The administrator cannot remove itself: said in words.
    QVERIFY(selectRow(page->table(), kAdmin));
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Remove account...")),
                      Qt::LeftButton);
    QTRY_VERIFY((box = page->findChild<QMessageBox*>()) && box->isVisible());
    box->button(QMessageBox::Yes)->click();
    QTRY_VERIFY(
        armtrack::gui::test::visibleMessage(page).contains(QStringLiteral("cannot remove itself")));
  }

  // Issue 25, item 12: accounts could not be disabled. Disabling asks first, the table says
  // so, the account cannot sign in (in words), and enabling lets it in again.
  void disableThenEnableTheTherapist() {
    auto* page = adminScreen()->accounts();
    const auto status = [&] {
      const int row = static_cast<int>(column(page->table(), 0).indexOf(kTherapist));
      return row < 0 ? QString() : page->table()->item(row, 3)->text();
    };
    const auto signInError = [&]() -> QString {
      storage::Database db(m_url, {});
      storage::ClinicalStore store(db);
      try {
        store.signIn(kTherapist, kTherapistPassword.toStdString());
        return {};
      } catch (const storage::StorageError& e) {
        return QString::fromStdString(e.what());
      }
    };
    QTRY_COMPARE(status(), QStringLiteral("Active"));
    QVERIFY(selectRow(page->table(), kTherapist));
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Disable account...")),
                      Qt::LeftButton);
    QMessageBox* box = nullptr;
    QTRY_VERIFY((box = page->findChild<QMessageBox*>()) && box->isVisible());
    QVERIFY(box->text().contains(kTherapist));
    box->button(QMessageBox::Yes)->click();
    QTRY_COMPARE(status(), QStringLiteral("Disabled"));
    QVERIFY2(signInError().contains(QStringLiteral("is disabled")), qPrintable(signInError()));
    QVERIFY(selectRow(page->table(), kTherapist));
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Enable account")),
                      Qt::LeftButton);
    QTRY_COMPARE(status(), QStringLiteral("Active"));
    QVERIFY2(signInError().isEmpty(), qPrintable(signInError()));
  }

  void aFreshClinicsNewSessionSaysWhereProtocolsComeFrom() {
    m_app->startNewSession(QStringLiteral("P001"));
    QTRY_VERIFY(qobject_cast<NewSessionScreen*>(screen()));
    QTRY_VERIFY(qobject_cast<NewSessionScreen*>(screen())->setupPage()->isComplete());
    QCOMPARE(findControl<QComboBox>(screen(), QStringLiteral("Protocol"))->count(), 1);
    const auto labels = screen()->findChildren<QLabel*>();
    QVERIFY(std::any_of(labels.begin(), labels.end(), [](QLabel* l) {
      return l->isVisible() && l->text().contains(QStringLiteral("Administration > Protocols"));
    }));
    qobject_cast<NewSessionScreen*>(screen())->wizard()->reject();
    QTRY_VERIFY(qobject_cast<PatientScreen*>(screen()));
    m_app->showAdmin();
    QTRY_VERIFY(adminScreen());
  }

  void addAndEditAProtocol() {
    adminScreen()->tabs()->setCurrentWidget(adminScreen()->protocols());
    auto* page = adminScreen()->protocols();
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Add protocol...")),
                      Qt::LeftButton);
    auto* d = dialog<admin::ProtocolDialog>();
    QVERIFY(d);
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Protocol name")),
             QStringLiteral("Reach forward"));
    auto* angle = findControl<QComboBox>(d, QStringLiteral("Angle"));
    angle->setCurrentIndex(angle->findData(QStringLiteral("elbow_flexion")));
    auto* from = findControl<QDoubleSpinBox>(d, QStringLiteral("Target from"));
    auto* to = findControl<QDoubleSpinBox>(d, QStringLiteral("Target to"));
    from->setValue(130);
    to->setValue(20);  // backwards
    save(d);
    QVERIFY2(
        armtrack::gui::test::visibleMessage(d).contains(QStringLiteral("below where it starts")),
        qPrintable(armtrack::gui::test::visibleMessage(d)));
    from->setValue(20);
    to->setValue(120);
    findControl<QSpinBox>(d, QStringLiteral("Repetitions"))->setValue(8);
    save(d);
    QTRY_VERIFY(!screen()->findChild<admin::ProtocolDialog*>());
    QTRY_VERIFY(column(page->table(), 0).contains(QStringLiteral("Reach forward")));
    // Edited: the name stays, the repetitions change.
    QVERIFY(selectRow(page->table(), QStringLiteral("Reach forward")));
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Edit protocol...")),
                      Qt::LeftButton);
    d = dialog<admin::ProtocolDialog>();
    QVERIFY(d);
    QVERIFY(findControl<QLineEdit>(d, QStringLiteral("Protocol name"))->isReadOnly());
    findControl<QSpinBox>(d, QStringLiteral("Repetitions"))->setValue(12);
    save(d);
    QTRY_VERIFY(!screen()->findChild<admin::ProtocolDialog*>());
    const storage::Protocol stored = asAdmin(
        [](storage::ClinicalStore& s) { return s.protocol(QStringLiteral("Reach forward")); });
    QCOMPARE(stored.angleKey, QStringLiteral("elbow_flexion"));
    QCOMPARE(stored.targetMinDeg, 20.0);
    QCOMPARE(stored.targetMaxDeg, 120.0);
    QCOMPARE(stored.repetitions, 12);
  }

  void putAnExerciseInTheHomeProgramme() {
    adminScreen()->tabs()->setCurrentWidget(adminScreen()->programmes());
    auto* page = adminScreen()->programmes();
    QTRY_COMPARE(page->patientCode(), QStringLiteral("P001"));
    QTRY_COMPARE(page->table()->columnCount(), 7);  // the programme is read (with the trunk limit)
    QTest::mouseClick(findControl<QPushButton>(page, QStringLiteral("Add exercise...")),
                      Qt::LeftButton);
    auto* d = dialog<admin::ExerciseDialog>();
    QVERIFY2(d, qPrintable(armtrack::gui::test::visibleMessage(page)));
    QCOMPARE(findControl<QComboBox>(d, QStringLiteral("Protocol"))->currentText(),
             QStringLiteral("Reach forward"));
    findControl<QSpinBox>(d, QStringLiteral("Sets"))->setValue(3);
    findControl<QSpinBox>(d, QStringLiteral("Repetitions per set"))->setValue(5);
    findControl<QSpinBox>(d, QStringLiteral("Sessions per week"))->setValue(4);
    typeInto(findControl<QLineEdit>(d, QStringLiteral("Notes for the patient")),
             QStringLiteral("Slowly, with the elbow on the table"));
    save(d);
    QTRY_VERIFY(!screen()->findChild<admin::ExerciseDialog*>());
    QTRY_COMPARE(column(page->table(), 0), QStringList{QStringLiteral("Reach forward")});
    QCOMPARE(page->table()->item(0, 1)->text(), QStringLiteral("3 x 5"));
    const auto programme =
        asAdmin([](storage::ClinicalStore& s) { return s.programme(QStringLiteral("P001")); });
    QCOMPARE(programme.size(), std::size_t{1});
    QCOMPARE(programme[0].protocolName, QStringLiteral("Reach forward"));
    QCOMPARE(programme[0].sets, 3);
    QCOMPARE(programme[0].repetitions, std::optional(5));
    QCOMPARE(programme[0].sessionsPerWeek, 4);
    QVERIFY(!programme[0].targetMinDeg);  // the protocol's target
    QCOMPARE(programme[0].notes, QStringLiteral("Slowly, with the elbow on the table"));
    gui::test::saveScreenshot(m_app->window(), QStringLiteral("admin-programme"));
  }

  void everyChangeIsAuditedAsTheCommandLineDoes() {
    const auto log = asAdmin([](storage::ClinicalStore& s) { return s.auditLog(); });
    const auto has = [&](const QString& action, const QString& type, const QString& id) {
      return std::any_of(log.begin(), log.end(), [&](const storage::AuditEntry& e) {
        return e.userName == kAdmin && e.action == action && e.objectType == type &&
               e.objectId == id;
      });
    };
    QVERIFY(has(QStringLiteral("create"), QStringLiteral("user"), kTherapist));
    QVERIFY(has(QStringLiteral("update"), QStringLiteral("user"), QStringLiteral("ada-home")));
    QVERIFY(has(QStringLiteral("delete"), QStringLiteral("user"), QStringLiteral("ada-home")));
    QVERIFY(has(QStringLiteral("update"), QStringLiteral("user"), kTherapist));  // disabled
    QVERIFY(
        has(QStringLiteral("create"), QStringLiteral("protocol"), QStringLiteral("Reach forward")));
    QVERIFY(
        has(QStringLiteral("update"), QStringLiteral("protocol"), QStringLiteral("Reach forward")));
  }

  void theNewTherapistSignsInAndIsOfferedTheProtocol() {
    QTest::mouseClick(findControl<QPushButton>(screen(), QStringLiteral("Back to the patients")),
                      Qt::LeftButton);
    QTRY_VERIFY(qobject_cast<PatientListScreen*>(screen()));
    m_app->signOut();
    QVERIFY(!adminAction()->isVisible());
    signIn(kTherapist, kTherapistPassword);
    QVERIFY(!adminAction()->isVisible());  // not for therapists
    m_app->showAdmin();                    // nor through the controller
    QVERIFY(!adminScreen());
    QTRY_COMPARE(
        findControl<QTableView>(screen(), QStringLiteral("Patient list"))->model()->rowCount(), 1);
    m_app->startNewSession(QStringLiteral("P001"));
    QTRY_VERIFY(qobject_cast<NewSessionScreen*>(screen()));
    auto* setup = qobject_cast<NewSessionScreen*>(screen())->setupPage();
    QTRY_VERIFY(setup->isComplete());
    auto* protocol = findControl<QComboBox>(screen(), QStringLiteral("Protocol"));
    QVERIFY(protocol);
    QVERIFY(protocol->findData(QStringLiteral("Reach forward")) > 0);
    QVERIFY(setup->selectProtocol(QStringLiteral("Reach forward")));
    QCOMPARE(setup->plan().protocol->repetitions, 12);
    QCOMPARE(m_app->records().user().name, kTherapist);
  }

  void cleanupTestCase() { m_app.reset(); }
};

ARMTRACK_APP_TEST_MAIN(TestAdmin)
#include "test_admin.moc"
