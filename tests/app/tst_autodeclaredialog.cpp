// The Declare Variable dialog driven from the keyboard: a type typed (with the combo box's inline
// completion) and one Enter declare it; Enter does nothing while the row is refused.
#include "app/autodeclaredialog.h"

#include <QComboBox>
#include <QLineEdit>
#include <QTest>

using namespace iec;
using namespace iec::app;

class TestAutoDeclareDialog : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void oneEnterDeclares_data()
    {
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("type");
        QTest::newRow("the guess as it is") << "" << "BOOL";
        QTest::newRow("completed inline") << "TI" << "TIME";
        QTest::newRow("typed whole") << "LREAL" << "LREAL";
        QTest::newRow("a type not offered") << "MyStruct" << "MyStruct";
    }

    void oneEnterDeclares()
    {
        QFETCH(QString, typed);
        QFETCH(QString, type);
        editors::DeclarationRow proposal;
        proposal.name = QStringLiteral("Lamp");
        proposal.varClass = QStringLiteral("VAR");
        proposal.type = QStringLiteral("BOOL");
        AutoDeclareDialog dialog(proposal, {QStringLiteral("BOOL"), QStringLiteral("INT"), QStringLiteral("LREAL"), QStringLiteral("TIME")},
            [](const editors::DeclarationRow &) { return QString(); });
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QLineEdit *field = dialog.typeBox()->lineEdit();
        if (!typed.isEmpty()) {
            field->selectAll();
            QTest::keyClicks(field, typed);
        }
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(dialog.row().type, type);
        QCOMPARE(dialog.row().name, QStringLiteral("Lamp"));
    }

    void enterIsRefusedWhileTheRowIs()
    {
        editors::DeclarationRow proposal;
        proposal.name = QStringLiteral("Lamp");
        proposal.varClass = QStringLiteral("VAR");
        proposal.type = QStringLiteral("BOOL");
        AutoDeclareDialog dialog(proposal, {QStringLiteral("BOOL")}, [](const editors::DeclarationRow &row) {
            return row.type.isEmpty() ? QStringLiteral("A variable needs a type.") : QString();
        });
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QLineEdit *field = dialog.typeBox()->lineEdit();
        field->clear();
        QTest::keyClick(field, Qt::Key_Return);
        QVERIFY(dialog.isVisible());
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
    }
};

QTEST_MAIN(TestAutoDeclareDialog)
#include "tst_autodeclaredialog.moc"
