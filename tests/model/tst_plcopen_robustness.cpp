// Truncated, mutated, random and hostile input: the reader never crashes or hangs, and every
// broken input gives at least one diagnostic (with a line for well-formedness errors).

#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "roundtrip.h"

#include <QElapsedTimer>
#include <QFile>
#include <QRandomGenerator>
#include <QTest>

using namespace iec::model;
using namespace iec::test;

namespace {

constexpr quint32 kSeed = 20260301;

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

QByteArray sample(const char *name)
{
    if (QByteArray(name).startsWith("fixture:"))
        return readFile(QStringLiteral(IEC_SOURCE_DIR "/tests/model/fixtures/") + QLatin1String(name + 8));
    return readFile(corpusPath(QLatin1String(name)));
}

bool hasError(const plcopen::ReadResult &result)
{
    return std::ranges::any_of(
        result.diagnostics, [](const Diagnostic &d) { return d.severity == Diagnostic::Severity::Error; });
}

// Whatever was read can be written and read again without a crash.
void writeAndReadAgain(const plcopen::ReadResult &result)
{
    const QByteArray written = plcopen::writeProject(result.project);
    const plcopen::ReadResult again = plcopen::readProject(written);
    QVERIFY(!again.diagnostics.empty() || again.ok);
}

void addSamples()
{
    QTest::addColumn<QByteArray>("bytes");
    for (const char *name : {"beremiz_first_steps.xml", "codesys35sp18_sfc_test.xml", "codesys35sp14_FBDExample.xml",
             "fixture:every_element.xml"})
        QTest::newRow(name) << sample(name);
}

} // namespace

class TestPlcopenRobustness : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void truncatedInputIsAnErrorWithALine_data() { addSamples(); }
    void truncatedInputIsAnErrorWithALine();
    void corruptedAttributeValuesAreErrors_data() { addSamples(); }
    void corruptedAttributeValuesAreErrors();
    void renamedStartTagsAreErrors_data() { addSamples(); }
    void renamedStartTagsAreErrors();
    void flippedBytesNeverCrash_data() { addSamples(); }
    void flippedBytesNeverCrash();
    void randomBytesAreErrors();
    void randomElementTreesGiveDiagnostics();
    void hostileInput_data();
    void hostileInput();
    void missingFileIsAFileError();
    void oldFormsLoadWithWarningsAndAreWrittenValid();
    void charactersXmlDoesNotAllowAreLeftOutWhenRead_data();
    void charactersXmlDoesNotAllowAreLeftOutWhenRead();
    void charactersXmlDoesNotAllowAreNeverWritten();
    void leadingNulBytesAreNotTakenForUtf16();
    void repeatedElementsAreKeptWhereTheyStood_data();
    void repeatedElementsAreKeptWhereTheyStood();
};

void TestPlcopenRobustness::truncatedInputIsAnErrorWithALine()
{
    QFETCH(QByteArray, bytes);
    QVERIFY(!bytes.isEmpty());
    const qsizetype end = bytes.lastIndexOf("</project>");
    QRandomGenerator random(kSeed);
    for (int i = 0; i < 60; ++i) {
        const qsizetype cut = i == 0 ? 0 : random.bounded(end);
        const QByteArray truncated = bytes.left(cut);
        const plcopen::ReadResult result = plcopen::readProject(truncated);
        QVERIFY2(!result.ok && hasError(result), qPrintable(QStringLiteral("cut at %1").arg(cut)));
        const int lines = int(truncated.count('\n')) + 1;
        QVERIFY(result.diagnostics.front().line >= 1);
        QVERIFY(result.diagnostics.front().line <= lines);
        QVERIFY(!result.diagnostics.front().message.isEmpty());
    }
}

void TestPlcopenRobustness::corruptedAttributeValuesAreErrors()
{
    QFETCH(QByteArray, bytes);
    // Numeric and boolean attributes of the schema: a letter in front makes each one invalid.
    const QByteArrayList patterns {
        " localId=\"", " x=\"", " y=\"", " width=\"", " height=\"", " refLocalId=\"", " initialStep=\"", " negated=\""};
    std::vector<qsizetype> positions;
    for (const QByteArray &pattern : patterns) {
        for (qsizetype at = bytes.indexOf(pattern); at >= 0; at = bytes.indexOf(pattern, at + 1))
            positions.push_back(at + pattern.size());
    }
    QVERIFY(positions.size() > 10);
    QRandomGenerator random(kSeed);
    for (int i = 0; i < 40; ++i) {
        QByteArray mutated = bytes;
        const qsizetype at = positions[random.bounded(qsizetype(positions.size()))];
        mutated.insert(at, "Z");
        const plcopen::ReadResult result = plcopen::readProject(mutated);
        QVERIFY2(hasError(result), qPrintable(QString::fromUtf8(mutated.mid(at - 20, 40))));
        QCOMPARE(result.diagnostics.front().line, int(mutated.left(at).count('\n')) + 1);
        writeAndReadAgain(result);
    }
}

void TestPlcopenRobustness::renamedStartTagsAreErrors()
{
    QFETCH(QByteArray, bytes);
    // Start tags with content (not "<x/>"): renaming one leaves its end tag unmatched.
    std::vector<qsizetype> starts;
    for (qsizetype at = bytes.indexOf('<'); at >= 0; at = bytes.indexOf('<', at + 1)) {
        const char next = at + 1 < bytes.size() ? bytes[at + 1] : 0;
        const qsizetype close = bytes.indexOf('>', at);
        if (std::isalpha(static_cast<unsigned char>(next)) && close > 0 && bytes[close - 1] != '/')
            starts.push_back(at + 1);
    }
    QRandomGenerator random(kSeed);
    for (int i = 0; i < 40; ++i) {
        QByteArray mutated = bytes;
        mutated.insert(starts[random.bounded(qsizetype(starts.size()))], "zz");
        const plcopen::ReadResult result = plcopen::readProject(mutated);
        QVERIFY(!result.ok);
        QVERIFY(hasError(result));
        QVERIFY(result.diagnostics.front().line >= 1);
    }
}

void TestPlcopenRobustness::flippedBytesNeverCrash()
{
    QFETCH(QByteArray, bytes);
    QRandomGenerator random(kSeed);
    for (int i = 0; i < 40; ++i) {
        QByteArray mutated = bytes;
        for (int flips = 0; flips < 8; ++flips)
            mutated[random.bounded(mutated.size())] = char(random.bounded(256));
        const plcopen::ReadResult result = plcopen::readProject(mutated);
        writeAndReadAgain(result);
    }
}

void TestPlcopenRobustness::randomBytesAreErrors()
{
    QRandomGenerator random(kSeed);
    for (int i = 0; i < 200; ++i) {
        QByteArray bytes(random.bounded(4096), Qt::Uninitialized);
        for (char &byte : bytes)
            byte = char(random.bounded(256));
        const plcopen::ReadResult result = plcopen::readProject(bytes);
        QVERIFY(!result.ok);
        QVERIFY(hasError(result));
    }
}

void TestPlcopenRobustness::randomElementTreesGiveDiagnostics()
{
    // Well-formed trees of PLCopen element and attribute names in random places.
    const char *tags[] = {"fileHeader", "contentHeader", "types", "pous", "pou", "body", "FBD", "SFC", "LD", "ST",
        "block", "step", "transition", "connectionPointIn", "connection", "position", "addData", "data", "variable",
        "interface", "localVars", "type", "INT", "derived", "value"};
    const char *attributes[] = {"name", "localId", "x", "y", "refLocalId", "pouType", "negated", "handleUnknown"};
    QRandomGenerator random(kSeed);
    for (int i = 0; i < 200; ++i) {
        QByteArray xml = "<project>";
        QByteArrayList open {"project"};
        for (int n = random.bounded(1, 60); n > 0; --n) {
            if (open.size() > 1 && random.bounded(3) == 0) {
                xml += "</" + open.takeLast() + ">";
                continue;
            }
            const QByteArray tag = tags[random.bounded(int(std::size(tags)))];
            xml += "<" + tag;
            for (int a = random.bounded(3); a > 0; --a)
                xml += QByteArray(" ") + attributes[random.bounded(int(std::size(attributes)))] + "=\""
                    + QByteArray::number(random.bounded(-5, 5)) + "\"";
            xml += ">";
            open.push_back(tag);
        }
        while (!open.isEmpty())
            xml += "</" + open.takeLast() + ">";
        const plcopen::ReadResult result = plcopen::readProject(xml);
        QVERIFY2(!result.diagnostics.empty(), xml.constData());
        writeAndReadAgain(result);
    }
}

void TestPlcopenRobustness::hostileInput_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("firstMessage");
    const QByteArray head = "<project><fileHeader companyName=\"c\" productName=\"p\" productVersion=\"1\" "
                            "creationDateTime=\"2020-01-01T00:00:00\"/><contentHeader name=\"n\"><coordinateInfo>"
                            "<fbd><scaling x=\"1\" y=\"1\"/></fbd><ld><scaling x=\"1\" y=\"1\"/></ld><sfc><scaling "
                            "x=\"1\" y=\"1\"/></sfc></coordinateInfo></contentHeader>";
    const QByteArray tail = "<instances><configurations/></instances></project>";
    QByteArray deepBodies = head + "<types><dataTypes/><pous><pou name=\"P\" pouType=\"program\"><body><SFC>";
    for (int i = 0; i < 20000; ++i)
        deepBodies
            += "<actionBlock localId=\"1\"><position x=\"0\" y=\"0\"/><action localId=\"0\"><relPosition x=\"0\" "
               "y=\"0\"/><inline><SFC>";
    for (int i = 0; i < 20000; ++i)
        deepBodies += "</SFC></inline></action></actionBlock>";
    deepBodies += "</SFC></body></pou></pous></types>" + tail;
    QTest::newRow("deeply nested bodies")
        << deepBodies << QStringLiteral("The elements are nested too deeply; the content below is skipped.");

    QByteArray deepAddData = head + "<types><dataTypes/><pous/></types>" + tail.left(tail.size() - 10)
        + "<addData><data name=\"x\" handleUnknown=\"preserve\">";
    deepAddData += QByteArray("<a>").repeated(200000) + "<pou name=\"P\" pouType=\"program\"/>"
        + QByteArray("</a>").repeated(200000);
    deepAddData += "</data></addData></project>";
    QTest::newRow("deeply nested addData") << deepAddData << QString();

    QByteArray deepPou = head + "<types><dataTypes/><pous/></types>" + tail.left(tail.size() - 10)
        + "<addData><data name=\"x\" handleUnknown=\"preserve\"><pou name=\"P\" pouType=\"program\">";
    deepPou += QByteArray("<a>").repeated(200000) + QByteArray("</a>").repeated(200000);
    deepPou += "</pou></data></addData></project>";
    QTest::newRow("deep vendor POU")
        << deepPou << QStringLiteral("A declaration in addData is nested too deeply to read; it is kept as it is.");

    QByteArray entities = "<!DOCTYPE project [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;\">]>"
        + head + "<types><dataTypes/><pous/></types>" + tail;
    entities.replace("name=\"n\"", "name=\"&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;\"");
    QTest::newRow("entity expansion") << entities << QString();

    QByteArray wide = head + "<types><dataTypes/><pous><pou name=\"P\" pouType=\"program\"><body><FBD>";
    for (int i = 0; i < 50000; ++i)
        wide += "<unknown" + QByteArray::number(i) + "/>";
    wide += "</FBD></body></pou></pous></types>" + tail;
    QTest::newRow("many unknown elements")
        << wide << QStringLiteral("Unknown element <unknown0> in <FBD> is kept as it is.");

    QByteArray numbers = head
        + "<types><dataTypes/><pous><pou name=\"P\" pouType=\"program\"><body><FBD>"
          "<label localId=\"1\" label=\"a\" width=\"1e308\" height=\"1e-300\"><position x=\"nan\" "
          "y=\"inf\"/></label></FBD></body></pou></pous></types>"
        + tail;
    QTest::newRow("extreme numbers") << numbers
                                     << QStringLiteral(
                                            "The attribute x=\"nan\" of <position> has an invalid value; it is "
                                            "kept as written.");

    QByteArray repeated = head + "<types><dataTypes/><pous><pou name=\"P\" pouType=\"program\" color=\"red\" "
                                 "pouType=\"function\" color=\"blue\"><body><ST><xhtml:p>x := 1;</xhtml:p></ST></body>"
                                 "</pou></pous></types>" + tail;
    QTest::newRow("repeated attribute")
        << repeated << QStringLiteral("<pou> has the attribute pouType more than once; the first is kept.");

    QTest::newRow("not PLCopen") << QByteArray("<html><body/></html>")
                                 << QStringLiteral(
                                        "The root element is <html>, not <project>: this is not a PLCopen XML file.");
    QTest::newRow("empty") << QByteArray()
                           << QStringLiteral("The file is not well-formed XML: No document element found.");
}

void TestPlcopenRobustness::hostileInput()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, firstMessage);
    QElapsedTimer timer;
    timer.start();
    const plcopen::ReadResult result = plcopen::readProject(bytes);
    if (!firstMessage.isEmpty()) {
        QVERIFY(!result.diagnostics.empty());
        QCOMPARE(result.diagnostics.front().message, firstMessage);
    }
    writeAndReadAgain(result);
    QVERIFY2(timer.elapsed() < 20000, qPrintable(QString::number(timer.elapsed())));
}

void TestPlcopenRobustness::missingFileIsAFileError()
{
    const plcopen::ReadResult result = plcopen::readProjectFile(QStringLiteral("/nonexistent/project.xml"));
    QVERIFY(result.fileError);
    QVERIFY(!result.ok);
    QCOMPARE(result.diagnostics.size(), std::size_t {1});
    QVERIFY(result.diagnostics.front().message.startsWith(QStringLiteral("Cannot open /nonexistent/project.xml: ")));
}

// Older exports that are not quite valid: an <action> without localId and relPosition, a
// <pouInstance type=...>, a creationDateTime with a space. They load with one warning each and
// are written back valid.
void TestPlcopenRobustness::oldFormsLoadWithWarningsAndAreWrittenValid()
{
    QByteArray bytes = sample("fixture:every_element.xml");
    const auto replaceOnce = [&](const QByteArray &from, const QByteArray &to) {
        QVERIFY2(bytes.count(from) >= 1, from.constData());
        const qsizetype at = bytes.indexOf(from);
        bytes.replace(at, from.size(), to);
    };
    replaceOnce(R"(creationDateTime="2026-01-02T03:04:05")", R"(creationDateTime="2026-01-02 03:04:05")");
    replaceOnce(R"(<action localId="0" qualifier="L")", R"(<action qualifier="L")");
    replaceOnce("<relPosition x=\"0\" y=\"0\" />\n                <reference name=\"Reset\" />", "<reference name=\"Reset\" />");
    replaceOnce(R"(<pouInstance name="ChartInstance" typeName="Chart" />)", R"(<pouInstance name="ChartInstance" type="Chart" />)");
    const plcopen::ReadResult result = plcopen::readProject(bytes);
    QVERIFY(result.ok);
    QVERIFY(!hasError(result));
    QStringList warnings;
    for (const Diagnostic &d : result.diagnostics)
        warnings << d.message;
    QCOMPARE(warnings.size(), 4);
    QVERIFY2(warnings.join(QLatin1Char('\n')).contains(QStringLiteral("creationDateTime '2026-01-02 03:04:05' has a space")), qPrintable(warnings.join(QLatin1Char('\n'))));
    QVERIFY(warnings.join(QLatin1Char('\n')).contains(QStringLiteral("This <action> has no localId")));
    QVERIFY(warnings.join(QLatin1Char('\n')).contains(QStringLiteral("This <action> has no position")));
    QVERIFY(warnings.join(QLatin1Char('\n')).contains(QStringLiteral("names its POU with 'type'")));
    const QByteArray written = plcopen::writeProject(result.project);
    QCOMPARE(schemaErrors(written), QString());
    QVERIFY(written.contains(R"(creationDateTime="2026-01-02T03:04:05")"));
    QVERIFY(written.contains(R"(<pouInstance name="ChartInstance" typeName="Chart")"));
    const plcopen::ReadResult again = plcopen::readProject(written);
    QVERIFY(again.ok);
    QVERIFY(again.diagnostics.empty());
}

void TestPlcopenRobustness::charactersXmlDoesNotAllowAreLeftOutWhenRead_data()
{
    QTest::addColumn<QByteArray>("name");      // the contentHeader's name attribute, as written in the file
    QTest::addColumn<QByteArray>("paragraph"); // the content of the ST body's <xhtml:p>
    QTest::addColumn<QString>("expectedName");
    QTest::addColumn<QString>("expectedText");
    QTest::addColumn<int>("dropped"); // 0: no warning
    QTest::addColumn<int>("line");    // of the warning

    const QString text = QStringLiteral("a := 1; b := 2;");
    QTest::newRow("reference to U+0001") << QByteArray("n") << QByteArray("a := 1;&#1; b := 2;") << "n" << text << 1 << 2;
    QTest::newRow("reference to NUL") << QByteArray("n") << QByteArray("a := 1;&#0; b := 2;") << "n" << text << 1 << 2;
    QTest::newRow("hexadecimal reference to NUL")
        << QByteArray("n") << QByteArray("a := 1;&#x0000; b := 2;") << "n" << text << 1 << 2;
    // pugixml adds a reference's digits up in 32 bits that wrap: these are NULs too.
    QTest::newRow("references that wrap to NUL")
        << QByteArray("n") << QByteArray("a := 1;&#4294967296;&#x100000000; b := 2;") << "n" << text << 2 << 2;
    QTest::newRow("raw NUL") << QByteArray("n") << QByteArray("a := 1;\0 b := 2;", 16) << "n" << text << 1 << 2;
    QTest::newRow("raw escape") << QByteArray("n") << QByteArray("a := 1;\x1b b := 2;") << "n" << text << 1 << 2;
    QTest::newRow("U+FFFF and U+FFFE")
        << QByteArray("n") << QByteArray("a := 1;&#xFFFF; b\xEF\xBF\xBE := 2;") << "n" << QStringLiteral("a := 1; b := 2;")
        << 2 << 2;
    QTest::newRow("in an attribute")
        << QByteArray("n&#2;&#0;m") << QByteArray("a := 1; b := 2;") << "nm" << text << 2 << 1;
    QTest::newRow("in an attribute and a body")
        << QByteArray("n\x01") << QByteArray("a := 1;&#3;&#4; b := 2;") << "n" << text << 3 << 1;
    QTest::newRow("tab and line breaks are allowed")
        << QByteArray("n&#9;") << QByteArray("a := 1;&#9;&#10; b := 2;") << "n\t"
        << QStringLiteral("a := 1;\t\n b := 2;") << 0 << 0;
    QTest::newRow("in a CDATA section a reference is text")
        << QByteArray("n") << QByteArray("<![CDATA[a := 1;&#0; b := 2;]]>") << "n" << QStringLiteral("a := 1;&#0; b := 2;")
        << 0 << 0;
    QTest::newRow("a comment hides a reference")
        << QByteArray("n") << QByteArray("a := 1;<!-- &#0; --> b := 2;") << "n" << text << 0 << 0;
}

void TestPlcopenRobustness::charactersXmlDoesNotAllowAreLeftOutWhenRead()
{
    QFETCH(QByteArray, name);
    QFETCH(QByteArray, paragraph);
    QFETCH(QString, expectedName);
    QFETCH(QString, expectedText);
    QFETCH(int, dropped);
    QFETCH(int, line);
    const QByteArray file = "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">"
                            "<fileHeader companyName=\"c\" productName=\"p\" productVersion=\"1\" "
                            "creationDateTime=\"2020-01-01T00:00:00\"/><contentHeader name=\""
        + name
        + "\"><coordinateInfo><fbd><scaling x=\"1\" y=\"1\"/></fbd><ld><scaling x=\"1\" y=\"1\"/></ld><sfc><scaling "
          "x=\"1\" y=\"1\"/></sfc></coordinateInfo></contentHeader>\n<types><dataTypes/><pous><pou name=\"P\" "
          "pouType=\"program\"><body><ST><xhtml:p>"
        + paragraph + "</xhtml:p></ST></body></pou></pous></types><instances><configurations/></instances></project>";

    const plcopen::ReadResult read = plcopen::readProject(file);
    QVERIFY2(read.ok, qPrintable(diagnosticsText(read.diagnostics)));
    QCOMPARE(read.project.contentHeader.name, expectedName);
    QCOMPARE(read.project.types.pous.front().body()->text(), expectedText);
    if (dropped == 0) {
        QCOMPARE(diagnosticsText(read.diagnostics), QString());
    } else {
        QCOMPARE(read.diagnostics.size(), std::size_t(1));
        QCOMPARE(read.diagnostics.front().severity, Diagnostic::Severity::Warning);
        QCOMPARE(read.diagnostics.front().message,
            QStringLiteral("Characters XML does not allow (control characters, U+FFFE or U+FFFF) were left out of the "
                           "file, %1 in all, so that the project is saved as valid XML.")
                .arg(dropped));
        QCOMPARE(read.diagnostics.front().line, line);
    }

    const QByteArray written = plcopen::writeProject(read.project);
    QCOMPARE(schemaErrors(written), QString());
    const plcopen::ReadResult again = plcopen::readProject(written);
    QCOMPARE(diagnosticsText(again.diagnostics), QString());
    QCOMPARE(firstDifference(read.project, again.project), QString());
}

void TestPlcopenRobustness::charactersXmlDoesNotAllowAreNeverWritten()
{
    // However such characters entered the model, the file stays valid XML and nothing after them is
    // lost (a NUL handed to pugixml would end the text there).
    const QString controls = QStringLiteral("\x01") + QChar(u'\0') + QChar(0xFFFF) + QStringLiteral("\x1b");
    Project project;
    project.contentHeader.name = QStringLiteral("Plant") + controls + QStringLiteral(" 2");
    Pou pou;
    pou.name = QStringLiteral("Main");
    pou.documentation = FormattedText {.text = QStringLiteral("Pasted") + controls + QStringLiteral(" text")};
    Body body = Body::withLanguage(BodyLanguage::ST);
    body.setText(QStringLiteral("a := 1; (* pasted ") + controls + QStringLiteral(" *)\nb := 2;"));
    pou.bodies.push_back(body);
    project.types.pous.push_back(pou);

    const QByteArray written = plcopen::writeProject(project);
    QCOMPARE(savedSchemaErrors(project), QString());
    const auto read = plcopen::readProject(written);
    QCOMPARE(diagnosticsText(read.diagnostics), QString());
    QCOMPARE(read.project.contentHeader.name, QStringLiteral("Plant 2"));
    QCOMPARE(read.project.types.pous.front().documentation->text, QStringLiteral("Pasted text"));
    QCOMPARE(read.project.types.pous.front().body()->text(), QStringLiteral("a := 1; (* pasted  *)\nb := 2;"));
}

// A file is UTF-16 or UTF-32 only when pugixml would guess so ('<' among its first bytes); before,
// any NUL among the first two bytes made the reader skip its NUL mending, and the file did not read.
void TestPlcopenRobustness::leadingNulBytesAreNotTakenForUtf16()
{
    const QByteArray project = "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\"><fileHeader companyName=\"c\" "
                               "productName=\"p\" productVersion=\"1\" creationDateTime=\"2020-01-01T00:00:00\"/>"
                               "<contentHeader name=\"n\"><coordinateInfo><fbd><scaling x=\"1\" y=\"1\"/></fbd><ld>"
                               "<scaling x=\"1\" y=\"1\"/></ld><sfc><scaling x=\"1\" y=\"1\"/></sfc></coordinateInfo>"
                               "</contentHeader><types><dataTypes/><pous/></types><instances><configurations/></instances>"
                               "</project>";
    const plcopen::ReadResult read = plcopen::readProject(QByteArray("\0\0", 2) + project);
    QVERIFY2(read.ok, qPrintable(diagnosticsText(read.diagnostics)));
    QCOMPARE(diagnosticsText(read.diagnostics), QString());
    QCOMPARE(read.project.contentHeader.name, QStringLiteral("n"));
}

void TestPlcopenRobustness::repeatedElementsAreKeptWhereTheyStood_data()
{
    QTest::addColumn<QByteArray>("pouContent"); // the children of <pou name="P">, each on its own line
    QTest::addColumn<QString>("readVariables"); // the variables of the interface that is read
    QTest::addColumn<QString>("readText"); // the text of the body that is read
    QTest::addColumn<QString>("warning"); // "line: message"
    QTest::addColumn<QByteArrayList>("writtenOrder"); // strings that follow each other in the written file

    const QByteArray interfaceA
        = "<interface><localVars><variable name=\"A\"><type><BOOL/></type></variable></localVars></interface>\n";
    const QByteArray interfaceB
        = "<interface><localVars><variable name=\"B\"><type><INT/></type></variable></localVars></interface>\n";
    const QByteArray bodyOne = "<body><ST><xhtml:p>A := TRUE;</xhtml:p></ST></body>\n";
    const QString extraPou
        = QStringLiteral("in <pou> is more than the file format allows there; it is kept as it is, but not read.");
    QTest::newRow("a second interface after the first")
        << interfaceA + interfaceB + bodyOne << QStringLiteral("A") << QStringLiteral("A := TRUE;")
        << QStringLiteral("4:1: <interface> ") + extraPou << QByteArrayList {"name=\"A\"", "name=\"B\"", "A := TRUE;"};
    // Bodies may repeat, so the second interface follows the last body when written.
    QTest::newRow("a second interface after the body")
        << interfaceA + bodyOne + interfaceB << QStringLiteral("A") << QStringLiteral("A := TRUE;")
        << QStringLiteral("5:1: <interface> ") + extraPou << QByteArrayList {"name=\"A\"", "A := TRUE;", "name=\"B\""};
    QTest::newRow("three interfaces among unknown elements")
        << interfaceA + "<vendorFirst/>\n" + interfaceB + "<vendorSecond/>\n" + interfaceB + bodyOne
        << QStringLiteral("A") << QStringLiteral("A := TRUE;")
        << QStringLiteral("4:1: Unknown element <vendorFirst> in <pou> is kept as it is.\n5:1: <interface> ") + extraPou
            + QStringLiteral("\n6:1: Unknown element <vendorSecond> in <pou> is kept as it is.\n7:1: <interface> ")
            + extraPou
        << QByteArrayList {"name=\"A\"", "<vendorFirst", "name=\"B\"", "<vendorSecond", "name=\"B\"", "A := TRUE;"};
    QTest::newRow("a body with two texts")
        << interfaceA + "<body><ST><xhtml:p>A := TRUE;</xhtml:p></ST>\n<ST><xhtml:p>A := FALSE;</xhtml:p></ST></body>\n"
        << QStringLiteral("A") << QStringLiteral("A := TRUE;")
        << QStringLiteral(
               "5:1: <ST> in <body> is more than the file format allows there; it is kept as it is, but not read.")
        << QByteArrayList {"A := TRUE;", "A := FALSE;"};
    QTest::newRow("a variable with two types")
        << QByteArray("<interface><localVars><variable name=\"A\"><type><BOOL/></type>\n<type><INT/></type>"
                      "</variable></localVars></interface>\n")
            + bodyOne
        << QStringLiteral("A") << QStringLiteral("A := TRUE;")
        << QStringLiteral("4:1: <type> in <variable> is more than the file format allows there; it is kept as it is, "
                          "but not read.")
        << QByteArrayList {"<BOOL", "<INT", "A := TRUE;"};
}

// A file may repeat an element the XSD allows once (fuzz_plcopen made one with three <interface>s).
// The first is read; the others are kept where they stood, so the file written reads the same.
void TestPlcopenRobustness::repeatedElementsAreKeptWhereTheyStood()
{
    QFETCH(QByteArray, pouContent);
    QFETCH(QString, readVariables);
    QFETCH(QString, readText);
    QFETCH(QString, warning);
    QFETCH(QByteArrayList, writtenOrder);
    const QByteArray file
        = "<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\">"
          "<fileHeader companyName=\"c\" productName=\"p\" productVersion=\"1\" "
          "creationDateTime=\"2020-01-01T00:00:00\"/><contentHeader name=\"n\"><coordinateInfo><fbd>"
          "<scaling x=\"1\" y=\"1\"/></fbd><ld><scaling x=\"1\" y=\"1\"/></ld><sfc><scaling x=\"1\" "
          "y=\"1\"/></sfc></coordinateInfo></contentHeader>\n<types><dataTypes/><pous><pou name=\"P\" "
          "pouType=\"program\">\n"
        + pouContent + "</pou></pous></types><instances><configurations/></instances></project>";

    const plcopen::ReadResult read = plcopen::readProject(file);
    QVERIFY2(read.ok, qPrintable(diagnosticsText(read.diagnostics)));
    const Pou &pou = read.project.types.pous.front();
    QStringList variables;
    for (const VarList &list : pou.pouInterface->varLists)
        for (const Variable &variable : list.variables)
            variables << variable.name;
    QCOMPARE(variables.join(QLatin1Char(' ')), readVariables);
    QCOMPARE(pou.body()->text(), readText);
    QCOMPARE(diagnosticsText(read.diagnostics), warning + QLatin1Char('\n'));

    const QByteArray written = plcopen::writeProject(read.project);
    qsizetype at = 0;
    for (const QByteArray &next : writtenOrder) {
        const qsizetype found = written.indexOf(next, at);
        QVERIFY2(found >= 0,
            qPrintable(QStringLiteral("%1 does not follow at %2 in\n%3")
                           .arg(QString::fromUtf8(next))
                           .arg(at)
                           .arg(QString::fromUtf8(written))));
        at = found + next.size();
    }
    const plcopen::ReadResult again = plcopen::readProject(written);
    QCOMPARE(diagnosticsText(again.diagnostics).count(QStringLiteral("more than the file format allows")),
        warning.count(QStringLiteral("more than the file format allows")));
    QCOMPARE(firstDifference(read.project, again.project), QString());
}

QTEST_GUILESS_MAIN(TestPlcopenRobustness)
#include "tst_plcopen_robustness.moc"
