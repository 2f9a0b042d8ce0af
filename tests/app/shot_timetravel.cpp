// Not a test: pictures of the Trace pane (two cursors) and of the mixing-tank chart shown in
// the past, in each UI language, for looking at. Offscreen, so it runs without a display.
//   build/test/tests/app/shot_timetravel OUT_DIR
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/online/historybar.h"
#include "app/online/onlinecontroller.h"
#include "app/online/tracepane.h"
#include "app/online/watchpane.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/sfc/sfceditor.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QSlider>
#include <QTemporaryDir>

namespace {

struct Input {
    int cycle;
    const char *name;
    const char *value;
};

const Input kInputs[] = {{1, "Tank.MixTime", "T#1s"}, {2, "Tank.SB1", "TRUE"},   {5, "Tank.SB1", "FALSE"},
                         {30, "Tank.L3", "TRUE"},     {60, "Tank.L2", "TRUE"},   {90, "Tank.L1", "TRUE"},
                         {250, "Tank.L1", "FALSE"},   {270, "Tank.L2", "FALSE"}, {300, "Tank.L3", "FALSE"}};

} // namespace

int main(int argc, char *argv[])
{
    QApplication application(argc, argv);
    QTemporaryDir config;
    qputenv("XDG_CONFIG_HOME", config.path().toLocal8Bit());
    const QDir out(argc > 1 ? QString::fromLocal8Bit(argv[1]) : QDir::tempPath());
    for (const QString &language : {QStringLiteral("en"), QStringLiteral("zh_CN"), QStringLiteral("de")}) {
        iec::app::MainWindow window;
        iec::app::Settings settings = window.settings();
        settings.uiLanguage = language;
        window.applySettings(settings);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        window.resize(1500, 980);
        window.show();
        if (!window.openProject(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml")))
            return 1;
        const iec::model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
        QWidget *document = window.documents().openBody({main->id, iec::model::BodyRef::Part::Pou, {}});
        auto *chart = document->findChild<iec::editors::sfc::SfcEditor *>();
        for (const char *name : {"Tank.Y1", "Tank.Y2", "Tank.M", "Tank.Y3", "Tank.Mixing.T"})
            window.watchPane().model().addName(QString::fromLatin1(name));
        iec::model::SavedTrace trace;
        trace.variables = {QStringLiteral("Tank.L1"), QStringLiteral("Tank.Y1"), QStringLiteral("Tank.Y2"),
                           QStringLiteral("Tank.M"), QStringLiteral("Tank.Y3"), QStringLiteral("Tank.Mixing.T")};
        window.tracePane().setSettings(trace);
        window.online().setThreaded(false);
        window.online().login();
        for (int cycle = 1; cycle <= 400; ++cycle) {
            for (const Input &input : kInputs)
                if (input.cycle == cycle)
                    window.online().write(QString::fromLatin1(input.name), QString::fromLatin1(input.value));
            window.online().singleCycle();
        }
        for (QDockWidget *dock : window.findChildren<QDockWidget *>())
            if (dock->objectName() == QLatin1String("traceDock"))
                dock->raise();
        QCoreApplication::processEvents();
        const iec::app::TraceData &data = window.tracePane().data();
        window.tracePane().chart()->setCursor(0, data.timeMs(91));
        window.tracePane().chart()->setCursor(1, data.timeMs(191));
        QCoreApplication::processEvents();
        window.grab().save(out.filePath(QStringLiteral("trace_%1.png").arg(language)));
        QString error;
        window.tracePane().exportTo(out.filePath(QStringLiteral("trace_export_%1.png").arg(language)), error);
        window.tracePane().exportTo(out.filePath(QStringLiteral("trace_export_%1.pdf").arg(language)), error);
        window.historyBar().slider()->setValue(123);
        // The step active at scan 123 in view.
        chart->select({chart->stepId(QStringLiteral("Mixing"))});
        if (!chart->scene()->selectedItems().isEmpty())
            chart->view()->centerOn(chart->scene()->selectedItems().front());
        QCoreApplication::processEvents();
        window.grab().save(out.filePath(QStringLiteral("history_%1.png").arg(language)));
        window.online().logout();
    }
    return 0;
}
