// Every file of ../shared/plcopen/corpus: read, write, validate against the XSD, read again and
// compare; writing twice gives the same bytes.

#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/statistics.h"
#include "roundtrip.h"

#include <QFile>
#include <QTest>

using namespace iec::model;
using namespace iec::test;

class TestPlcopenCorpus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roundTrip_data();
    void roundTrip();
};

void TestPlcopenCorpus::roundTrip_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("pous");
    QTest::addColumn<int>("dataTypes");
    QTest::addColumn<int>("pousFromAddData");
    QTest::addColumn<int>("generatedLayouts");
    QTest::addColumn<int>("elements");
    QTest::addColumn<int>("variables");
    QTest::newRow("beremiz first steps") << "beremiz_first_steps.xml" << 7 << 0 << 0 << 0 << 45 << 39;
    QTest::newRow("beremiz svghmi") << "beremiz_svghmi_traffic_light.xml" << 2 << 0 << 0 << 0 << 72 << 26;
    QTest::newRow("beremiz lang test") << "beremiz_iec61131_lang_test.xml" << 3 << 0 << 0 << 0 << 55 << 20;
    QTest::newRow("beremiz standard FBs") << "beremiz_Standard_Function_Blocks.xml" << 23 << 0 << 0 << 0 << 0 << 150;
    QTest::newRow("openplc traffic light") << "openplc_Traffic_Light_FBD.xml" << 1 << 0 << 0 << 0 << 24 << 10;
    QTest::newRow("openplc tcp socket") << "openplc_TCP_socket.xml" << 1 << 0 << 0 << 0 << 52 << 12;
    QTest::newRow("codesys mixing tank") << "codesys35sp16_hello_mixing_tank.xml" << 3 << 2 << 2 << 0 << 0 << 45;
    QTest::newRow("codesys sfc") << "codesys35sp18_sfc_test.xml" << 1 << 0 << 0 << 1 << 46 << 25;
    QTest::newRow("codesys fbd") << "codesys35sp14_FBDExample.xml" << 3 << 0 << 0 << 2 << 42 << 14;
    QTest::newRow("twincat MAIN") << "twincat3513_MAIN.xml" << 1 << 0 << 0 << 0 << 0 << 10;
    QTest::newRow("twincat ppu") << "twincat356_ppu.xml" << 12 << 1 << 12 << 35 << 697 << 132;
}

void TestPlcopenCorpus::roundTrip()
{
    QFETCH(QString, file);
    QFETCH(int, pous);
    QFETCH(int, dataTypes);
    QFETCH(int, pousFromAddData);
    QFETCH(int, generatedLayouts);
    QFETCH(int, elements);
    QFETCH(int, variables);

    const plcopen::ReadResult first = plcopen::readProjectFile(corpusPath(file));
    QVERIFY2(first.ok, qPrintable(diagnosticsText(first.diagnostics)));
    QVERIFY2(first.diagnostics.empty(), qPrintable(diagnosticsText(first.diagnostics)));
    QCOMPARE(int(first.project.types.pous.size()), pous);
    QCOMPARE(int(first.project.types.dataTypes.size()), dataTypes);
    QCOMPARE(int(std::ranges::count_if(first.project.types.pous, [](const Pou &p) { return p.addDataSlot != 0; })),
        pousFromAddData);
    int layouts = 0;
    for (const Pou &pou : first.project.types.pous) {
        for (const Body &body : pou.bodies)
            layouts += body.layoutGenerated ? 1 : 0;
        for (const PouAction &action : pou.actions)
            layouts += action.body.layoutGenerated ? 1 : 0;
        for (const PouTransition &transition : pou.transitions)
            layouts += transition.body.layoutGenerated ? 1 : 0;
    }
    QCOMPARE(layouts, generatedLayouts);
    const ProjectStatistics stats = statistics(first.project);
    QCOMPARE(stats.elements, elements);
    QCOMPARE(stats.variables, variables);

    const QByteArray written = plcopen::writeProject(first.project);
    const QString errors = schemaErrors(written);
    QVERIFY2(errors.isEmpty(), qPrintable(errors));

    const plcopen::ReadResult second = plcopen::readProject(written);
    QVERIFY2(second.diagnostics.empty(), qPrintable(diagnosticsText(second.diagnostics)));
    const QString difference = firstDifference(first.project, second.project);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
    QVERIFY(first.project == second.project);
    QVERIFY(statistics(second.project) == stats); // `iecstudio-cli info` gives the same numbers for both
    QCOMPARE(plcopen::writeProject(second.project), written);
}

QTEST_GUILESS_MAIN(TestPlcopenCorpus)
#include "tst_plcopen_corpus.moc"
