// The printed documentation of a project: its contents in order, every part's text (declarations,
// bodies, data types, global lists, tasks), diagrams (LD, FBD, CFC, SFC) as pictures, page numbers in the contents that
// match the pages, and the PDF export.
#include "app/projectdocumentation.h"
#include "model/plcopen/reader.h"
#include "model/projectmodel.h"

#include <QFile>
#include <QPrinter>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextDocument>

using namespace iec;
using namespace iec::app;

namespace {

model::Project example(const char *name)
{
    model::plcopen::ReadResult read
        = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/%1").arg(QString::fromLatin1(name)));
    return read.project;
}

} // namespace

class TestDocumentation : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void contentsListEveryPart();
    void partsCarryTheirText();
    void diagramsArePictures_data();
    void diagramsArePictures();
    void withoutAPictureTheDocumentSaysWhy();
    void contentsPageNumbersPointAtTheParts();
    void pdfIsWritten();
};

void TestDocumentation::contentsListEveryPart()
{
    model::ProjectModel model;
    model.reset(example("first_steps.xml"));
    const QStringList contents = ProjectDocumentation(model).contents();
    QCOMPARE(contents.front(), QStringLiteral("Main (program, ST)"));
    QCOMPARE(contents.back(), QStringLiteral("Configuration Config"));
}

void TestDocumentation::partsCarryTheirText()
{
    model::ProjectModel model;
    model.reset(example("first_steps.xml"));
    const QString html = ProjectDocumentation(model).html();
    const model::Pou &main = *model.project().findPou(QStringLiteral("Main"));
    // The body as written, the declarations as the editor prints them, the task as a table row.
    const QString firstLine = main.body()->text().section(QLatin1Char('\n'), 0, 0).toHtmlEscaped();
    QVERIFY2(html.contains(firstLine), qPrintable(firstLine));
    QVERIFY(html.contains(QStringLiteral("<td>MainTask</td><td>T#10ms</td>")));
    QVERIFY(html.contains(QStringLiteral("page-break-before: always")));
}

void TestDocumentation::diagramsArePictures_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("SFC") << "mixing_tank.xml";
    QTest::newRow("LD") << "motor_start_stop.xml";
    QTest::newRow("FBD") << "staggered_fans.xml";
    QTest::newRow("CODESYS CFC") << "";
}

void TestDocumentation::diagramsArePictures()
{
    QFETCH(QString, file);
    model::ProjectModel model;
    if (file.isEmpty()) {
        // CODESYS keeps a CFC in the addData of an empty ST body: drawn, not "The body is empty".
        model::Project project = example("first_steps.xml");
        model::Body body = model::Body::withLanguage(model::BodyLanguage::ST);
        body.addData.push_back({QStringLiteral("http://www.3s-software.com/plcopenxml/cfc"), QStringLiteral("implementation"),
            QStringLiteral("<CFC><inVariable localId=\"1\"><position x=\"5\" y=\"5\"/><connectionPointOut><expression/></connectionPointOut>"
                           "<expression>Start</expression></inVariable>"
                           "<outVariable localId=\"3\" executionOrderId=\"0\"><position x=\"15\" y=\"5\"/><connectionPointIn><relPosition x=\"0\" y=\"0\"/>"
                           "<connection refLocalId=\"1\"/></connectionPointIn><expression>Lamp</expression></outVariable></CFC>")});
        project.types.pous.front().bodies = {body};
        model.reset(project);
    } else {
        model.reset(example(qPrintable(file)));
    }
    int pictures = 0;
    ProjectDocumentation documentation(model, [&](model::ProjectModel &m, const model::BodyRef &ref) {
        QImage image = ProjectDocumentation::defaultBodyPicture(m, ref);
        // Something is drawn on the white page.
        bool inked = false;
        for (int y = 0; y < image.height() && !inked; y += 2)
            for (int x = 0; x < image.width() && !inked; x += 2)
                inked = image.pixel(x, y) != qRgb(255, 255, 255);
        pictures += inked ? 1 : 0;
        return image;
    });
    const QString html = documentation.html();
    QVERIFY(pictures >= 1);
    QVERIFY(html.contains(QStringLiteral("<img src=\"body")));
    QVERIFY(!html.contains(QStringLiteral("cannot print it as a picture")));
    QVERIFY(!html.contains(QStringLiteral("The body is empty.")));
}

void TestDocumentation::withoutAPictureTheDocumentSaysWhy()
{
    model::ProjectModel model;
    model.reset(example("motor_start_stop.xml"));
    const QString html = ProjectDocumentation(model, [](model::ProjectModel &, const model::BodyRef &) { return QImage(); }).html();
    QVERIFY(html.contains(QStringLiteral("The LD body is drawn in the editor; this version cannot print it as a picture.")));
}

void TestDocumentation::contentsPageNumbersPointAtTheParts()
{
    model::ProjectModel model;
    model.reset(example("mixing_tank.xml"));
    ProjectDocumentation documentation(model);
    QTemporaryDir dir;
    QPrinter printer(QPrinter::HighResolution);
    printer.setOutputFormat(QPrinter::PdfFormat);
    printer.setOutputFileName(dir.filePath(QStringLiteral("x.pdf")));
    const std::unique_ptr<QTextDocument> document = documentation.document(printer);
    // The contents' numbers: one per part, from page 3 on (cover, contents), never decreasing.
    const QStringList contents = documentation.contents();
    std::vector<int> numbers;
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        if (contents.contains(block.text()) && block.next().isValid()) {
            bool ok = false;
            const int page = block.next().text().toInt(&ok);
            if (ok)
                numbers.push_back(page);
        }
    }
    QCOMPARE(numbers.size(), size_t(contents.size()));
    QVERIFY(numbers.front() >= 3);
    QVERIFY(std::ranges::is_sorted(numbers));
    QVERIFY(numbers.back() > numbers.front()); // each part on a page of its own
}

void TestDocumentation::pdfIsWritten()
{
    model::ProjectModel model;
    model.reset(example("mixing_tank.xml"));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mixing_tank.pdf"));
    QCOMPARE(ProjectDocumentation(model).exportPdf(path), QString());
    QFile pdf(path);
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    const QByteArray bytes = pdf.readAll();
    QVERIFY(bytes.startsWith("%PDF"));
    // A cover, the contents and one page per part at least.
    const qsizetype pages = bytes.count("/Type /Page\n") + bytes.count("/Type /Page\r") + bytes.count("/Type /Page>>");
    QVERIFY2(pages >= 4 || bytes.count("/Type /Page") >= 5, qPrintable(QString::number(bytes.count("/Type /Page"))));
}

QTEST_MAIN(TestDocumentation)
#include "tst_documentation.moc"
