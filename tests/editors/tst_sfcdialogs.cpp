// The SFC editor's dialogs driven as a new user drives them (issue 13): Step Properties creates
// the actions it names in the same undo step and keeps a refused input open with the reason, the
// IEC Actions dialog shows its headers whole and offers BOOL variables with completion.
#include "editors/sfc/sfcdialogs.h"
#include "editors/sfc/sfceditor.h"
#include "editors/sfc/sfcgeometry.h"
#include "editors/text/completion.h"
#include "model/body.h"
#include "model/projectmodel.h"
#include "model/sfcoptions.h"

#include <QApplication>
#include <QComboBox>
#include <QCompleter>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QTranslator>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors::sfc;
using model::BodyRef;

namespace {

model::Project projectWithEmptyChart()
{
    model::Project project;
    model::Pou pou;
    pou.name = QStringLiteral("Tank");
    pou.kind = model::PouKind::Program;
    pou.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::SFC));
    model::PouPart existing;
    existing.name = QStringLiteral("Existing");
    existing.body = model::Body::withLanguage(model::BodyLanguage::ST);
    pou.actions.push_back(existing);
    project.types.pous.push_back(pou);
    return project;
}

// Runs `use` on the dialog of type D once the command has opened it (modal), then closes it if
// it is still open, so that a failing check never leaves the test waiting in exec().
template<class D> void whenOpen(const std::function<void(D &)> &use)
{
    QTimer::singleShot(0, qApp, [use] {
        auto *dialog = qobject_cast<D *>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        use(*dialog);
        if (dialog->isVisible())
            dialog->reject();
    });
}

void pressOk(QDialog &dialog)
{
    dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok)->click();
}

// What the app's completion provider says: BOOL variables, one INT, a global BOOL.
class Variables : public editors::CompletionProvider
{
public:
    QList<editors::CompletionItem> variables() const override
    {
        using Item = editors::CompletionItem;
        return {{QStringLiteral("Horn"), Item::Kind::Variable, QStringLiteral("BOOL"), {}},
            {QStringLiteral("Level"), Item::Kind::Variable, QStringLiteral("INT"), {}},
            {QStringLiteral("AlarmLamp"), Item::Kind::Variable, QStringLiteral("bool"), QStringLiteral("Global variables")}};
    }
    QList<editors::CompletionItem> members(const QString &) const override { return {}; }
    QList<editors::CompletionItem> pous() const override { return {}; }
};

// Every text made long, as German and Chinese fonts make them: the columns must still show them.
class LongTranslator : public QTranslator
{
public:
    QString translate(const char *, const char *sourceText, const char *, int) const override
    {
        const QString text = QString::fromUtf8(sourceText);
        return text + QLatin1Char(' ') + text + QStringLiteral(" (lang)");
    }
    bool isEmpty() const override { return false; }
};

} // namespace

class TestSfcDialogs : public QObject
{
    Q_OBJECT

private:
    struct Fixture {
        model::ProjectModel model;
        QUndoStack stack;
        BodyRef ref;
        std::unique_ptr<SfcEditor> editor;

        Fixture()
        {
            model.reset(projectWithEmptyChart());
            ref = BodyRef {model.project().types.pous.front().id};
            editor = std::make_unique<SfcEditor>(model, ref, &stack);
            editor->resize(900, 700);
            editor->trigger(QStringLiteral("sfcNewChart"));
            editor->trigger(QStringLiteral("sfcStepAfter")); // Init, T, Step1 (selected), T, jump
            stack.clear();
        }
        const model::Pou &pou() const { return *model.project().findPou(ref.pou); }
        QStringList actionNames() const
        {
            QStringList names;
            for (const model::PouPart &part : pou().actions)
                names << part.name;
            return names;
        }
        model::StepOptions optionsOf(const QString &step) const { return stepProperties(editor->document(), editor->stepId(step))->options; }
    };

private Q_SLOTS:
    // Item 5: typed names become POU actions (ST), with the property change as one undo step.
    void stepPropertiesCreatesTheActionsItNames()
    {
        Fixture f;
        f.editor->select({f.editor->stepId(QStringLiteral("Init"))});
        whenOpen<StepPropertiesDialog>([](StepPropertiesDialog &dialog) {
            dialog.findChild<QComboBox *>(QStringLiteral("entryAction"))->setCurrentText(QStringLiteral("Init_entry"));
            dialog.findChild<QComboBox *>(QStringLiteral("exitAction"))->setCurrentText(QStringLiteral("existing"));
            pressOk(dialog);
        });
        QVERIFY2(f.editor->trigger(QStringLiteral("sfcProperties")), qPrintable(f.editor->lastMessage()));
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(f.stack.undoText(), QStringLiteral("Change step"));
        QCOMPARE(f.actionNames(), (QStringList {QStringLiteral("Existing"), QStringLiteral("Init_entry")}));
        QCOMPARE(f.pou().actions.back().body.language(), model::BodyLanguage::ST);
        QCOMPARE(f.optionsOf(QStringLiteral("Init")).entryAction, QStringLiteral("Init_entry"));
        QCOMPARE(f.optionsOf(QStringLiteral("Init")).exitAction, QStringLiteral("existing"));
        f.stack.undo();
        QCOMPARE(f.actionNames(), QStringList {QStringLiteral("Existing")});
        QCOMPARE(f.optionsOf(QStringLiteral("Init")).entryAction, QString());
        f.stack.redo();
        QCOMPARE(f.actionNames(), (QStringList {QStringLiteral("Existing"), QStringLiteral("Init_entry")}));
        QCOMPARE(f.optionsOf(QStringLiteral("Init")).entryAction, QStringLiteral("Init_entry"));
    }

    // Item 5: the E corner and the dialog take the same path (one undo step each).
    void theCornerCreatesItsActionToo()
    {
        Fixture f;
        const quint64 step = f.editor->stepId(QStringLiteral("Step1"));
        QVERIFY(f.editor->openStepAction(step, QStringLiteral("exit")));
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(f.optionsOf(QStringLiteral("Step1")).exitAction, QStringLiteral("Step1_exit"));
        QVERIFY(f.actionNames().contains(QStringLiteral("Step1_exit")));
        // Named and existing: nothing to push, the action is only opened.
        QVERIFY(f.editor->openStepAction(step, QStringLiteral("exit")));
        QCOMPARE(f.stack.count(), 1);
        f.stack.undo();
        QCOMPARE(f.actionNames(), QStringList {QStringLiteral("Existing")});
    }

    // Item 14: a refusal is shown in the dialog, which stays open with what was typed.
    void aRefusedDialogStaysOpenWithTheReason_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("entry");
        QTest::addColumn<QString>("reason");
        QTest::newRow("duplicate step name") << QStringLiteral("Init") << QString() << QStringLiteral("There is already a step named 'Init'.");
        QTest::newRow("invalid step name") << QStringLiteral("2nd") << QString()
                                           << QStringLiteral("'2nd' is not a valid step name: use letters, digits and single underscores, starting with a letter.");
        QTest::newRow("invalid action name") << QStringLiteral("Step1") << QStringLiteral("Fill tank")
                                             << QStringLiteral("'Fill tank' is not a valid action name: use letters, digits and single underscores, starting with a letter.");
    }

    void aRefusedDialogStaysOpenWithTheReason()
    {
        QFETCH(QString, name);
        QFETCH(QString, entry);
        QFETCH(QString, reason);
        Fixture f;
        f.editor->select({f.editor->stepId(QStringLiteral("Step1"))});
        bool stayedOpen = false;
        QString shown;
        QString kept;
        whenOpen<StepPropertiesDialog>([&](StepPropertiesDialog &dialog) {
            auto *nameEdit = dialog.findChild<QLineEdit *>(QStringLiteral("stepName"));
            nameEdit->setText(name);
            dialog.findChild<QComboBox *>(QStringLiteral("entryAction"))->setCurrentText(entry);
            pressOk(dialog);
            stayedOpen = dialog.isVisible();
            const auto *problem = dialog.findChild<QLabel *>(QStringLiteral("stepPropertiesProblem"));
            shown = problem->isVisible() ? problem->text() : QString();
            kept = nameEdit->text();
            // Corrected, OK goes through.
            nameEdit->setText(QStringLiteral("Fill"));
            dialog.findChild<QComboBox *>(QStringLiteral("entryAction"))->setCurrentText(QString());
            pressOk(dialog);
        });
        QVERIFY(f.editor->trigger(QStringLiteral("sfcProperties")));
        QVERIFY(stayedOpen);
        QCOMPARE(shown, reason);
        QCOMPARE(kept, name);
        QCOMPARE(f.stack.count(), 1);
        QVERIFY(f.editor->stepId(QStringLiteral("Fill")) != 0);
        QCOMPARE(f.actionNames(), QStringList {QStringLiteral("Existing")});
    }

    // Item 9: every header is shown whole, in any language.
    void actionColumnsShowTheirHeaders_data()
    {
        QTest::addColumn<bool>("longTexts");
        QTest::newRow("English") << false;
        QTest::newRow("long translation") << true;
    }

    void actionColumnsShowTheirHeaders()
    {
        QFETCH(bool, longTexts);
        LongTranslator translator;
        if (longTexts)
            QCoreApplication::installTranslator(&translator);
        ActionAssociationsDialog dialog({actionAssociation(QStringLiteral("N"), QStringLiteral("Fill"))}, {QStringLiteral("Fill")});
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QCoreApplication::removeTranslator(&translator);
        auto *table = dialog.findChild<QTableWidget *>(QStringLiteral("actionTable"));
        QHeaderView *header = table->horizontalHeader();
        for (int column = 0; column < table->columnCount(); ++column) {
            const QString label = table->horizontalHeaderItem(column)->text();
            QVERIFY2(!longTexts || label.endsWith(QStringLiteral("(lang)")), qPrintable(label));
            QVERIFY2(header->sectionSize(column) > header->fontMetrics().horizontalAdvance(label), qPrintable(label));
            QVERIFY2(header->sectionViewportPosition(column) + header->sectionSize(column) <= header->viewport()->width(),
                qPrintable(label));
        }
    }

    // Item 10: the action field offers the POU's actions and the BOOL variables, and completes.
    void actionFieldOffersBooleanVariables()
    {
        Fixture f;
        Variables variables;
        f.editor->setCompletionProvider(&variables);
        f.editor->select({f.editor->stepId(QStringLiteral("Step1"))});
        QStringList offered;
        QString completed;
        whenOpen<ActionAssociationsDialog>([&](ActionAssociationsDialog &dialog) {
            auto *table = dialog.findChild<QTableWidget *>(QStringLiteral("actionTable"));
            const auto buttons = dialog.findChildren<QPushButton *>();
            const auto add = std::ranges::find_if(buttons, [](QPushButton *b) { return b->text() == QStringLiteral("Add"); });
            (*add)->click();
            auto *name = qobject_cast<QComboBox *>(table->cellWidget(0, 2));
            for (int i = 0; i < name->count(); ++i)
                offered << name->itemText(i);
            name->completer()->setCompletionPrefix(QStringLiteral("ala"));
            completed = name->completer()->currentCompletion();
            name->setCurrentText(QStringLiteral("Horn"));
            pressOk(dialog);
        });
        QVERIFY(f.editor->trigger(QStringLiteral("sfcActions")));
        QCOMPARE(offered, (QStringList {QStringLiteral("Existing"), QStringLiteral("Horn"), QStringLiteral("AlarmLamp")}));
        QCOMPARE(completed, QStringLiteral("AlarmLamp"));
        const auto actions = stepActions(f.editor->document(), f.editor->stepId(QStringLiteral("Step1")));
        QCOMPARE(actions.size(), std::size_t(1));
        QCOMPARE(actionName(actions.front()), QStringLiteral("Horn"));
        f.editor->setCompletionProvider(nullptr);
    }
};

QTEST_MAIN(TestSfcDialogs)
#include "tst_sfcdialogs.moc"
