// Not a test: pictures of the SFC editor in the window, for looking at (issue 13): the window at
// 1600 px with a chart (is every tool bar command on the bar?), the context menu of a
// right-clicked step, the IEC Actions dialog, and the chart online with S and R actions on two
// steps. Offscreen, so it runs without a display:
//   build/test/tests/app/shot_sfc OUT_DIR [PROJECT (mixing_tank.xml)] [STEP (FillA)] [START (Tank.SB1)]
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/online/onlinecontroller.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/sfc/sfceditor.h"
#include "interpreter/runtime/snapshot.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QContextMenuEvent>
#include <QDir>
#include <QPainter>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>

#include <cstdio>

namespace {

using iec::editors::sfc::SfcEditor;

QString g_outDir;

void save(const QPixmap &picture, const QString &name)
{
    const QString path = QDir(g_outDir).filePath(name);
    picture.save(path);
    std::printf("%s\n", qPrintable(path));
}

// The window with a popup or dialog drawn where it is on the screen.
QPixmap windowWith(QWidget &window, QWidget *top)
{
    QPixmap picture = window.grab();
    if (top) {
        QPainter painter(&picture);
        painter.drawPixmap(window.mapFromGlobal(top->mapToGlobal(QPoint(0, 0))), top->grab());
    }
    return picture;
}

// Runs `open` (which shows a popup or a modal dialog and waits), saves the picture once it is up
// and closes it.
void shootModal(QWidget &window, const QString &name, const std::function<void()> &open)
{
    QTimer::singleShot(300, [&window, name] {
        QWidget *top = QApplication::activePopupWidget();
        if (!top)
            top = QApplication::activeModalWidget();
        if (!top) {
            std::printf("nothing opened for %s\n", qPrintable(name));
            return;
        }
        save(top->grab(), name + QStringLiteral(".png"));
        save(windowWith(window, top), name + QStringLiteral("_window.png"));
        top->close();
    });
    open();
}

void reportToolBar(SfcEditor &editor)
{
    auto *bar = editor.findChild<QToolBar *>(QStringLiteral("diagramToolBar"));
    QStringList hidden;
    for (QAction *action : bar->actions()) {
        QWidget *button = bar->widgetForAction(action);
        if (!action->isSeparator() && (!button || !button->isVisible()))
            hidden << action->objectName();
    }
    std::printf("tool bar %d px wide; in the overflow: %s\n", bar->width(), qPrintable(hidden.join(QLatin1Char(' '))));
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication application(argc, argv);
    QTemporaryDir config;
    qputenv("XDG_CONFIG_HOME", config.path().toLocal8Bit());
    g_outDir = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QDir::tempPath();
    QDir().mkpath(g_outDir);
    const QString project = argc > 2 ? QString::fromLocal8Bit(argv[2])
                                     : QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml");
    const QString stepName = argc > 3 ? QString::fromLocal8Bit(argv[3]) : QStringLiteral("FillA");
    const QString start = argc > 4 ? QString::fromLocal8Bit(argv[4]) : QStringLiteral("Tank.SB1");
    for (const QString &language : {QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("zh_CN")}) {
        iec::app::MainWindow window;
        iec::app::Settings settings = window.settings();
        settings.uiLanguage = language;
        window.applySettings(settings);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        window.online().setThreaded(false);
        window.resize(1600, 900);
        window.show();
        if (!window.openProject(project))
            return 1;
        const iec::model::Pou *chart = nullptr;
        for (const iec::model::Pou &pou : window.projectModel().project().types.pous)
            if (pou.language() == iec::model::BodyLanguage::SFC && !chart)
                chart = &pou;
        if (!chart)
            return 2;
        window.documents().openBody({chart->id, iec::model::BodyRef::Part::Pou, {}});
        auto *editor = qobject_cast<SfcEditor *>(window.documents().currentDiagramEditor());
        if (!editor)
            return 3;
        QCoreApplication::processEvents();
        save(window.grab(), QStringLiteral("sfc_window_%1.png").arg(language));
        reportToolBar(*editor);

        const quint64 step = editor->stepId(stepName);
        iec::editors::DiagramView *view = editor->view();
        const QPoint at = view->mapFromScene(editor->scene()->itemFor(step)->frame().center());
        // A right-click: the press selects, the context menu event opens the menu (as the
        // platform sends it; QTest's click does not).
        shootModal(window, QStringLiteral("sfc_contextmenu_%1").arg(language), [&] {
            QTest::mouseClick(view->viewport(), Qt::RightButton, {}, at);
            QContextMenuEvent event(QContextMenuEvent::Mouse, at, view->viewport()->mapToGlobal(at));
            QApplication::sendEvent(view->viewport(), &event);
        });
        editor->select({step});
        shootModal(window, QStringLiteral("sfc_iecactions_%1").arg(language),
            [&] { editor->trigger(QStringLiteral("sfcActions")); });

        // Online: the start button pressed, the chart moves on to the step that stores an action.
        if (!window.online().login())
            return 4;
        window.online().singleCycle();
        window.online().write(start, QStringLiteral("TRUE"));
        window.online().singleCycle();
        window.online().write(start, QStringLiteral("FALSE"));
        window.online().singleCycle();
        editor->select({});
        QCoreApplication::processEvents();
        save(window.grab(), QStringLiteral("sfc_online_%1.png").arg(language));
        window.online().logout();
    }
    return 0;
}
