// The printed documentation of a project: its contents in order, every part's text (declarations,
// bodies, data types, global lists, tasks), charts as pictures, page numbers in the contents that
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
    void chartsArePicturesOthersSayWhy();
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

void TestDocumentation::chartsArePicturesOthersSayWhy()
{
    model::ProjectModel model;
    model.reset(example("mixing_tank.xml"));
    int pictures = 0;
    ProjectDocumentation documentation(model, [&](model::ProjectModel &m, const model::BodyRef &ref) {
        QImage image = ProjectDocumentation::defaultBodyPicture(m, ref);
        pictures += image.isNull() ? 0 : 1;
        return image;
    });
    const QString html = documentation.html();
    QVERIFY(pictures >= 1);
    QVERIFY(html.contains(QStringLiteral("<img src=\"body")));

    model.reset(example("motor_start_stop.xml"));
    QVERIFY(ProjectDocumentation(model).html().contains(
        QStringLiteral("The LD body is drawn in the editor; this version cannot print it as a picture.")));
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
