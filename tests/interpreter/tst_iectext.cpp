// IEC text <-> project model (interpreter/frontend/iecreader.h, iecprinter.h): what a .st file
// becomes in the model, how the model prints, and that printing is stable after one round.
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/frontend/sourcefile.h"
#include "interpreter/runtime/runtime.h"

#include "model/plcopen/reader.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;

class TestIecText : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void printsWhatItRead_data();
    void printsWhatItRead();
    void readsIntoModelValues();
    void keepsBodiesVerbatim();
    void printsTheFirstStepsExample();
    void globalListNamesAndChartsSurviveText();
    void graphicalBodiesBecomeAComment();
    void reportsParseErrorsWithFileLines();
    void refusesCharactersAFileCannotKeep();
    void sourceFilesAreUtf8OrWindows1252_data();
    void sourceFilesAreUtf8OrWindows1252();
    void textAndModelRunAlike();
};

namespace {

QString errors(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

QString roundTrip(const QString &text)
{
    const frontend::TextReadResult read = frontend::readIecText(text, QStringLiteral("p"));
    if (!read.diagnostics.all().empty())
        return errors(read.diagnostics);
    return frontend::printProject(read.project);
}

} // namespace

void TestIecText::printsWhatItRead_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("printed");

    QTest::newRow("struct, enum, array, subrange, string")
        << QStringLiteral("TYPE P : STRUCT x : INT := 1; y : REAL; END_STRUCT; END_TYPE\n"
                          "TYPE C : (Red, Green := 5) INT := Green; END_TYPE\n"
                          "TYPE A : ARRAY[1..2, 0..N] OF P; S : UINT (0..10); N8 : STRING[8] := 'x'; END_TYPE\n")
        << QStringLiteral(
               "TYPE\n    P : STRUCT\n        x : INT := 1;\n        y : REAL;\n    END_STRUCT;\nEND_TYPE\n\n"
               "TYPE\n    C : (Red, Green := 5) INT := Green;\nEND_TYPE\n\n"
               "TYPE\n    A : ARRAY[1..2, 0..N] OF P;\nEND_TYPE\n\n"
               "TYPE\n    S : UINT (0..10);\nEND_TYPE\n\n"
               "TYPE\n    N8 : STRING[8] := 'x';\nEND_TYPE\n");
    QTest::newRow("function with sections, flags, AT and initial values")
        << QStringLiteral(
               "FUNCTION F : DINT\nVAR_INPUT a, b : INT := -1; END_VAR\nVAR CONSTANT K : INT := 2 * 3; END_VAR\n"
               "VAR RETAIN q AT %QX0.1 : BOOL; arr : ARRAY[0..3] OF INT := [2(1), 3, 4]; s : P := (x := 2); END_VAR\n"
               "F := a + b;\nEND_FUNCTION\n")
        << QStringLiteral("FUNCTION F : DINT\nVAR_INPUT\n    a : INT := -1;\n    b : INT := -1;\nEND_VAR\n"
                          "VAR CONSTANT\n    K : INT := 2 * 3;\nEND_VAR\n"
                          "VAR RETAIN\n    q AT %QX0.1 : BOOL;\n    arr : ARRAY[0..3] OF INT := [2(1), 3, 4];\n    s : "
                          "P := (x := 2);\nEND_VAR\n"
                          "F := a + b;\nEND_FUNCTION\n");
    // The action's chart is read into a graphical SFC body and printed back as textual SFC.
    QTest::newRow("chart in an action")
        << QStringLiteral("PROGRAM Main\nSeq();\nACTION Seq:\nINITIAL_STEP A: Beep(N); END_STEP\n"
                          "TRANSITION FROM A TO B := TRUE; END_TRANSITION\nSTEP B: END_STEP\nTRANSITION FROM B TO A := TRUE; END_TRANSITION\n"
                          "END_ACTION\nACTION Beep:\n;\nEND_ACTION\nEND_PROGRAM\n")
        << QStringLiteral("PROGRAM Main\nSeq();\nACTION Seq:\nINITIAL_STEP A:\n    Beep(N);\nEND_STEP\nSTEP B:\nEND_STEP\n"
                          "TRANSITION FROM A TO B := TRUE; END_TRANSITION\nTRANSITION FROM B TO A := TRUE; END_TRANSITION\n"
                          "END_ACTION\nACTION Beep:\n;\nEND_ACTION\nEND_PROGRAM\n");
    QTest::newRow("chart in an action of a chart")
        << QStringLiteral("PROGRAM Main\nINITIAL_STEP Run: Inner(N); END_STEP\nTRANSITION FROM Run TO Run2 := TRUE; END_TRANSITION\n"
                          "STEP Run2: END_STEP\nTRANSITION FROM Run2 TO Run := TRUE; END_TRANSITION\n"
                          "ACTION Inner:\nINITIAL_STEP A: END_STEP\nTRANSITION FROM A TO B := TRUE; END_TRANSITION\nSTEP B: END_STEP\n"
                          "TRANSITION FROM B TO A := TRUE; END_TRANSITION\nEND_ACTION\nEND_PROGRAM\n")
        << QStringLiteral("PROGRAM Main\nINITIAL_STEP Run:\n    Inner(N);\nEND_STEP\nSTEP Run2:\nEND_STEP\n"
                          "TRANSITION FROM Run TO Run2 := TRUE; END_TRANSITION\nTRANSITION FROM Run2 TO Run := TRUE; END_TRANSITION\n"
                          "ACTION Inner:\nINITIAL_STEP A:\nEND_STEP\nSTEP B:\nEND_STEP\n"
                          "TRANSITION FROM A TO B := TRUE; END_TRANSITION\nTRANSITION FROM B TO A := TRUE; END_TRANSITION\n"
                          "END_ACTION\nEND_PROGRAM\n");
    QTest::newRow("configuration with tasks and instances")
        << QStringLiteral(
               "PROGRAM Main\nEND_PROGRAM\nCONFIGURATION Cfg\nVAR_GLOBAL g : INT; END_VAR\nRESOURCE R ON PLC\n"
               "TASK T1(INTERVAL := T#20ms, PRIORITY := 3);\nPROGRAM M1 WITH T1 : Main;\nPROGRAM M2 : Main;\n"
               "END_RESOURCE\nEND_CONFIGURATION\n")
        << QStringLiteral(
               "PROGRAM Main\nEND_PROGRAM\n\nCONFIGURATION Cfg\n    VAR_GLOBAL\n        g : INT;\n    END_VAR\n"
               "    RESOURCE R ON PLC\n        TASK T1(INTERVAL := T#20ms, PRIORITY := 3);\n"
               "        PROGRAM M1 WITH T1 : Main;\n        PROGRAM M2 : Main;\n    END_RESOURCE\nEND_CONFIGURATION\n");
}

void TestIecText::printsWhatItRead()
{
    QFETCH(QString, input);
    QFETCH(QString, printed);
    QCOMPARE(roundTrip(input), printed);
    QCOMPARE(roundTrip(printed), printed); // stable after one round
}

void TestIecText::readsIntoModelValues()
{
    const auto read
        = frontend::readIecText(u"FUNCTION_BLOCK Fb\nVAR_IN_OUT io : WSTRING; END_VAR\nVAR_OUTPUT NON_RETAIN o : "
                                u"ARRAY[1..2] OF BOOL := [TRUE, FALSE]; END_VAR\nEND_FUNCTION_BLOCK\n",
            QStringLiteral("proj"));
    QCOMPARE(errors(read.diagnostics), QString());
    QCOMPARE(read.project.contentHeader.name, QStringLiteral("proj"));
    QCOMPARE(read.project.types.pous.size(), size_t(1));
    const model::Pou &fb = read.project.types.pous.front();
    QCOMPARE(fb.kind, model::PouKind::FunctionBlock);
    const auto &lists = fb.pouInterface->varLists;
    QCOMPARE(lists.size(), size_t(2));
    QCOMPARE(lists[0].kind, model::VarListKind::InOut);
    QCOMPARE(lists[0].variables.front().type, (model::DataType {model::StringType {true, std::nullopt}}));
    QCOMPARE(lists[1].kind, model::VarListKind::Output);
    QVERIFY(lists[1].nonretain);
    const model::Variable &o = lists[1].variables.front();
    const auto *array = std::get_if<model::ArrayType>(&o.type.kind);
    QVERIFY(array);
    QCOMPARE(array->dimensions, (std::vector<model::Range> {{QStringLiteral("1"), QStringLiteral("2")}}));
    QCOMPARE(*array->baseType, (model::DataType {model::ElementaryType {QStringLiteral("BOOL")}}));
    const auto *items = std::get_if<model::ArrayValue>(&o.initialValue->kind);
    QVERIFY(items);
    QCOMPARE(items->values.size(), size_t(2));
    QCOMPARE(*items->values[1].value, (model::Value {model::SimpleValue {QStringLiteral("FALSE")}}));
}

void TestIecText::keepsBodiesVerbatim()
{
    const QString body = QStringLiteral("(* keep me *)\nIF x THEN\n    x := FALSE; // and me\nEND_IF;");
    const auto read = frontend::readIecText(
        QStringLiteral(
            "PROGRAM Main\nVAR x : BOOL; END_VAR\n%1\n\nACTION Reset:\nx := FALSE;\nEND_ACTION\nEND_PROGRAM\n")
            .arg(body),
        QStringLiteral("p"));
    QCOMPARE(errors(read.diagnostics), QString());
    const model::Pou &main = read.project.types.pous.front();
    QCOMPARE(main.body()->language(), model::BodyLanguage::ST);
    QCOMPARE(main.body()->text(), body);
    QCOMPARE(main.actions.size(), size_t(1));
    QCOMPARE(main.actions.front().name, QStringLiteral("Reset"));
    QCOMPARE(main.actions.front().body.text(), QStringLiteral("x := FALSE;"));

    const auto il
        = frontend::readIecText(u"FUNCTION_BLOCK F\nVAR n : INT; END_VAR\nLD n\nADD 1\nST n\nEND_FUNCTION_BLOCK\n", {});
    QCOMPARE(il.project.types.pous.front().body()->language(), model::BodyLanguage::IL);
    QCOMPARE(il.project.types.pous.front().body()->text(), QStringLiteral("LD n\nADD 1\nST n"));
}

void TestIecText::printsTheFirstStepsExample()
{
    const auto read
        = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml"));
    QVERIFY(read.ok);
    QCOMPARE(frontend::printProject(read.project),
        QStringLiteral("PROGRAM Main\nVAR\n    Pulse : TON;\n    Blink : BOOL;\n    Count : INT := 0;\nEND_VAR\n"
                       "(* A lamp that blinks at 1 Hz and counts its flashes. *)\n"
                       "Pulse(IN := NOT Pulse.Q, PT := T#500ms);\nIF Pulse.Q THEN\n    Blink := NOT Blink;\n"
                       "    IF Blink THEN\n        Count := Count + 1;\n    END_IF;\nEND_IF;\nEND_PROGRAM\n\n"
                       "CONFIGURATION Config\n    RESOURCE Resource ON PLC\n        TASK MainTask(INTERVAL := T#10ms, "
                       "PRIORITY := 1);\n"
                       "        PROGRAM Main WITH MainTask : Main;\n    END_RESOURCE\nEND_CONFIGURATION\n"));
}

// iecstudio-cli convert: .xml -> .st -> .xml keeps a CODESYS global list's name (the comment
// CODESYS V2.3 writes before it) and a chart (textual SFC).
void TestIecText::globalListNamesAndChartsSurviveText()
{
    const auto read
        = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml"));
    QVERIFY(read.ok);
    model::Project project = read.project;
    model::VarList io;
    io.kind = model::VarListKind::Global;
    io.name = QStringLiteral("IO");
    io.variables.push_back({.name = QStringLiteral("Valve")});
    project.instances.configurations.at(0).resources.at(0).globalVars.push_back(io);
    const QString text = frontend::printProject(project);
    QVERIFY(text.contains(QStringLiteral("(* @GLOBAL_VARIABLE_LIST := IO *)\n        VAR_GLOBAL\n")));

    const frontend::TextReadResult back = frontend::readIecText(text, QStringLiteral("p"));
    const std::vector<model::VarList> &lists = back.project.instances.configurations.at(0).resources.at(0).globalVars;
    QCOMPARE(lists.back().name, std::optional(QStringLiteral("IO")));
    const model::Pou *chart = back.project.findPou(QStringLiteral("Main"));
    QVERIFY(chart && chart->body());
    QCOMPARE(chart->body()->language(), model::BodyLanguage::SFC);
    const auto countSteps = [](const model::Pou &pou) {
        return std::ranges::count_if(*pou.body()->elements(),
            [](const model::Element &e) { return std::holds_alternative<model::Step>(e); });
    };
    QCOMPARE(countSteps(*chart), countSteps(*project.findPou(QStringLiteral("Main"))));
    QCOMPARE(frontend::printProject(back.project), text);
}

void TestIecText::graphicalBodiesBecomeAComment()
{
    model::Pou chart;
    chart.name = QStringLiteral("Chart");
    chart.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::SFC));
    std::vector<frontend::PrintWarning> warnings;
    QCOMPARE(frontend::printPou(chart, &warnings),
        QStringLiteral(
            "PROGRAM Chart\n(* The SFC body of Chart has no IEC text form and was left out. *)\nEND_PROGRAM\n"));
    QCOMPARE(warnings.size(), size_t(1));
    QCOMPARE(warnings.front().pou, QStringLiteral("Chart"));
    QCOMPARE(warnings.front().message,
        QStringLiteral("The chart of Chart cannot be written as textual SFC (it is incomplete, or has macro steps, actions written "
                       "in a step or conditions drawn as networks); it was left out."));
}

void TestIecText::reportsParseErrorsWithFileLines()
{
    const auto read = frontend::readIecText(u"PROGRAM Main\nVAR x : INT END_VAR\nEND_PROGRAM\n", {});
    QVERIFY(read.diagnostics.hasErrors());
    QCOMPARE(read.diagnostics.all().front().location.line, 2);
}

void TestIecText::refusesCharactersAFileCannotKeep()
{
    // Found by fuzz_iectext: a NUL in a comment was kept in the body and cut it short in XML.
    const QString text = QStringLiteral("PROGRAM Main\n(* a\tb \x01 *) x := 1;\nEND_PROGRAM\n");
    const auto read = frontend::readIecText(text, {});
    QVERIFY(read.diagnostics.hasErrors());
    const Diagnostic &error = read.diagnostics.all().front();
    QCOMPARE(error.location.line, 2);
    QCOMPARE(error.location.column, 8); // the tab before it counts as one character
    QCOMPARE(error.message,
        QStringLiteral("The text holds the control character U+0001, which a project file cannot keep; remove it."));
}

void TestIecText::textAndModelRunAlike()
{
    const QString source = QStringLiteral("PROGRAM Main\nVAR t : TON; n : INT; END_VAR\nt(IN := TRUE, PT := T#30ms);\n"
                                          "IF t.Q THEN n := n + 1; END_IF;\nEND_PROGRAM\n");
    const auto read = frontend::readIecText(source, {});
    QCOMPARE(errors(read.diagnostics), QString());
    Diagnostics fromModel, fromText;
    const auto viaModel = frontend::compileProject(read.project, fromModel);
    const auto viaText = compileText(source, fromText);
    QVERIFY(viaModel && viaText);
    Runtime a(viaModel), b(viaText);
    QStringList traceA, traceB;
    for (int cycle = 0; cycle < 6; ++cycle) {
        QVERIFY(a.runCycle() && b.runCycle());
        traceA << a.read(QStringLiteral("Main.n")).value();
        traceB << b.read(QStringLiteral("Main.n")).value();
    }
    QCOMPARE(traceA,
        (QStringList {QStringLiteral("0"), QStringLiteral("0"), QStringLiteral("0"), QStringLiteral("1"),
            QStringLiteral("2"), QStringLiteral("3")}));
    QCOMPARE(traceB, traceA);
}

// A CoDeSys 2.3 export is in Windows-1252: read as UTF-8, its umlauts would be lost.
void TestIecText::sourceFilesAreUtf8OrWindows1252_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("windows1252Line");
    QTest::newRow("utf-8") << QByteArray("x := 'St\xC3\xB6rung \xE2\x82\xAC';") << QStringLiteral("x := 'Störung €';") << 0;
    QTest::newRow("utf-8 with a byte order mark") << QByteArray("\xEF\xBB\xBFx := 1;") << QStringLiteral("x := 1;") << 0;
    QTest::newRow("windows-1252") << QByteArray("(* ok *)\nx := 'St\xF6rung \x80';\n(* \x93quoted\x94 *)")
                                  << QStringLiteral("(* ok *)\nx := 'Störung €';\n(* \u201Cquoted\u201D *)") << 2;
    QTest::newRow("bytes windows-1252 leaves undefined") << QByteArray("\x81\x8D") << QStringLiteral("\u0081\u008D") << 1;
    QTest::newRow("empty") << QByteArray() << QString() << 0;
    QTest::newRow("utf-16 with its byte order mark") << QByteArray("\xFF\xFEx\0 \0:\0=\0 \0'\0\xD6\0'\0;\0", 20)
                                                     << QStringLiteral("x := 'Ö';") << 0;
    QTest::newRow("line ends and export markers")
        << QByteArray("(* @NESTEDCOMMENTS := 'Yes' *)\r\nPROGRAM P\r\nVAR x : INT; END_VAR\r\n  (* @END_DECLARATION := '0' *)\r\n"
                      "x := 1; (* @KEPT := 'inline' *)\rEND_PROGRAM")
        << QStringLiteral("\nPROGRAM P\nVAR x : INT; END_VAR\n\nx := 1; (* @KEPT := 'inline' *)\nEND_PROGRAM") << 0;
    // A body in CoDeSys 2.3's graphical export form becomes a comment under an {error} pragma, up to
    // the end of its POU; a name that only starts like an end (END_X) does not end it.
    const QString notRead = QStringLiteral("{error 'CoDeSys 2.3 exported this %1 body in its own graphical form, which IEC "
                                           "Studio does not read; it is kept below as a comment. Export the POU from "
                                           "CoDeSys as PLCopen XML to open it as a diagram.'} // _%1_BODY");
    QTest::newRow("graphical bodies")
        << QByteArray("PROGRAM L\r\nVAR x : BOOL; END_VAR\r\n_LD_BODY\r\n_NETWORKS : 1\r\n_LD_CONTACT\r\nEND_X\r\nEND_PROGRAM\r\n"
                      "FUNCTION_BLOCK F\r\n  _FBD_BODY  \r\n_ASSIGN\r\n  END_FUNCTION_BLOCK\r\nPROGRAM S\r\nx := 1;\r\nEND_PROGRAM")
        << QStringLiteral("PROGRAM L\nVAR x : BOOL; END_VAR\n") + notRead.arg(QStringLiteral("LD"))
            + QStringLiteral("\n// _NETWORKS : 1\n// _LD_CONTACT\n// END_X\nEND_PROGRAM\nFUNCTION_BLOCK F\n")
            + notRead.arg(QStringLiteral("FBD")) + QStringLiteral("\n// _ASSIGN\n  END_FUNCTION_BLOCK\nPROGRAM S\nx := 1;\nEND_PROGRAM")
        << 0;
    // Without its END_PROGRAM the body ends where the next POU starts; that one is read.
    QTest::newRow("graphical body without its end")
        << QByteArray("PROGRAM L\n_SFC_BODY\n_STEP\nVAR_GLOBAL\nEND_VAR\nPROGRAM M\nEND_PROGRAM")
        << QStringLiteral("PROGRAM L\n") + notRead.arg(QStringLiteral("SFC"))
            + QStringLiteral("\n// _STEP\nVAR_GLOBAL\nEND_VAR\nPROGRAM M\nEND_PROGRAM")
        << 0;
}

void TestIecText::sourceFilesAreUtf8OrWindows1252()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, text);
    QFETCH(int, windows1252Line);
    const frontend::SourceText source = frontend::decodeSourceFile(bytes);
    QCOMPARE(source.text, text);
    QCOMPARE(source.windows1252Line, windows1252Line);
}

QTEST_GUILESS_MAIN(TestIecText)
#include "tst_iectext.moc"
