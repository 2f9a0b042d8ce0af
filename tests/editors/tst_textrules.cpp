// The pure rules behind the ST/IL editors, as tables: bracket matching, Enter (auto-indent and
// block completion), closing-keyword re-indent, folding ranges, comment toggling, completion.
#include "editors/text/blockrules.h"
#include "editors/text/bracketmatcher.h"
#include "editors/text/commenttoggle.h"
#include "editors/text/completion.h"
#include "editors/text/foldingregions.h"
#include "editors/common/boxspec.h"
#include "editors/text/standardlibrary.h"
#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/compiler.h"
#include "model/project.h"

#include <QTest>

using namespace iec::editors;

Q_DECLARE_METATYPE(iec::editors::TextLanguage)
Q_DECLARE_METATYPE(QList<iec::editors::FoldRange>)

namespace {

class FakeProvider : public CompletionProvider
{
public:
    QList<CompletionItem> variables() const override
    {
        return {{QStringLiteral("Tank"), CompletionItem::Kind::Variable, QStringLiteral("TankCtl"), {}},
            {QStringLiteral("Temp"), CompletionItem::Kind::Variable, QStringLiteral("REAL"), {}},
            {QStringLiteral("Timer1"), CompletionItem::Kind::Variable, QStringLiteral("TON"), {}}};
    }
    QList<CompletionItem> members(const QString &path) const override
    {
        if (path == QLatin1String("Tank"))
            return {{QStringLiteral("Valve"), CompletionItem::Kind::Member, QStringLiteral("BOOL"), {}},
                {QStringLiteral("Level"), CompletionItem::Kind::Member, QStringLiteral("REAL"), {}}};
        return {};
    }
    QList<CompletionItem> pous() const override
    {
        return {{QStringLiteral("Main"), CompletionItem::Kind::Program, {}, {}},
            {QStringLiteral("Scale"), CompletionItem::Kind::Function, QStringLiteral("Scale(X: REAL) : REAL"), {}}};
    }
    QString typeOf(const QString &path) const override
    {
        return path == QLatin1String("Timer1") ? QStringLiteral("TON") : QString();
    }
};

QStringList texts(const QList<CompletionItem> &items)
{
    QStringList result;
    for (const CompletionItem &item : items)
        result.append(item.text);
    return result;
}

} // namespace

class TestTextRules : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void bracketMatching_data();
    void bracketMatching();
    void enterEdit_data();
    void enterEdit();
    void closingKeywordIndent_data();
    void closingKeywordIndent();
    void foldingRanges_data();
    void foldingRanges();
    void commentToggle_data();
    void commentToggle();
    void completionContext_data();
    void completionContext();
    void completionItems_data();
    void completionItems();
    void completionDetailsCarryParameters();
    void utilLibraryIsOffered_data();
    void utilLibraryIsOffered();
    void everyUtilBlockIsOffered();
    void ilOperatorsHaveTheirModifiers();
};

void TestTextRules::bracketMatching_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("position");
    QTest::addColumn<int>("commentDepth");
    QTest::addColumn<int>("expected");
    QTest::newRow("open") << "(a)" << 0 << 0 << 2;
    QTest::newRow("close") << "(a)" << 2 << 0 << 0;
    QTest::newRow("outer") << "((a))" << 0 << 0 << 4;
    QTest::newRow("inner") << "((a))" << 1 << 0 << 3;
    QTest::newRow("outer close") << "((a))" << 4 << 0 << 0;
    QTest::newRow("square") << "a[i](x)" << 1 << 0 << 3;
    QTest::newRow("round after square") << "a[i](x)" << 4 << 0 << 6;
    QTest::newRow("unclosed") << "(a" << 0 << 0 << -1;
    QTest::newRow("unopened") << "a)" << 1 << 0 << -1;
    QTest::newRow("not a bracket") << "x" << 0 << 0 << -2;
    QTest::newRow("out of range") << "()" << 5 << 0 << -2;
    QTest::newRow("kinds do not mix") << "(]" << 0 << 0 << -1;
    QTest::newRow("bracket in comment skipped") << "(a (* ) *) )" << 0 << 0 << 11;
    QTest::newRow("bracket in string skipped") << "f(')')" << 1 << 0 << 5;
    QTest::newRow("on a commented bracket") << "(a (* ) *) )" << 6 << 0 << -2;
    QTest::newRow("across lines") << "(\n a,\n b)" << 0 << 0 << 8;
    QTest::newRow("starting inside a comment: hidden") << "a ( *) (x)" << 2 << 1 << -2;
    QTest::newRow("starting inside a comment: real") << "a ( *) (x)" << 7 << 1 << 9;
}

void TestTextRules::bracketMatching()
{
    QFETCH(QString, text);
    QFETCH(int, position);
    QFETCH(int, commentDepth);
    QFETCH(int, expected);
    iec::interp::LexState state;
    state.commentDepth = commentDepth;
    QCOMPARE(matchingBracket(text, position, state), expected);
}

void TestTextRules::enterEdit_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("column"); // -1: end of line
    QTest::addColumn<QString>("following");
    QTest::addColumn<TextLanguage>("language");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("cursorOffset");
    QTest::addColumn<int>("removeAfter");
    const auto ST = TextLanguage::ST;
    const auto IL = TextLanguage::IL;
    QTest::newRow("plain keeps indent") << "    x := 1;" << -1 << "" << ST << "\n    " << 5 << 0;
    QTest::newRow("IF") << "IF x THEN" << -1 << "" << ST << "\n    \nEND_IF" << 5 << 0;
    QTest::newRow("IF indented") << "  IF x THEN" << -1 << "" << ST << "\n      \n  END_IF" << 7 << 0;
    QTest::newRow("IF lower case") << "if x then" << -1 << "" << ST << "\n    \nend_if" << 5 << 0;
    QTest::newRow("IF with comment") << "IF x THEN (* go *)" << -1 << "" << ST << "\n    \nEND_IF" << 5 << 0;
    QTest::newRow("IF trailing blanks") << "IF x THEN  " << 9 << "" << ST << "\n    \nEND_IF" << 5 << 2;
    QTest::newRow("IF already closed") << "IF x THEN" << -1 << "END_IF;\n" << ST << "\n    " << 5 << 0;
    QTest::newRow("IF with a body") << "IF x THEN" << -1 << "    y := 1;\nEND_IF" << ST << "\n    " << 5 << 0;
    QTest::newRow("IF before a statement") << "IF x THEN" << -1 << "\ny := 1;" << ST << "\n    \nEND_IF" << 5 << 0;
    QTest::newRow("IF mid-line") << "IF x THEN y" << 9 << "" << ST << "\n" << 1 << 0;
    QTest::newRow("ELSIF") << "ELSIF y THEN" << -1 << "" << ST << "\n    " << 5 << 0;
    QTest::newRow("ELSE") << "  ELSE" << -1 << "" << ST << "\n      " << 7 << 0;
    QTest::newRow("CASE") << "CASE n OF" << -1 << "" << ST << "\n    \nEND_CASE" << 5 << 0;
    QTest::newRow("CASE label") << "    1, 2:" << -1 << "" << ST << "\n        " << 9 << 0;
    QTest::newRow("FOR") << "FOR i := 1 TO 10 BY 2 DO" << -1 << "" << ST << "\n    \nEND_FOR" << 5 << 0;
    QTest::newRow("WHILE") << "WHILE a < 10 DO" << -1 << "" << ST << "\n    \nEND_WHILE" << 5 << 0;
    QTest::newRow("REPEAT") << "REPEAT" << -1 << "" << ST << "\n    \nUNTIL\nEND_REPEAT" << 5 << 0;
    QTest::newRow("VAR") << "VAR" << -1 << "" << ST << "\n    \nEND_VAR" << 5 << 0;
    QTest::newRow("VAR_INPUT RETAIN") << "VAR_INPUT RETAIN" << -1 << "" << ST << "\n    \nEND_VAR" << 5 << 0;
    QTest::newRow("VAR in IL") << "VAR_OUTPUT" << -1 << "" << IL << "\n    \nEND_VAR" << 5 << 0;
    QTest::newRow("PROGRAM") << "PROGRAM Main" << -1 << "" << ST << "\n\nEND_PROGRAM" << 1 << 0;
    QTest::newRow("PROGRAM closed later") << "PROGRAM Main" << -1 << "VAR\nEND_VAR\nEND_PROGRAM" << ST << "\n"
                                          << 1 << 0;
    QTest::newRow("FUNCTION_BLOCK") << "FUNCTION_BLOCK Fb1" << -1 << "" << ST << "\n\nEND_FUNCTION_BLOCK" << 1 << 0;
    QTest::newRow("FUNCTION") << "FUNCTION F : INT" << -1 << "" << ST << "\n\nEND_FUNCTION" << 1 << 0;
    QTest::newRow("METHOD") << "METHOD M : BOOL" << -1 << "" << ST << "\n\nEND_METHOD" << 1 << 0;
    QTest::newRow("ACTION") << "ACTION Reset:" << -1 << "" << ST << "\n\nEND_ACTION" << 1 << 0;
    QTest::newRow("TYPE") << "TYPE Colour :" << -1 << "" << ST << "\n\nEND_TYPE" << 1 << 0;
    QTest::newRow("TYPE STRUCT") << "TYPE Motor : STRUCT" << -1 << "" << ST << "\n    \nEND_STRUCT\nEND_TYPE" << 5 << 0;
    QTest::newRow("STRUCT") << "STRUCT" << -1 << "" << ST << "\n    \nEND_STRUCT" << 5 << 0;
    QTest::newRow("IF in IL is not a block") << "IF x THEN" << -1 << "" << IL << "\n" << 1 << 0;
    QTest::newRow("IL instruction") << "    LD x" << -1 << "" << IL << "\n    " << 5 << 0;
    QTest::newRow("IF in a comment") << "(* IF x THEN *)" << -1 << "" << ST << "\n" << 1 << 0;
}

void TestTextRules::enterEdit()
{
    QFETCH(QString, line);
    QFETCH(int, column);
    QFETCH(QString, following);
    QFETCH(TextLanguage, language);
    QFETCH(QString, text);
    QFETCH(int, cursorOffset);
    QFETCH(int, removeAfter);
    const EnterEdit edit = iec::editors::enterEdit(line, column < 0 ? int(line.size()) : column, following, language);
    QCOMPARE(edit.text, text);
    QCOMPARE(edit.cursorOffset, cursorOffset);
    QCOMPARE(edit.removeAfter, removeAfter);
}

void TestTextRules::closingKeywordIndent_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("previous");
    QTest::addColumn<TextLanguage>("language");
    QTest::addColumn<int>("expected");
    const auto ST = TextLanguage::ST;
    QTest::newRow("END_IF after body") << "    END_IF;"
                                       << "    x := 1;" << ST << 0;
    QTest::newRow("END_IF right after IF") << "    END_IF"
                                           << "IF a THEN" << ST << 0;
    QTest::newRow("ELSE after body") << "        ELSE"
                                     << "        y;" << ST << 4;
    QTest::newRow("ELSIF") << "    ELSIF b THEN"
                           << "    c := 2;" << ST << 0;
    QTest::newRow("UNTIL") << "    UNTIL i > 3"
                           << "    i := i + 1;" << ST << 0;
    QTest::newRow("END_VAR") << "    END_VAR"
                             << "    x : INT;" << ST << 0;
    QTest::newRow("already left") << "END_IF"
                                  << "    x := 1;" << ST << -1;
    QTest::newRow("not a closer") << "    x := 1;"
                                  << "    y := 1;" << ST << -1;
    QTest::newRow("END_IF in IL") << "    END_IF"
                                  << "    LD x" << TextLanguage::IL << -1;
    QTest::newRow("END_VAR in IL") << "    END_VAR"
                                   << "    x : BOOL;" << TextLanguage::IL << 0;
}

void TestTextRules::closingKeywordIndent()
{
    QFETCH(QString, line);
    QFETCH(QString, previous);
    QFETCH(TextLanguage, language);
    QFETCH(int, expected);
    QCOMPARE(iec::editors::closingKeywordIndent(line, previous, language), expected);
}

void TestTextRules::foldingRanges_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<TextLanguage>("language");
    QTest::addColumn<QList<FoldRange>>("expected");
    const auto ST = TextLanguage::ST;
    using L = QList<FoldRange>;
    QTest::newRow("IF") << "IF a THEN\n  b := 1;\nEND_IF" << ST << L {{0, 2}};
    QTest::newRow("nested") << "IF a THEN\n  IF b THEN\n    c := 1;\n  END_IF\nEND_IF" << ST << L {{0, 4}, {1, 3}};
    QTest::newRow("one line") << "IF a THEN b := 1; END_IF" << ST << L {};
    QTest::newRow("VAR") << "VAR\n  x : INT;\nEND_VAR" << ST << L {{0, 2}};
    QTest::newRow("comment") << "(* one\n   two *)\nx := 1;" << ST << L {{0, 1}};
    QTest::newRow("nested comment") << "(* a (* b *)\n c *)" << ST << L {{0, 1}};
    QTest::newRow("keywords in comment") << "(* IF *)\nx := 1;\n(* END_IF *)" << ST << L {};
    QTest::newRow("keyword in string") << "IF a THEN\n s := 'END_IF';\nEND_IF" << ST << L {{0, 2}};
    QTest::newRow("unclosed") << "IF a THEN\n b := 1;" << ST << L {};
    QTest::newRow("lower case") << "if a then\n b := 1;\nend_if" << ST << L {{0, 2}};
    QTest::newRow("program") << "PROGRAM P\nVAR\n x : INT;\nEND_VAR\nx := 1;\nEND_PROGRAM" << ST << L {{0, 5}, {1, 3}};
    QTest::newRow("loops") << "FOR i := 1 TO 2 DO\n  WHILE a DO\n  a := FALSE;\n  END_WHILE\nEND_FOR\nREPEAT\n "
                              "i := 1;\nUNTIL TRUE\nEND_REPEAT\nCASE i OF\n 1: a := TRUE;\nEND_CASE"
                           << ST << L {{0, 4}, {1, 3}, {5, 8}, {9, 11}};
    QTest::newRow("type") << "TYPE T :\nSTRUCT\n a : INT;\nEND_STRUCT\nEND_TYPE" << ST << L {{0, 4}, {1, 3}};
    QTest::newRow("a missing END_IF inside a FOR")
        << "FOR i := 1 TO 2 DO\n IF a THEN\n b := 1;\nEND_FOR" << ST << L {{0, 3}};
    QTest::newRow("IL body") << "VAR\n x : BOOL;\nEND_VAR\nLD x\nST y" << TextLanguage::IL << L {{0, 2}};
    QTest::newRow("IF in IL is no block") << "IF a THEN\n b;\nEND_IF" << TextLanguage::IL << L {};
}

void TestTextRules::foldingRanges()
{
    QFETCH(QString, text);
    QFETCH(TextLanguage, language);
    QFETCH(QList<FoldRange>, expected);
    const QList<FoldRange> actual = iec::editors::foldingRanges(text, language);
    QCOMPARE(actual.size(), expected.size());
    for (int i = 0; i < actual.size(); ++i) {
        QCOMPARE(actual[i].firstLine, expected[i].firstLine);
        QCOMPARE(actual[i].lastLine, expected[i].lastLine);
    }
}

void TestTextRules::commentToggle_data()
{
    QTest::addColumn<QStringList>("lines");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("comment") << QStringList {"x := 1;"} << QStringList {"(* x := 1; *)"};
    QTest::newRow("keeps indentation") << QStringList {"    x := 1;  "} << QStringList {"    (* x := 1; *)"};
    QTest::newRow("uncomment") << QStringList {"(* x := 1; *)"} << QStringList {"x := 1;"};
    QTest::newRow("uncomment indented") << QStringList {"  (* x := 1; *)"} << QStringList {"  x := 1;"};
    QTest::newRow("uncomment tight") << QStringList {"(*x;*)"} << QStringList {"x;"};
    QTest::newRow("mixed comments all") << QStringList {"(* a; *)", "b;"} << QStringList {"(* (* a; *) *)", "(* b; *)"};
    QTest::newRow("blank lines stay") << QStringList {"a;", "", "  b;"} << QStringList {"(* a; *)", "", "  (* b; *)"};
    QTest::newRow("uncomment with blank") << QStringList {"(* a; *)", "", "(* b; *)"} << QStringList {"a;", "", "b;"};
    QTest::newRow("only blank") << QStringList {"", "  "} << QStringList {"", "  "};
    QTest::newRow("trailing comment is not whole-line")
        << QStringList {"x; (* c *)"} << QStringList {"(* x; (* c *) *)"};
}

void TestTextRules::commentToggle()
{
    QFETCH(QStringList, lines);
    QFETCH(QStringList, expected);
    QCOMPARE(toggleLineComments(lines), expected);
}

void TestTextRules::completionContext_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("prefix");
    QTest::addColumn<QString>("path");
    QTest::addColumn<int>("start");
    QTest::newRow("word") << "x := Ta" << 7 << "Ta"
                          << "" << 5;
    QTest::newRow("member") << "Tank.Le" << 7 << "Le"
                            << "Tank" << 5;
    QTest::newRow("after dot") << "Main.Tank." << 10 << ""
                               << "Main.Tank" << 10;
    QTest::newRow("index") << "a[i+1].Q" << 8 << "Q"
                           << "a[i+1]" << 7;
    QTest::newRow("mid word") << "Level" << 2 << "Le"
                              << "" << 0;
    QTest::newRow("empty") << "" << 0 << ""
                           << "" << 0;
    QTest::newRow("after operator") << "x := " << 5 << ""
                                    << "" << 5;
}

void TestTextRules::completionContext()
{
    QFETCH(QString, line);
    QFETCH(int, column);
    QFETCH(QString, prefix);
    QFETCH(QString, path);
    QFETCH(int, start);
    const CompletionContext context = iec::editors::completionContext(line, column);
    QCOMPARE(context.prefix, prefix);
    QCOMPARE(context.memberPath, path);
    QCOMPARE(context.prefixStart, start);
}

void TestTextRules::completionItems_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<TextLanguage>("language");
    QTest::addColumn<QStringList>("expected");
    const auto ST = TextLanguage::ST;
    QTest::newRow("variable") << "x := Te" << ST << QStringList {"Temp"};
    QTest::newRow("variable and function") << "Ta" << ST << QStringList {"TAN", "Tank"};
    QTest::newRow("standard and Util functions") << "LIM" << ST << QStringList {"LIMIT", "LIMITALARM"};
    QTest::newRow("standard FB and variable") << "TO" << ST << QStringList {"TO", "TOD"} + [] {
        QStringList conversions;
        for (const char *to : {"BOOL", "BYTE", "DATE", "DINT", "DT", "DWORD", "INT", "LREAL", "REAL", "SINT", "STRING",
                 "TIME", "UDINT", "UINT", "USINT", "WORD"})
            conversions.append(QLatin1String("TOD_TO_") + QLatin1String(to));
        return conversions;
    }() + QStringList {"TOF", "TON"};
    QTest::newRow("POU") << "Sc" << ST << QStringList {"Scale"};
    QTest::newRow("program") << "Mai" << ST << QStringList {"Main"};
    QTest::newRow("keyword") << "END_W" << ST << QStringList {"END_WHILE"};
    QTest::newRow("members") << "Tank." << ST << QStringList {"Level", "Valve"};
    QTest::newRow("members with prefix") << "Tank.v" << ST << QStringList {"Valve"};
    QTest::newRow("standard FB members") << "Timer1." << ST << QStringList {"ET", "IN", "PT", "Q"};
    QTest::newRow("unknown member path") << "Nothing." << ST << QStringList {};
    QTest::newRow("IL operators") << "JMP" << TextLanguage::IL << QStringList {"JMP", "JMPC", "JMPCN"};
    QTest::newRow("no IL operators in ST") << "JMP" << ST << QStringList {};
    QTest::newRow("IL keeps variables") << "Timer" << TextLanguage::IL << QStringList {"Timer1"};
    QTest::newRow("IL types") << "TIME_O" << TextLanguage::IL << QStringList {"TIME_OF_DAY"};
}

void TestTextRules::completionItems()
{
    QFETCH(QString, line);
    QFETCH(TextLanguage, language);
    QFETCH(QStringList, expected);
    FakeProvider provider;
    const CompletionContext context = iec::editors::completionContext(line, int(line.size()));
    QCOMPARE(texts(iec::editors::completionItems(context, &provider, language)), expected);
}

void TestTextRules::completionDetailsCarryParameters()
{
    const QList<CompletionItem> items
        = iec::editors::completionItems({QStringLiteral("LIMIT"), {}, 0}, nullptr, TextLanguage::ST);
    QCOMPARE(items.size(), 2);
    QCOMPARE(items[0].kind, CompletionItem::Kind::Function);
    QCOMPARE(items[0].detail, QStringLiteral("LIMIT(MN: ANY, IN: ANY, MX: ANY) : ANY"));
    QCOMPARE(items[1].kind, CompletionItem::Kind::FunctionBlock);
    QCOMPARE(items[1].detail, QStringLiteral("LIMITALARM(IN: INT, HIGH: INT, LOW: INT) => O: BOOL, U: BOOL, IL: BOOL"));
    const StdPou *ton = findStandardPou(u"ton");
    QVERIFY(ton);
    QCOMPARE(ton->signature(), QStringLiteral("TON(IN: BOOL, PT: TIME) => Q: BOOL, ET: TIME"));
}

void TestTextRules::utilLibraryIsOffered_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("signature");
    QTest::addColumn<QString>("library");
    QTest::addColumn<QString>("category");
    QTest::addColumn<QStringList>("boxInputs");
    QTest::addColumn<QStringList>("boxOutputs");
    QTest::newRow("BLINK") << "blink" << "BLINK(ENABLE: BOOL, TIMELOW: TIME, TIMEHIGH: TIME) => OUT: BOOL" << "Util"
                           << "Signal generators" << QStringList {"ENABLE", "TIMELOW", "TIMEHIGH"} << QStringList {"OUT"};
    QTest::newRow("CHARCURVE") << "CHARCURVE"
                               << "CHARCURVE(IN: INT, N: BYTE, P: ARRAY[0..10] OF POINT) => OUT: INT, ERR: BYTE" << "Util"
                               << "Function manipulators" << QStringList {"IN", "N", "P"} << QStringList {"OUT", "ERR"};
    QTest::newRow("PID_FIXCYCLE") << "PID_FIXCYCLE"
                                  << "PID_FIXCYCLE(ACTUAL: REAL, SET_POINT: REAL, KP: REAL, TN: REAL, TV: REAL, Y_MANUAL: "
                                     "REAL, Y_OFFSET: REAL, Y_MIN: REAL, Y_MAX: REAL, MANUAL: BOOL, RESET: BOOL, CYCLE: "
                                     "REAL) => Y: REAL, LIMITS_ACTIVE: BOOL, OVERFLOW: BOOL"
                                  << "Util" << "Controllers"
                                  << QStringList {"ACTUAL", "SET_POINT", "KP", "TN", "TV", "Y_MANUAL", "Y_OFFSET", "Y_MIN",
                                         "Y_MAX", "MANUAL", "RESET", "CYCLE"}
                                  << QStringList {"Y", "LIMITS_ACTIVE", "OVERFLOW"};
    QTest::newRow("EXTRACT") << "EXTRACT" << "EXTRACT(X: DWORD, N: BYTE) : BOOL" << "Util" << "Bit and byte functions"
                             << QStringList {"X", "N"} << QStringList {"OUT"};
    QTest::newRow("BCD_TO_INT") << "BCD_TO_INT" << "BCD_TO_INT(B: BYTE) : INT" << "Util" << "BCD conversion"
                                << QStringList {"B"} << QStringList {"OUT"};
    QTest::newRow("RTC") << "RTC" << "RTC(IN: BOOL, PDT: DT) => Q: BOOL, CDT: DT" << "Beremiz" << "Timers"
                         << QStringList {"IN", "PDT"} << QStringList {"Q", "CDT"};
    QTest::newRow("LOGGER") << "LOGGER" << "LOGGER(TRIG: BOOL, MSG: STRING, LEVEL: LOGLEVEL)" << "Beremiz" << "Messages"
                            << QStringList {"TRIG", "MSG", "LEVEL"} << QStringList {};
}

// The Util library's blocks are offered with the pins the compiler defines (library pane, F2,
// completion, and the box a diagram editor inserts).
void TestTextRules::utilLibraryIsOffered()
{
    QFETCH(QString, name);
    QFETCH(QString, signature);
    QFETCH(QString, library);
    QFETCH(QString, category);
    QFETCH(QStringList, boxInputs);
    QFETCH(QStringList, boxOutputs);
    const StdPou *pou = findStandardPou(name);
    QVERIFY(pou);
    QCOMPARE(pou->signature(), signature);
    QCOMPARE(pou->library, library);
    QCOMPARE(stdCategoryName(pou->category), category);
    QVERIFY(!pou->translatedDescription().isEmpty());
    const std::optional<BoxSpec> box = boxSpecFor(iec::model::Project {}, name, true, nullptr);
    QVERIFY(box);
    QCOMPARE(box->inputs, boxInputs);
    QCOMPARE(box->outputs, boxOutputs);
}

void TestTextRules::everyUtilBlockIsOffered()
{
    for (const iec::interp::ast::Pou &pou : iec::interp::utilLibrary().pous) {
        const StdPou *offered = findStandardPou(pou.name);
        QVERIFY2(offered && offered->library != QLatin1String("Standard"), qPrintable(pou.name));
    }
}

void TestTextRules::ilOperatorsHaveTheirModifiers()
{
    QStringList names;
    for (const IlOperator &op : ilOperators())
        names.append(op.text);
    const QStringList expected = {"LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN", "AND(", "ANDN(", "OR", "ORN",
        "OR(", "ORN(", "XOR", "XORN", "XOR(", "XORN(", "ADD", "ADD(", "SUB", "SUB(", "MUL", "MUL(", "DIV", "DIV(", "GT",
        "GT(", "GE", "GE(", "EQ", "EQ(", "NE", "NE(", "LE", "LE(", "LT", "LT(", "JMP", "JMPC", "JMPCN", "CAL", "CALC",
        "CALCN", "RET", "RETC", "RETCN", ")"};
    QCOMPARE(names, expected);
}

QTEST_GUILESS_MAIN(TestTextRules)
#include "tst_textrules.moc"
