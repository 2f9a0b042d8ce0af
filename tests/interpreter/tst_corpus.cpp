// The Beremiz examples of ../shared/plcopen/corpus, read by the model's PLCopen reader and
// compiled through the model front end (projectsource.h): their ST POUs compile, the language
// test's conversion checks pass when run, and its FBD POUs are reported, not run.
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "model/plcopen/reader.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;

class TestCorpus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void languageTestPassesItsOwnChecks();
    void languageTestNamesItsFbdPous();
    void standardFunctionBlocksCompile();
};

namespace {

model::Project readCorpus(const char *file)
{
    const auto result
        = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + QLatin1String(file));
    return result.project;
}

QString errors(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

// Drops the POUs the compiler cannot run yet (graphical bodies); returns their names.
QStringList dropGraphicalPous(model::Project &project)
{
    QStringList dropped;
    std::erase_if(project.types.pous, [&](const model::Pou &pou) {
        const bool graphical = pou.body() && pou.body()->isGraphical();
        if (graphical)
            dropped << pou.name;
        return graphical;
    });
    return dropped;
}

} // namespace

void TestCorpus::languageTestPassesItsOwnChecks()
{
    model::Project project = readCorpus("beremiz_iec61131_lang_test.xml");
    QCOMPARE(dropGraphicalPous(project), (QStringList {QStringLiteral("main_test"), QStringLiteral("TEMPO_TEST")}));
    project.instances.configurations.clear(); // its task runs main_test, which is FBD
    const auto main = frontend::readIecText(
        u"PROGRAM Main\nVAR t : CONVERSION_TEST; result : STRING; END_VAR\nt();\nresult := t.RESULT;\nEND_PROGRAM\n",
        {});
    QCOMPARE(errors(main.diagnostics), QString());
    project.types.pous.push_back(main.project.types.pous.front());
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project, diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(runtime.runCycle());
    // The test sets RESULT to the name of each conversion before checking it and returns at the
    // first failure; 'OK' means all 240 passed.
    QCOMPARE(runtime.read(QStringLiteral("Main.result")).value(), QStringLiteral("'OK'"));
}

void TestCorpus::languageTestNamesItsFbdPous()
{
    Diagnostics diagnostics;
    QVERIFY(!frontend::compileProject(readCorpus("beremiz_iec61131_lang_test.xml"), diagnostics));
    // Its FBD POUs are lowered; what stops them is the Beremiz library they call (one message per block).
    const QString logger = QStringLiteral("main_test:0:0: error: The LOGGER block comes from the Beremiz library, "
                                          "which this version does not have.");
    QCOMPARE(errors(diagnostics),
        QStringList({logger, logger, logger,
                        QStringLiteral("TEMPO_TEST:0:0: error: The RTC block comes from the Beremiz library, "
                                       "which this version does not have.")})
            .join(QLatin1Char('\n')));
}

void TestCorpus::standardFunctionBlocksCompile()
{
    const model::Project project = readCorpus("beremiz_Standard_Function_Blocks.xml");
    QCOMPARE(project.types.pous.size(), size_t(23));
    Diagnostics diagnostics;
    CompileOptions options;
    const auto unit = frontend::buildUnit(project, diagnostics);
    QCOMPARE(unit.unit.pous.size(), size_t(23));
    const auto module = frontend::compileUnit(unit, diagnostics, options);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module); // the file's own SR, TON, ... replace the built-in library ones
}

QTEST_GUILESS_MAIN(TestCorpus)
#include "tst_corpus.moc"
