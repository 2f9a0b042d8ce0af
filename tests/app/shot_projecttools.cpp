// Not a test: renders the project tools (global list editor, task configuration, find in project
// results, library pane, a page of the printed documentation) in each UI language to PNG files,
// for looking at. Offscreen: build/test/tests/app/shot_projecttools OUT_DIR
#include "app/documentarea.h"
#include "app/globallistcommands.h"
#include "app/librarypane.h"
#include "app/mainwindow.h"
#include "app/projectdocumentation.h"
#include "app/searchactions.h"
#include "app/searchresultspane.h"
#include "editors/datatypes/rowtable.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/globals/globallisteditor.h"
#include "editors/tasks/configurationeditor.h"
#include "model/plcopen/reader.h"
#include "model/projectmodel.h"

#include <QAbstractTextDocumentLayout>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QPainter>
#include <QPrinter>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QTextFrame>

using namespace iec;

namespace {

void save(QWidget *widget, const QString &dir, const QString &name, const QString &language)
{
    QCoreApplication::processEvents();
    widget->grab().save(QDir(dir).filePath(QStringLiteral("%1_%2.png").arg(name, language)));
}

// Page `page` (1-based) of the documentation as the printer lays it out, at screen resolution.
QImage documentationPage(model::ProjectModel &model, int page)
{
    QTemporaryDir dir;
    QPrinter printer(QPrinter::ScreenResolution);
    printer.setOutputFormat(QPrinter::PdfFormat);
    printer.setOutputFileName(dir.filePath(QStringLiteral("page.pdf")));
    const std::unique_ptr<QTextDocument> document = app::ProjectDocumentation(model).document(printer);
    document->documentLayout()->setPaintDevice(&printer);
    QTextFrameFormat format = document->rootFrame()->frameFormat();
    format.setMargin(int((2 / 2.54) * printer.logicalDpiY()));
    document->rootFrame()->setFrameFormat(format);
    const QSizeF size(printer.width(), printer.height());
    document->setPageSize(size);
    QImage image(size.toSize(), QImage::Format_ARGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.translate(0, -size.height() * (page - 1));
    document->drawContents(&painter, QRectF(0, size.height() * (page - 1), size.width(), size.height()));
    return image;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication application(argc, argv);
    QTemporaryDir config;
    qputenv("XDG_CONFIG_HOME", config.path().toLocal8Bit());
    const QString out = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QDir::tempPath();
    for (const QString &language : {QStringLiteral("en"), QStringLiteral("zh_CN"), QStringLiteral("de")}) {
        app::MainWindow window;
        app::Settings settings = window.settings();
        settings.uiLanguage = language;
        window.applySettings(settings);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        window.resize(1280, 800);
        window.show();
        if (!window.openProject(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml")))
            return 1;
        model::ProjectModel &model = window.projectModel();

        const auto list = window.globalListCommands().add(QStringLiteral("IO"));
        auto *lists = qobject_cast<editors::GlobalListEditor *>(window.documents().openGlobalList(*list));
        lists->addRow();
        lists->addRow();
        editors::DeclarationTableModel *rows = lists->tableModel();
        rows->setData(rows->index(0, int(editors::DeclarationColumn::Address)), QStringLiteral("%IX0.0"));
        rows->setData(rows->index(1, int(editors::DeclarationColumn::Class)), QStringLiteral("VAR_GLOBAL RETAIN"));
        rows->setData(rows->index(1, int(editors::DeclarationColumn::Type)), QStringLiteral("INT"));
        rows->setData(rows->index(1, int(editors::DeclarationColumn::Name)), QStringLiteral("1Level")); // a message
        save(&window, out, QStringLiteral("globallist"), language);

        auto *tasks = qobject_cast<editors::ConfigurationEditor *>(
            window.documents().openConfiguration(model.project().instances.configurations.at(0).name));
        tasks->taskTable()->addRow();
        tasks->showTask({}, QStringLiteral("MainTask")); // with the programs it runs
        save(&window, out, QStringLiteral("tasks"), language);

        window.searchActions().findInProject({QStringLiteral("Level")});
        save(&window, out, QStringLiteral("findinproject"), language);

        window.libraryPane().selectEntry(QStringLiteral("TON"));
        save(&window, out, QStringLiteral("library"), language);

        documentationPage(model, 3).save(QDir(out).filePath(QStringLiteral("documentation_%1.png").arg(language)));
        documentationPage(model, 1).save(QDir(out).filePath(QStringLiteral("documentation_cover_%1.png").arg(language)));
        documentationPage(model, 2).save(QDir(out).filePath(QStringLiteral("documentation_contents_%1.png").arg(language)));
        // Diagrams in the documentation: an LD and an FBD body as their editors draw them.
        for (const char *example : {"motor_start_stop", "staggered_fans"}) {
            model::plcopen::ReadResult read
                = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/%1.xml").arg(QLatin1String(example)));
            if (!read.ok)
                return 1;
            model::ProjectModel diagrams;
            diagrams.reset(std::move(read.project));
            documentationPage(diagrams, 3)
                .save(QDir(out).filePath(QStringLiteral("documentation_%1_%2.png").arg(QLatin1String(example), language)));
        }
    }
    return 0;
}
