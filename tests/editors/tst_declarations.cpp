// The declaration editor: its pure functions as tables (interface <-> rows, interface <-> text,
// validation) and the widget driven as a user drives it, checking the model after redo/undo/redo.
#include "editors/declarations/declarationeditor.h"
#include "editors/declarations/declarationrows.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/declarations/declarationtext.h"
#include "editors/text/codeeditor.h"
#include "model/projectmodel.h"
#include "model/undo/variablecommands.h"

#include <QLabel>
#include <QTableView>
#include <QTest>
#include <QUndoStack>

using namespace iec::editors;
using namespace iec::model;

Q_DECLARE_METATYPE(iec::model::Interface)
Q_DECLARE_METATYPE(std::vector<iec::editors::DeclarationRow>)
Q_DECLARE_METATYPE(std::vector<iec::editors::RowProblem>)
Q_DECLARE_METATYPE(std::vector<iec::editors::DeclarationProblem>)
Q_DECLARE_METATYPE(iec::editors::DeclarationColumn)

namespace {

Variable variable(const QString &name, const QString &type, const QString &initial = {}, const QString &address = {},
    const QString &comment = {})
{
    Variable v;
    v.name = name;
    v.type = {ElementaryType {type}};
    if (!initial.isEmpty())
        v.initialValue = Value {SimpleValue {initial}};
    if (!address.isEmpty())
        v.address = address;
    if (!comment.isEmpty())
        v.documentation = FormattedText {comment, {}};
    return v;
}

VarList varList(VarListKind kind, std::vector<Variable> variables, bool constant = false, bool retain = false)
{
    VarList list;
    list.kind = kind;
    list.constant = constant;
    list.retain = retain;
    list.variables = std::move(variables);
    return list;
}

Interface interfaceOf(std::vector<VarList> lists)
{
    Interface declarations;
    declarations.varLists = std::move(lists);
    return declarations;
}

DeclarationRow row(const QString &name, const QString &varClass, const QString &type, const QString &initial = {},
    const QString &address = {}, const QString &comment = {})
{
    return {name, varClass, type, initial, address, comment};
}

// Blink's declarations: three lists, an address, initial values, comments.
Interface sample()
{
    return interfaceOf({varList(VarListKind::Input,
                            {variable(QStringLiteral("Start"), QStringLiteral("BOOL"), {}, QStringLiteral("%IX0.0"),
                                QStringLiteral("Start button"))}),
        varList(VarListKind::Local,
            {variable(QStringLiteral("Count"), QStringLiteral("INT"), QStringLiteral("5")),
                variable(QStringLiteral("Lamp"), QStringLiteral("BOOL"), {}, QStringLiteral("%QX0.1"))}),
        varList(VarListKind::Local, {variable(QStringLiteral("Limit"), QStringLiteral("INT"), QStringLiteral("10"))},
            true)});
}

std::vector<DeclarationRow> sampleRows()
{
    return {row(QStringLiteral("Start"), QStringLiteral("VAR_INPUT"), QStringLiteral("BOOL"), {},
                QStringLiteral("%IX0.0"), QStringLiteral("Start button")),
        row(QStringLiteral("Count"), QStringLiteral("VAR"), QStringLiteral("INT"), QStringLiteral("5")),
        row(QStringLiteral("Lamp"), QStringLiteral("VAR"), QStringLiteral("BOOL"), {}, QStringLiteral("%QX0.1")),
        row(QStringLiteral("Limit"), QStringLiteral("VAR CONSTANT"), QStringLiteral("INT"), QStringLiteral("10"))};
}

const QString kSampleText = QStringLiteral("VAR_INPUT\n"
                                           "    Start AT %IX0.0 : BOOL; (* Start button *)\n"
                                           "END_VAR\n"
                                           "\n"
                                           "VAR\n"
                                           "    Count : INT := 5;\n"
                                           "    Lamp AT %QX0.1 : BOOL;\n"
                                           "END_VAR\n"
                                           "\n"
                                           "VAR CONSTANT\n"
                                           "    Limit : INT := 10;\n"
                                           "END_VAR\n");

Pou samplePou()
{
    Pou pou;
    pou.name = QStringLiteral("Blink");
    pou.pouInterface = sample();
    pou.bodies.push_back(Body::withLanguage(BodyLanguage::ST));
    return pou;
}

// Replaces the editor's whole text as typing does (so textEdited follows).
void typeText(CodeEditor &editor, const QString &text)
{
    editor.selectAll();
    editor.insertPlainText(text);
}

} // namespace

class TestDeclarations : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    // pure functions
    void rowsFromInterfaceListsEveryVariable();
    void interfaceFromRows_data();
    void interfaceFromRows();
    void validateRows_data();
    void validateRows();
    void declarationTextPrintsSectionsWithComments();
    void readDeclarationText_data();
    void commentsPrintAsTheyRead();
    void readDeclarationText();
    void textKeepsWhatItCannotShow();
    void addresses_data();
    void addresses();
    void freeVariableNameSkipsTakenNames();

    // the widget
    void cellEditAppliesOneCommand_data();
    void cellEditAppliesOneCommand();
    void invalidCellIsMarkedAndNotApplied();
    void rowGestures_data();
    void rowGestures();
    void textEditAppliesOnePauseAsOneCommand();
    void invalidTextShowsALocatedError();
    void focusOutAppliesPendingText();
    void modelChangeRefreshesBothViews();
    void ctrlZInTheTableUndoes();

private:
    std::unique_ptr<ProjectModel> m_model;
    std::unique_ptr<QUndoStack> m_stack;
    std::unique_ptr<DeclarationEditor> m_editor;
    PouId m_pou;

    [[nodiscard]] Interface modelInterface() const
    {
        return m_model->project().findPou(m_pou)->pouInterface.value_or(Interface {});
    }
    void checkRedoUndoRedo(const Interface &before, const Interface &after);
};

void TestDeclarations::init()
{
    m_model = std::make_unique<ProjectModel>();
    m_stack = std::make_unique<QUndoStack>();
    m_pou = m_model->addPou(samplePou());
    m_editor = std::make_unique<DeclarationEditor>(*m_model, m_pou, *m_stack);
    m_editor->textEditor()->setEditDebounceInterval(60000); // tests apply with flushPendingEdit
    m_editor->resize(800, 300);
}

void TestDeclarations::cleanup()
{
    m_editor.reset();
    m_stack.reset();
    m_model.reset();
}

void TestDeclarations::checkRedoUndoRedo(const Interface &before, const Interface &after)
{
    QCOMPARE(m_stack->count(), 1);
    QCOMPARE(modelInterface(), after);
    m_stack->undo();
    QCOMPARE(modelInterface(), before);
    QCOMPARE(m_editor->tableModel()->rows(), rowsFromInterface(before));
    QCOMPARE(m_editor->textEditor()->toPlainText(), declarationText(before));
    m_stack->redo();
    QCOMPARE(modelInterface(), after);
    QCOMPARE(m_editor->tableModel()->rows(), rowsFromInterface(after));
}

// ---- pure functions ---------------------------------------------------------------------------

void TestDeclarations::rowsFromInterfaceListsEveryVariable()
{
    QCOMPARE(rowsFromInterface(sample()), sampleRows());
    QCOMPARE(rowsFromInterface(Interface {}), std::vector<DeclarationRow> {});
}

void TestDeclarations::interfaceFromRows_data()
{
    QTest::addColumn<std::vector<DeclarationRow>>("rows");
    QTest::addColumn<Interface>("expected");

    QTest::newRow("the sample") << sampleRows() << sample();
    QTest::newRow("no rows") << std::vector<DeclarationRow> {} << Interface {};
    QTest::newRow("same class apart makes two lists")
        << std::vector {row(QStringLiteral("a"), QStringLiteral("VAR"), QStringLiteral("INT")),
               row(QStringLiteral("b"), QStringLiteral("VAR_OUTPUT"), QStringLiteral("BOOL")),
               row(QStringLiteral("c"), QStringLiteral("VAR"), QStringLiteral("REAL"))}
        << interfaceOf({varList(VarListKind::Local, {variable(QStringLiteral("a"), QStringLiteral("INT"))}),
               varList(VarListKind::Output, {variable(QStringLiteral("b"), QStringLiteral("BOOL"))}),
               varList(VarListKind::Local, {variable(QStringLiteral("c"), QStringLiteral("REAL"))})});
    QTest::newRow("type case is normalised, retain kept")
        << std::vector {row(QStringLiteral("t"), QStringLiteral("VAR RETAIN"), QStringLiteral("int"),
               QStringLiteral("16#FF"), {}, QStringLiteral("kept"))}
        << interfaceOf({varList(VarListKind::Local,
               {variable(
                   QStringLiteral("t"), QStringLiteral("INT"), QStringLiteral("16#FF"), {}, QStringLiteral("kept"))},
               false, true)});
    Variable timer;
    timer.name = QStringLiteral("Delay");
    timer.type = {DerivedType {QStringLiteral("TON"), {}, {}}};
    VarList persistent
        = varList(VarListKind::Local, {variable(QStringLiteral("p"), QStringLiteral("DINT"))}, false, true);
    persistent.persistent = true;
    QTest::newRow("retain persistent") << std::vector {row(QStringLiteral("p"), QStringLiteral("VAR RETAIN PERSISTENT"),
        QStringLiteral("DINT"))} << interfaceOf({persistent});
    QTest::newRow("a function block instance")
        << std::vector {row(QStringLiteral("Delay"), QStringLiteral("VAR"), QStringLiteral("TON"))}
        << interfaceOf({varList(VarListKind::Local, {timer})});
}

void TestDeclarations::interfaceFromRows()
{
    QFETCH(std::vector<DeclarationRow>, rows);
    QFETCH(Interface, expected);
    const RowsResult result = iec::editors::interfaceFromRows(rows);
    QCOMPARE(result.problems, std::vector<RowProblem> {});
    QVERIFY(result.declarations.has_value());
    QCOMPARE(*result.declarations, expected);
}

void TestDeclarations::validateRows_data()
{
    QTest::addColumn<std::vector<DeclarationRow>>("rows");
    QTest::addColumn<int>("problemRow");
    QTest::addColumn<DeclarationColumn>("problemColumn");

    const QString var = QStringLiteral("VAR");
    const QString boolType = QStringLiteral("BOOL");
    auto one = [&](const DeclarationRow &r) { return std::vector {row(QStringLiteral("ok"), var, boolType), r}; };
    QTest::newRow("name starts with a digit")
        << one(row(QStringLiteral("1x"), var, boolType)) << 1 << DeclarationColumn::Name;
    QTest::newRow("double underscore") << one(row(QStringLiteral("a__b"), var, boolType)) << 1
                                       << DeclarationColumn::Name;
    QTest::newRow("keyword as name") << one(row(QStringLiteral("IF"), var, boolType)) << 1 << DeclarationColumn::Name;
    QTest::newRow("empty name") << one(row(QString(), var, boolType)) << 1 << DeclarationColumn::Name;
    QTest::newRow("duplicate, other case")
        << one(row(QStringLiteral("OK"), var, boolType)) << 1 << DeclarationColumn::Name;
    QTest::newRow("unknown class") << one(row(QStringLiteral("x"), QStringLiteral("VAR_FOO"), boolType)) << 1
                                   << DeclarationColumn::Class;
    QTest::newRow("VAR_ACCESS in a POU") << one(row(QStringLiteral("x"), QStringLiteral("VAR_ACCESS"), boolType)) << 1
                                         << DeclarationColumn::Class;
    QTest::newRow("empty type") << one(row(QStringLiteral("x"), var, QString())) << 1 << DeclarationColumn::Type;
    QTest::newRow("type with an initial value")
        << one(row(QStringLiteral("x"), var, QStringLiteral("INT := 3"))) << 1 << DeclarationColumn::Type;
    QTest::newRow("two declarations in the type")
        << one(row(QStringLiteral("x"), var, QStringLiteral("INT; y : BOOL"))) << 1 << DeclarationColumn::Type;
    QTest::newRow("broken array type") << one(row(QStringLiteral("x"), var, QStringLiteral("ARRAY[1..] OF INT"))) << 1
                                       << DeclarationColumn::Type;
    QTest::newRow("initial value does not parse")
        << one(row(QStringLiteral("x"), var, QStringLiteral("INT"), QStringLiteral("3 +"))) << 1
        << DeclarationColumn::InitialValue;
    QTest::newRow("address without %") << one(row(QStringLiteral("x"), var, boolType, {}, QStringLiteral("IX0.0"))) << 1
                                       << DeclarationColumn::Address;
    QTest::newRow("address with a bad area")
        << one(row(QStringLiteral("x"), var, boolType, {}, QStringLiteral("%ZX0.0"))) << 1
        << DeclarationColumn::Address;
}

void TestDeclarations::validateRows()
{
    QFETCH(std::vector<DeclarationRow>, rows);
    QFETCH(int, problemRow);
    QFETCH(DeclarationColumn, problemColumn);
    const std::vector<RowProblem> problems = iec::editors::validateRows(rows);
    QCOMPARE(problems.size(), size_t(1));
    QCOMPARE(problems.front().row, problemRow);
    QCOMPARE(problems.front().column, problemColumn);
    QVERIFY(!problems.front().message.isEmpty());
    QVERIFY(!iec::editors::interfaceFromRows(rows).declarations.has_value());
}

void TestDeclarations::declarationTextPrintsSectionsWithComments()
{
    QCOMPARE(declarationText(sample()), kSampleText);
    QCOMPARE(declarationText(Interface {}), QString());
}

void TestDeclarations::readDeclarationText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<Interface>("expected");
    QTest::addColumn<std::vector<DeclarationProblem>>("problems");

    QTest::newRow("the sample") << kSampleText << sample() << std::vector<DeclarationProblem> {};
    QTest::newRow("empty") << QString() << Interface {} << std::vector<DeclarationProblem> {};
    QTest::newRow("// comment and two names on one line")
        << QStringLiteral("VAR_OUTPUT\n  a, b : REAL; // both\nEND_VAR")
        << interfaceOf({varList(VarListKind::Output,
               {variable(QStringLiteral("a"), QStringLiteral("REAL"), {}, {}, QStringLiteral("both")),
                   variable(QStringLiteral("b"), QStringLiteral("REAL"), {}, {}, QStringLiteral("both"))})})
        << std::vector<DeclarationProblem> {};
    // Found by fuzz_declarations: a comment over two lines is read as the one line it prints as.
    QTest::newRow("comment over two lines")
        << QStringLiteral("VAR\n  a : INT; (* first\nsecond *)\nEND_VAR")
        << interfaceOf({varList(VarListKind::Local,
               {variable(QStringLiteral("a"), QStringLiteral("INT"), {}, {}, QStringLiteral("first second"))})})
        << std::vector<DeclarationProblem> {};
    QTest::newRow("missing semicolon") << QStringLiteral("VAR\n  a : INT\n  b : BOOL;\nEND_VAR") << Interface {}
                                       << std::vector<DeclarationProblem> {
                                              {2, 10, QStringLiteral("Missing ';' after the declaration of a.")}};
    QTest::newRow("duplicate") << QStringLiteral("VAR\n  a : INT;\nEND_VAR\nVAR_INPUT\n  A : BOOL;\nEND_VAR")
                               << Interface {}
                               << std::vector<DeclarationProblem> {{5, 3, QStringLiteral("A is declared twice.")}};
    QTest::newRow("bad address") << QStringLiteral("VAR\n  a AT %IX : BOOL;\nEND_VAR") << Interface {}
                                 << std::vector<DeclarationProblem> {
                                        {2, 8, QStringLiteral("'%IX' is not valid IEC 61131-3 text.")}};
    QTest::newRow("access variables") << QStringLiteral("VAR\nEND_VAR\nVAR_ACCESS\nEND_VAR") << Interface {}
                                      << std::vector<DeclarationProblem> {{3, 1,
                                             QStringLiteral("VAR_ACCESS and VAR_CONFIG belong in a configuration, "
                                                            "not in a POU.")}};
}

void TestDeclarations::readDeclarationText()
{
    QFETCH(QString, text);
    QFETCH(Interface, expected);
    QFETCH(std::vector<DeclarationProblem>, problems);
    const DeclarationTextResult result = iec::editors::readDeclarationText(text);
    if (!problems.empty()) {
        QVERIFY(!result.problems.empty());
        QCOMPARE(result.problems.front().message, problems.front().message);
        QCOMPARE(result.problems.front().line, problems.front().line);
        QCOMPARE(result.problems.front().column, problems.front().column);
        QVERIFY(!result.declarations.has_value());
        return;
    }
    QCOMPARE(result.problems, problems);
    QVERIFY(result.declarations.has_value());
    QCOMPARE(*result.declarations, expected);
}

void TestDeclarations::commentsPrintAsTheyRead()
{
    // "*)" would end a (* *) comment early: such a text is printed as a // comment.
    for (const QString &comment : {QStringLiteral("opens *) the valve"), QStringLiteral("first second")}) {
        const Interface declared = interfaceOf({varList(VarListKind::Local,
            {variable(QStringLiteral("a"), QStringLiteral("INT"), {}, {}, comment)})});
        const DeclarationTextResult result = iec::editors::readDeclarationText(declarationText(declared));
        QVERIFY(result.declarations.has_value());
        QCOMPARE(*result.declarations, declared);
    }
    QVERIFY(declarationText(interfaceOf({varList(VarListKind::Local,
                                {variable(QStringLiteral("a"), QStringLiteral("INT"), {}, {}, QStringLiteral("x *) y"))})}))
                .contains(QStringLiteral("a : INT; // x *) y")));
}

void TestDeclarations::textKeepsWhatItCannotShow()
{
    Interface base = sample();
    base.returnType = DataType {ElementaryType {QStringLiteral("INT")}};
    base.varLists[1].variables[0].globalId = QStringLiteral("id-count");
    base.varLists[1].addData.push_back(
        {QStringLiteral("urn:vendor"), QStringLiteral("preserve"), QStringLiteral("<x/>")});
    const DeclarationTextResult result = iec::editors::readDeclarationText(declarationText(base), base);
    QVERIFY(result.declarations.has_value());
    QCOMPARE(*result.declarations, base);
}

void TestDeclarations::addresses_data()
{
    QTest::addColumn<QString>("address");
    QTest::addColumn<bool>("valid");
    for (const char *good : {"%IX0.0", "%QW3", "%MD10", "%QB7", "%ix1.7", "%I*", "%IW2.1.0", "%QL4"})
        QTest::newRow(good) << QString::fromLatin1(good) << true;
    for (const char *bad : {"", "%", "IX0.0", "%IX", "%ZX0.0", "%QW3.", "%MD-1", "%IX0.0 "})
        QTest::newRow(bad) << QString::fromLatin1(bad) << false;
}

void TestDeclarations::addresses()
{
    QFETCH(QString, address);
    QFETCH(bool, valid);
    QCOMPARE(isValidAddress(address), valid);
}

void TestDeclarations::freeVariableNameSkipsTakenNames()
{
    QCOMPARE(freeVariableName({}, QStringLiteral("Var")), QStringLiteral("Var1"));
    QCOMPARE(freeVariableName({row(QStringLiteral("VAR1"), QStringLiteral("VAR"), QStringLiteral("INT")),
                                  row(QStringLiteral("Var2"), QStringLiteral("VAR"), QStringLiteral("INT"))},
                 QStringLiteral("Var")),
        QStringLiteral("Var3"));
}

// ---- the widget -------------------------------------------------------------------------------

void TestDeclarations::cellEditAppliesOneCommand_data()
{
    QTest::addColumn<int>("rowIndex");
    QTest::addColumn<DeclarationColumn>("column");
    QTest::addColumn<QString>("text");
    QTest::addColumn<Interface>("expected");

    Interface renamed = sample();
    renamed.varLists[1].variables[0].name = QStringLiteral("Counter");
    QTest::newRow("name") << 1 << DeclarationColumn::Name << QStringLiteral("Counter") << renamed;

    Interface typed = sample();
    typed.varLists[1].variables[0].type = {ElementaryType {QStringLiteral("DINT")}};
    QTest::newRow("type") << 1 << DeclarationColumn::Type << QStringLiteral("dint") << typed;

    Interface initial = sample();
    initial.varLists[1].variables[0].initialValue.reset();
    QTest::newRow("initial value cleared") << 1 << DeclarationColumn::InitialValue << QString() << initial;

    Interface located = sample();
    located.varLists[1].variables[1].address = QStringLiteral("%QX1.0");
    QTest::newRow("address") << 2 << DeclarationColumn::Address << QStringLiteral("%QX1.0") << located;

    Interface commented = sample();
    commented.varLists[0].variables[0].documentation = FormattedText {QStringLiteral("Green button"), {}};
    QTest::newRow("comment") << 0 << DeclarationColumn::Comment << QStringLiteral("Green button") << commented;

    // Count becomes an output: VAR splits around it no more, it is a list of its own.
    Interface moved = sample();
    moved.varLists.insert(moved.varLists.begin() + 1,
        varList(VarListKind::Output, {variable(QStringLiteral("Count"), QStringLiteral("INT"), QStringLiteral("5"))}));
    moved.varLists[2].variables.erase(moved.varLists[2].variables.begin());
    QTest::newRow("class") << 1 << DeclarationColumn::Class << QStringLiteral("VAR_OUTPUT") << moved;

    Interface retained = sample();
    retained.varLists[2].constant = false;
    retained.varLists[2].retain = true;
    QTest::newRow("flag") << 3 << DeclarationColumn::Class << QStringLiteral("VAR RETAIN") << retained;
}

void TestDeclarations::cellEditAppliesOneCommand()
{
    QFETCH(int, rowIndex);
    QFETCH(DeclarationColumn, column);
    QFETCH(QString, text);
    QFETCH(Interface, expected);
    DeclarationTableModel *table = m_editor->tableModel();
    QVERIFY(table->setData(table->index(rowIndex, int(column)), text));
    QCOMPARE(m_editor->problemText(), QString());
    checkRedoUndoRedo(sample(), expected);
    QCOMPARE(m_editor->textEditor()->toPlainText(), declarationText(expected));
}

void TestDeclarations::invalidCellIsMarkedAndNotApplied()
{
    DeclarationTableModel *table = m_editor->tableModel();
    const QModelIndex type = table->index(2, int(DeclarationColumn::Type));
    QVERIFY(table->setData(type, QStringLiteral("ARRAY[")));
    QCOMPARE(m_stack->count(), 0);
    QCOMPARE(modelInterface(), sample());
    QCOMPARE(table->data(type).toString(), QStringLiteral("ARRAY["));
    QVERIFY(table->data(type, Qt::BackgroundRole).isValid());
    QCOMPARE(table->data(type, Qt::ToolTipRole).toString(), QStringLiteral("\"ARRAY[\" is not a data type."));
    QCOMPARE(m_editor->problemText(), QStringLiteral("Row 3: \"ARRAY[\" is not a data type."));

    // Fixing the cell applies the whole table, and the mark goes.
    QVERIFY(table->setData(type, QStringLiteral("WORD")));
    Interface fixed = sample();
    fixed.varLists[1].variables[1].type = {ElementaryType {QStringLiteral("WORD")}};
    QCOMPARE(modelInterface(), fixed);
    QVERIFY(!table->data(type, Qt::BackgroundRole).isValid());
    QCOMPARE(m_editor->problemText(), QString());
    QCOMPARE(m_stack->count(), 1);
}

void TestDeclarations::rowGestures_data()
{
    QTest::addColumn<int>("current");
    QTest::addColumn<QString>("gesture");
    QTest::addColumn<Interface>("expected");
    QTest::addColumn<int>("selectedAfter");

    Interface added = sample();
    added.varLists[1].variables.insert(
        added.varLists[1].variables.begin() + 1, variable(QStringLiteral("Var1"), QStringLiteral("BOOL")));
    QTest::newRow("add after the current row, in its class") << 1 << QStringLiteral("add") << added << 2;

    Interface appended = sample();
    appended.varLists.push_back(
        varList(VarListKind::Local, {variable(QStringLiteral("Var1"), QStringLiteral("BOOL"))}));
    QTest::newRow("add without a current row") << -1 << QStringLiteral("add") << appended << 4;

    Interface removed = sample();
    removed.varLists.erase(removed.varLists.begin());
    QTest::newRow("remove the only input") << 0 << QStringLiteral("remove") << removed << 0;

    Interface swapped = sample();
    std::swap(swapped.varLists[1].variables[0], swapped.varLists[1].variables[1]);
    QTest::newRow("move down within a list") << 1 << QStringLiteral("down") << swapped << 2;
    QTest::newRow("move up within a list") << 2 << QStringLiteral("up") << swapped << 1;
}

void TestDeclarations::rowGestures()
{
    QFETCH(int, current);
    QFETCH(QString, gesture);
    QFETCH(Interface, expected);
    QFETCH(int, selectedAfter);
    if (current >= 0)
        m_editor->table()->setCurrentIndex(m_editor->tableModel()->index(current, 0));
    if (gesture == QLatin1String("add"))
        m_editor->addRow();
    else if (gesture == QLatin1String("remove"))
        m_editor->removeCurrentRow();
    else
        m_editor->moveCurrentRow(gesture == QLatin1String("up") ? -1 : 1);
    QCOMPARE(m_editor->table()->currentIndex().row(), selectedAfter);
    checkRedoUndoRedo(sample(), expected);
}

void TestDeclarations::textEditAppliesOnePauseAsOneCommand()
{
    m_editor->showText();
    CodeEditor *text = m_editor->textEditor();
    QString edited = kSampleText;
    edited.replace(QStringLiteral("Count : INT := 5;"), QStringLiteral("Count : INT := 7; (* steps *)"));
    typeText(*text, edited);
    QCOMPARE(modelInterface(), sample()); // not before the pause
    text->flushPendingEdit();
    Interface expected = sample();
    expected.varLists[1].variables[0].initialValue = Value {SimpleValue {QStringLiteral("7")}};
    expected.varLists[1].variables[0].documentation = FormattedText {QStringLiteral("steps"), {}};
    QCOMPARE(text->toPlainText(), edited); // the text as typed stays
    QCOMPARE(m_editor->tableModel()->rows()[1].comment, QStringLiteral("steps"));
    checkRedoUndoRedo(sample(), expected);
}

void TestDeclarations::invalidTextShowsALocatedError()
{
    CodeEditor *text = m_editor->textEditor();
    QString broken = kSampleText;
    broken.replace(QStringLiteral("Lamp AT %QX0.1 : BOOL;"), QStringLiteral("Lamp AT %QX0.1 : BOOL"));
    typeText(*text, broken);
    text->flushPendingEdit();
    QCOMPARE(modelInterface(), sample());
    QCOMPARE(m_stack->count(), 0);
    const QList<TextDiagnostic> diagnostics = text->diagnostics();
    QVERIFY(!diagnostics.isEmpty());
    QCOMPARE(diagnostics.front().line, 7);
    QCOMPARE(diagnostics.front().column, 25); // just past the line's end, the editor marks its last character
    QCOMPARE(m_editor->problemText(), QStringLiteral("Line 7, column 26: Missing ';' after the declaration of Lamp."));
    QCOMPARE(text->toPlainText(), broken); // the user's text is kept for fixing
}

void TestDeclarations::focusOutAppliesPendingText()
{
    m_editor->show();
    m_editor->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_editor.get()));
    m_editor->showText();
    CodeEditor *text = m_editor->textEditor();
    text->setFocus();
    QTRY_VERIFY(text->hasFocus());
    typeText(*text, QStringLiteral("VAR\n    Only : BOOL;\nEND_VAR\n"));
    QCOMPARE(m_stack->count(), 0);
    m_editor->showTable(); // the text is hidden and loses the focus
    m_editor->table()->setFocus();
    QTRY_COMPARE(m_stack->count(), 1);
    QCOMPARE(modelInterface(),
        interfaceOf({varList(VarListKind::Local, {variable(QStringLiteral("Only"), QStringLiteral("BOOL"))})}));
}

void TestDeclarations::modelChangeRefreshesBothViews()
{
    // A rename elsewhere (the model's own command), then its undo.
    m_stack->push(ChangeVariableCommand::rename(*m_model, m_pou, QStringLiteral("Lamp"), QStringLiteral("Light")));
    QCOMPARE(m_editor->tableModel()->rows()[2].name, QStringLiteral("Light"));
    QVERIFY(m_editor->textEditor()->toPlainText().contains(QStringLiteral("Light AT %QX0.1 : BOOL;")));
    m_stack->undo();
    QCOMPARE(m_editor->tableModel()->rows(), sampleRows());
    QCOMPARE(m_editor->textEditor()->toPlainText(), kSampleText);
    m_stack->push(new RemoveVariableCommand(*m_model, m_pou, QStringLiteral("Start")));
    QCOMPARE(m_editor->tableModel()->rowCount(), 3);
    QVERIFY(!m_editor->textEditor()->toPlainText().contains(QStringLiteral("Start")));
}

void TestDeclarations::ctrlZInTheTableUndoes()
{
    DeclarationTableModel *table = m_editor->tableModel();
    QVERIFY(table->setData(table->index(0, int(DeclarationColumn::Name)), QStringLiteral("Go")));
    QCOMPARE(m_stack->count(), 1);
    QTest::keySequence(m_editor->table(), QKeySequence::Undo);
    QCOMPARE(modelInterface(), sample());
    QTest::keySequence(m_editor->table(), QKeySequence::Redo);
    QCOMPARE(table->rows()[0].name, QStringLiteral("Go"));
}

QTEST_MAIN(TestDeclarations)
#include "tst_declarations.moc"
