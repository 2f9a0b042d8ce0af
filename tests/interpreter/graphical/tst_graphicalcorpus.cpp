// Every LD and FBD POU of ../shared/plcopen/corpus is lowered: it compiles, or its diagnostics
// name the vendor library it needs. SFC bodies (another part of the lowering) are replaced by
// empty ST here, so that the POUs using them still compile; their LD/FBD actions are lowered.
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "model/plcopen/reader.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;

class TestGraphicalCorpus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void compilesOrNamesTheVendorFeature_data();
    void compilesOrNamesTheVendorFeature();
    void firstStepsCountersAgreeAcrossLanguages();
};

namespace {

model::Project readWithoutCharts(const QString &file)
{
    auto read = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + file);
    for (model::Pou &pou : read.project.types.pous) {
        if (pou.body() && pou.body()->language() == model::BodyLanguage::SFC)
            pou.bodies = {model::Body::withLanguage(model::BodyLanguage::ST)};
    }
    return read.project;
}

QString errors(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all()) {
        if (d.severity == Diagnostic::Severity::Error)
            lines << d.pou + QStringLiteral(": ") + d.message;
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace

void TestGraphicalCorpus::compilesOrNamesTheVendorFeature_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("expected");
    QTest::newRow("beremiz first steps") << "beremiz_first_steps.xml" << "";
    // Its LOGGER and RTC blocks are Beremiz's, which IEC Studio has (docs/stdlib.md).
    QTest::newRow("beremiz language test") << "beremiz_iec61131_lang_test.xml" << "";
    // Its FBD lowers; its Beremiz SVGHMI variables (HMI_BOOL) are plain BOOLs (docs/stdlib.md).
    QTest::newRow("beremiz traffic light") << "beremiz_svghmi_traffic_light.xml" << "";
    QTest::newRow("codesys FBD example") << "codesys35sp14_FBDExample.xml" << "";
    // A warning names the library at the block's first use; the error says which program cannot run.
    QTest::newRow("openplc TCP socket")
        << "openplc_TCP_socket.xml" << "tcp_socket: instance0 cannot run: tcp_socket uses the OpenPLC TCP socket library.";
    QTest::newRow("openplc traffic light") << "openplc_Traffic_Light_FBD.xml" << "";
}

void TestGraphicalCorpus::compilesOrNamesTheVendorFeature()
{
    QFETCH(QString, file);
    QFETCH(QString, expected);
    Diagnostics diagnostics;
    frontend::compileProject(readWithoutCharts(file), diagnostics);
    if (expected.startsWith(QLatin1String("first: "))) {
        Diagnostics lowering; // parsing and lowering alone are clean
        QVERIFY(!frontend::buildUnit(readWithoutCharts(file), lowering).parseErrors);
        QCOMPARE(errors(lowering), QString());
        QCOMPARE(errors(diagnostics).section(QLatin1Char('\n'), 0, 0), expected.mid(7));
        return;
    }
    QCOMPARE(errors(diagnostics), expected);
}

// plc_prg of first_steps runs the same counter written in ST, IL, LD and FBD side by side.
void TestGraphicalCorpus::firstStepsCountersAgreeAcrossLanguages()
{
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(readWithoutCharts(QStringLiteral("beremiz_first_steps.xml")), diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module, 100'000'000); // its task runs every 100 ms
    for (int cycle = 1; cycle <= 5; ++cycle) {
        QVERIFY(runtime.runCycle());
        const auto st = runtime.read(QStringLiteral("plc_prg.CounterST0.OUT"));
        QVERIFY(st);
        QCOMPARE(*st, QString::number(cycle));
        QCOMPARE(runtime.read(QStringLiteral("plc_prg.CounterFBD0.OUT")), st);
        QCOMPARE(runtime.read(QStringLiteral("plc_prg.CounterLD0.OUT")), st);
    }
}

QTEST_GUILESS_MAIN(TestGraphicalCorpus)
#include "tst_graphicalcorpus.moc"
