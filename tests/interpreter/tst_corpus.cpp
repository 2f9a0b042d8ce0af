// The Beremiz examples of ../shared/plcopen/corpus: their ST POUs compile, and the language
// test's conversion checks pass when run.
#include "plcopentext.h"

#include "interpreter/compiler/compiler.h"
#include "interpreter/runtime/runtime.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;

class TestCorpus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void languageTestPassesItsOwnChecks();
    void standardFunctionBlocksCompile();
};

namespace {

QString corpus(const char *file)
{
    return QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + QLatin1String(file);
}

QString stSource(const std::vector<PlcopenPou> &pous, QStringList *names = nullptr)
{
    QString source;
    for (const PlcopenPou &p : pous) {
        if (p.language != QLatin1String("ST"))
            continue; // graphical bodies are compiled by the next issue
        source += p.source;
        if (names)
            *names << p.name;
    }
    return source;
}

QString errors(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

} // namespace

void TestCorpus::languageTestPassesItsOwnChecks()
{
    const auto pous = readPlcopenPous(corpus("beremiz_iec61131_lang_test.xml"));
    QVERIFY(!pous.empty());
    QStringList names;
    const QString source = stSource(pous, &names) +
        QStringLiteral("PROGRAM Main\nVAR t : CONVERSION_TEST; result : STRING; END_VAR\nt();\nresult := t.RESULT;\nEND_PROGRAM\n");
    QCOMPARE(names, QStringList{QStringLiteral("CONVERSION_TEST")});
    Diagnostics diagnostics;
    CompileOptions options;
    options.program = QStringLiteral("Main");
    const auto module = compileText(source, diagnostics, options);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(runtime.runCycle());
    // The test sets RESULT to the name of each conversion before checking it and returns at the
    // first failure; 'OK' means all 240 passed.
    QCOMPARE(runtime.read(QStringLiteral("Main.result")).value(), QStringLiteral("'OK'"));
}

void TestCorpus::standardFunctionBlocksCompile()
{
    const auto pous = readPlcopenPous(corpus("beremiz_Standard_Function_Blocks.xml"));
    QStringList names;
    const QString source = stSource(pous, &names);
    QCOMPARE(names.size(), 23);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module); // the file's own SR, TON, ... replace the built-in library ones
}

QTEST_GUILESS_MAIN(TestCorpus)
#include "tst_corpus.moc"
