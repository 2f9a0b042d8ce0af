// PLCopen fragments (model/plcopen/fragment.h): the elements of every graphical body of the
// fixtures and the corpus written as a fragment and read back equal; everything else refused.
#include "model/plcopen/fragment.h"
#include "model/plcopen/reader.h"
#include "modelfixture.h"
#include "roundtrip.h"

#include <QTest>

using namespace iec;
using namespace iec::model;

class TestPlcopenFragment : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyBodyRoundTrips_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("every element") << QStringLiteral(IEC_SOURCE_DIR "/tests/model/fixtures/every_element.xml");
        for (const char *name : {"beremiz_first_steps.xml", "beremiz_svghmi_traffic_light.xml", "codesys35sp18_sfc_test.xml",
                 "openplc_Traffic_Light_FBD.xml", "twincat356_ppu.xml"})
            QTest::newRow(name) << test::corpusPath(QLatin1String(name));
    }

    void everyBodyRoundTrips()
    {
        QFETCH(QString, file);
        const plcopen::ReadResult read = plcopen::readProjectFile(file);
        if (read.fileError)
            QSKIP("the file is not there");
        int bodies = 0;
        const auto check = [&](const Body &body, const QString &where) {
            if (!body.elements())
                return;
            ++bodies;
            const QByteArray xml = plcopen::writeElementsFragment(QStringLiteral("LD"), *body.elements());
            const plcopen::FragmentReadResult back = plcopen::readElementsFragment(xml);
            QVERIFY2(back.ok(), qPrintable(where + QStringLiteral(": ") + back.error));
            QCOMPARE(back.language, QStringLiteral("LD"));
            QVERIFY2(back.elements == *body.elements(), qPrintable(where));
            // Deterministic, as the file writer.
            QCOMPARE(plcopen::writeElementsFragment(QStringLiteral("LD"), back.elements), xml);
        };
        for (const Pou &pou : read.project.types.pous) {
            for (const Body &body : pou.bodies)
                check(body, pou.name);
            for (const PouPart &part : pou.actions)
                check(part.body, pou.name + QLatin1Char('.') + part.name);
            for (const PouPart &part : pou.transitions)
                check(part.body, pou.name + QLatin1Char('.') + part.name);
        }
        QVERIFY(bodies > 0);
    }

    void otherBytesAreRefused_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("error");
        QTest::newRow("text") << QByteArray("Start AND Stop") << QStringLiteral("It is not well-formed XML: No document element found.");
        QTest::newRow("malformed") << QByteArray("<fragment language=\"LD\"><contact localId=\"1\"")
                                   << QStringLiteral("It is not well-formed XML: Error parsing start element tag.");
        QTest::newRow("a project") << QByteArray("<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"/>")
                                   << QStringLiteral("It is XML with a <project> root, not elements copied in IEC Studio.");
        QTest::newRow("unknown element") << QByteArray("<fragment language=\"LD\"><gadget/></fragment>")
                                         << QStringLiteral("It holds something that is not an element of a body.");
        QTest::newRow("no language") << QByteArray("<fragment/>")
                                     << QStringLiteral("It cannot be read: <fragment> lacks the required attribute 'language'.");
    }

    void otherBytesAreRefused()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, error);
        const plcopen::FragmentReadResult read = plcopen::readElementsFragment(bytes);
        QCOMPARE(read.error, error);
        QVERIFY(read.elements.empty() || !read.ok());
    }
};

QTEST_GUILESS_MAIN(TestPlcopenFragment)
#include "tst_plcopen_fragment.moc"
