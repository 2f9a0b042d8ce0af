// The library pane (standard blocks and the project's own, grouped, searchable, with pins, types
// and a description; a drag carries a call and the POU's name) and the IL editor's Insert menu
// (RunPro's Operator, Operand, Function, Function Block opening the input assistant).
#include "app/documentarea.h"
#include "app/librarypane.h"
#include "app/mainwindow.h"
#include "editors/text/calltext.h"
#include "editors/text/codeeditor.h"
#include "editors/text/inputassistant.h"
#include "editors/text/texteditorwidget.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"
#include "testsettings.h"

#include <QApplication>
#include <QClipboard>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidgetItemIterator>

using namespace iec;
using namespace iec::app;

namespace {

const char *const kSource = R"(FUNCTION_BLOCK Valve
VAR_INPUT
  Open : BOOL;
  Limit : INT;
END_VAR
VAR_OUTPUT
  IsOpen : BOOL;
END_VAR
IsOpen := Open;
END_FUNCTION_BLOCK
FUNCTION Twice : INT
VAR_INPUT
  X : INT;
END_VAR
Twice := 2 * X;
END_FUNCTION
PROGRAM Main
END_PROGRAM
PROGRAM Steps
END_PROGRAM
)";

model::Project sampleProject()
{
    model::Project project = interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("Test")).project;
    for (model::Pou &pou : project.types.pous) {
        if (pou.name == QLatin1String("Steps"))
            pou.bodies = {model::Body::withLanguage(model::BodyLanguage::IL)};
    }
    return project;
}

const LibraryEntry *entryNamed(const std::vector<LibraryEntry> &entries, const QString &name)
{
    const auto it = std::ranges::find_if(entries, [&](const LibraryEntry &e) { return e.call.name == name; });
    return it == entries.end() ? nullptr : &*it;
}

QStringList visibleEntries(const LibraryPane &pane)
{
    QStringList names;
    for (QTreeWidgetItemIterator it(pane.tree()); *it; ++it) {
        if (pane.entryOf(*it) && !(*it)->isHidden() && !(*it)->parent()->isHidden())
            names << (*it)->text(0);
    }
    return names;
}

} // namespace

class TestLibraryPane : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void entriesHavePinsTypesAndDescriptions();
    void callTexts_data();
    void callTexts();
    void filterFindsNamesAndDescriptions();
    void paneFollowsTheProjectsPous();
    void dragCarriesTheCallAndTheName();
    void droppedCallTakesTheEditorsLanguage();
    void ilInsertMenuOpensTheAssistantOnItsCategory();

private:
    QTemporaryDir m_configHome;
};

void TestLibraryPane::initTestCase()
{
    useTestSettings(m_configHome);
}

void TestLibraryPane::entriesHavePinsTypesAndDescriptions()
{
    const std::vector<LibraryEntry> entries = libraryEntries(sampleProject());
    const LibraryEntry *ton = entryNamed(entries, QStringLiteral("TON"));
    QVERIFY(ton);
    QCOMPARE(ton->group, QStringLiteral("Standard library"));
    QCOMPARE(ton->subgroup, QStringLiteral("Timers"));
    QCOMPARE(ton->pins, (QStringList {QStringLiteral("IN : BOOL"), QStringLiteral("PT : TIME")}));
    QCOMPARE(ton->outputPins, (QStringList {QStringLiteral("Q : BOOL"), QStringLiteral("ET : TIME")}));
    QCOMPARE(ton->description, QStringLiteral("On delay: Q follows IN after it was TRUE for PT."));
    const LibraryEntry *conversion = entryNamed(entries, QStringLiteral("INT_TO_REAL"));
    QVERIFY(conversion);
    QCOMPARE(conversion->description, QStringLiteral("Converts INT to REAL."));
    const LibraryEntry *valve = entryNamed(entries, QStringLiteral("Valve"));
    QVERIFY(valve);
    QCOMPARE(valve->group, QStringLiteral("Project"));
    QCOMPARE(valve->subgroup, QStringLiteral("Function Blocks"));
    QCOMPARE(valve->pins, (QStringList {QStringLiteral("Open : BOOL"), QStringLiteral("Limit : INT")}));
    QCOMPARE(valve->outputPins, QStringList {QStringLiteral("IsOpen : BOOL")});
    const LibraryEntry *twice = entryNamed(entries, QStringLiteral("Twice"));
    QVERIFY(twice && twice->returnType == QLatin1String("INT"));
    QVERIFY(!entryNamed(entries, QStringLiteral("Main"))); // programs are not called
    QVERIFY(libraryEntryDetails(*ton).contains(QStringLiteral("IN : BOOL, PT : TIME")));
}

void TestLibraryPane::callTexts_data()
{
    QTest::addColumn<int>("language");
    QTest::addColumn<bool>("block");
    QTest::addColumn<QString>("expected");
    QTest::newRow("ST function") << int(editors::TextLanguage::ST) << false << QStringLiteral("LIMIT(MN := , IN := , MX :=)");
    QTest::newRow("ST block") << int(editors::TextLanguage::ST) << true << QStringLiteral("TON_1(IN := , PT := , Q => , ET =>);");
    QTest::newRow("IL function") << int(editors::TextLanguage::IL) << false << QStringLiteral("LIMIT(MN := , IN := , MX :=)");
    QTest::newRow("IL block") << int(editors::TextLanguage::IL) << true << QStringLiteral("CAL TON_1(IN := , PT :=)");
}

void TestLibraryPane::callTexts()
{
    QFETCH(int, language);
    QFETCH(bool, block);
    QFETCH(QString, expected);
    const editors::CallSignature signature = block
        ? editors::CallSignature {QStringLiteral("TON"), true, {QStringLiteral("IN"), QStringLiteral("PT")},
              {QStringLiteral("Q"), QStringLiteral("ET")}}
        : editors::CallSignature {QStringLiteral("LIMIT"), false,
              {QStringLiteral("MN"), QStringLiteral("IN"), QStringLiteral("MX")}, {}};
    QCOMPARE(editors::callText(editors::TextLanguage(language), signature), expected);
}

void TestLibraryPane::filterFindsNamesAndDescriptions()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    LibraryPane pane(model);
    pane.setFilter(QStringLiteral("off delay"));
    QCOMPARE(visibleEntries(pane), QStringList {QStringLiteral("TOF")});
    pane.setFilter(QStringLiteral("valv"));
    QCOMPARE(visibleEntries(pane), QStringList {QStringLiteral("Valve")});
    QVERIFY(pane.selectEntry(QStringLiteral("valve")));
    QVERIFY(pane.detailsText().contains(QStringLiteral("Limit : INT")));
    pane.setFilter({});
    QVERIFY(visibleEntries(pane).size() > 100);
}

void TestLibraryPane::paneFollowsTheProjectsPous()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    LibraryPane pane(model);
    model::Pou scale;
    scale.name = QStringLiteral("Scale");
    scale.kind = model::PouKind::Function;
    model.addPou(scale);
    pane.setFilter(QStringLiteral("scale"));
    QCOMPARE(visibleEntries(pane), QStringList {QStringLiteral("Scale")});
}

void TestLibraryPane::dragCarriesTheCallAndTheName()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    LibraryPane pane(model);
    QVERIFY(pane.selectEntry(QStringLiteral("Valve")));
    const std::unique_ptr<QMimeData> data(pane.tree()->mimeData({pane.tree()->currentItem()}));
    QVERIFY(data);
    QCOMPARE(data->data(QString::fromLatin1(editors::kPouMimeType)), QByteArray("Valve"));
    QCOMPARE(QString::fromUtf8(data->data(QString::fromLatin1(editors::kStCallMimeType))),
        QStringLiteral("Valve_1(Open := , Limit := , IsOpen =>);"));
    QCOMPARE(data->text(), QStringLiteral("Valve_1(Open := , Limit := , IsOpen =>);"));
    QCOMPARE(QString::fromUtf8(data->data(QString::fromLatin1(editors::kIlCallMimeType))),
        QStringLiteral("CAL Valve_1(Open := , Limit :=)"));
}

void TestLibraryPane::droppedCallTakesTheEditorsLanguage()
{
    // Paste goes the way a drop goes (insertFromMimeData).
    editors::CodeEditor st(editors::TextLanguage::ST);
    editors::CodeEditor il(editors::TextLanguage::IL);
    for (editors::CodeEditor *editor : {&st, &il}) {
        QApplication::clipboard()->setMimeData(editors::pouMimeData(
            {QStringLiteral("Twice"), false, {QStringLiteral("X")}, {}}));
        editor->paste();
    }
    QCOMPARE(st.toPlainText(), QStringLiteral("Twice(X :=)"));
    QCOMPARE(il.toPlainText(), QStringLiteral("Twice(X :=)"));
    QApplication::clipboard()->setMimeData(editors::pouMimeData({QStringLiteral("TON"), true, {QStringLiteral("IN")}, {}}));
    il.clear();
    il.paste();
    QCOMPARE(il.toPlainText(), QStringLiteral("CAL TON_1(IN :=)"));
}

void TestLibraryPane::ilInsertMenuOpensTheAssistantOnItsCategory()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    const model::Pou *steps = window.projectModel().project().findPou(QStringLiteral("Steps"));
    window.documents().openBody({steps->id, model::BodyRef::Part::Pou, {}});
    auto *insert = window.menuBar()->findChild<QMenu *>(QStringLiteral("insertMenu"));
    QStringList texts;
    QList<QAction *> entries;
    for (QAction *action : insert->actions()) {
        if (action->objectName().startsWith(QLatin1String("ilInsert")) && action->isVisible()) {
            texts << action->text();
            entries << action;
        }
    }
    QCOMPARE(texts, (QStringList {QStringLiteral("&Operator..."), QStringLiteral("O&perand..."),
                        QStringLiteral("&Function..."), QStringLiteral("Function &Block...")}));
    editors::CodeEditor *editor = window.documents().textEditorFor({steps->id, model::BodyRef::Part::Pou, {}});
    using Category = editors::InputAssistantDialog::Category;
    const Category expected[] {Category::Operators, Category::Operands, Category::Functions, Category::FunctionBlocks};
    for (int index = 0; index < 4; ++index) {
        entries[index]->trigger();
        QVERIFY(editor->inputAssistant());
        QCOMPARE(editor->inputAssistant()->category(), expected[index]);
    }
    editor->inputAssistant()->selectItem(QStringLiteral("TON"));
    // An ST body has no such entries.
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    for (QAction *action : insert->actions())
        QVERIFY(!action->objectName().startsWith(QLatin1String("ilInsert")));
}

QTEST_MAIN(TestLibraryPane)
#include "tst_librarypane.moc"
