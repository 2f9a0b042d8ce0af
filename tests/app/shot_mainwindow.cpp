// Not a test: renders the main window with the example project open, in each UI language, to
// PNG files for looking at (scripts/screenshots.sh). Offscreen, so it runs without a display.
#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "editors/text/codeeditor.h"
#include "app/mainwindow.h"
#include "app/online/debugcontroller.h"
#include "app/online/onlinecontroller.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"

#include <QApplication>
#include <QDir>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTemporaryDir>

int main(int argc, char *argv[])
{
    QApplication application(argc, argv);
    QTemporaryDir config;
    qputenv("XDG_CONFIG_HOME", config.path().toLocal8Bit());
    const QString outDir = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QDir::tempPath();
    const QString project = argc > 2 ? QString::fromLocal8Bit(argv[2])
                                     : QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml");
    for (const QString &language : {QStringLiteral("en"), QStringLiteral("zh_CN"), QStringLiteral("de")}) {
        iec::app::MainWindow window;
        iec::app::Settings settings = window.settings();
        settings.uiLanguage = language;
        window.applySettings(settings);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        window.resize(1280, 800);
        window.show();
        if (!window.openProject(project))
            return 1;
        auto *tree = static_cast<const iec::app::ProjectTreeModel *>(window.projectTree().model());
        const QModelIndex firstPou = tree->index(0, 0, tree->index(0, 0));
        if (const auto body = tree->bodyRef(firstPou)) {
            window.documents().openBody(*body);
            // IEC_SHOT_TYPO=1 adds a misspelt name and builds, to show how errors look.
            if (qEnvironmentVariableIsSet("IEC_SHOT_TYPO")) {
                auto *editor = window.documents().textEditorFor(*body);
                editor->appendPlainText(QStringLiteral("Countr := 0;"));
                window.buildController().build();
            }
            // IEC_SHOT_HALT=1 puts a breakpoint on the place at the cursor (line 3 of a text body,
            // the first network of a diagram), logs in and runs a cycle, which halts there.
            if (qEnvironmentVariableIsSet("IEC_SHOT_HALT")) {
                window.online().setThreaded(false);
                if (auto *editor = window.documents().textEditorFor(*body))
                    editor->goToLine(3);
                window.debugger().toggleBreakpointAtCursor();
                window.online().login();
                window.online().singleCycle();
            }
        }
        QCoreApplication::processEvents();
        window.grab().save(QDir(outDir).filePath(QStringLiteral("mainwindow_%1.png").arg(language)));
        // The menus too, to check that their items are translated and fit.
        for (QMenu *menu : window.menuBar()->findChildren<QMenu *>(QString(), Qt::FindDirectChildrenOnly)) {
            if (menu->objectName().isEmpty())
                continue;
            menu->popup(window.mapToGlobal(QPoint(0, 0)));
            QCoreApplication::processEvents();
            menu->grab().save(
                QDir(outDir).filePath(QStringLiteral("menu_%1_%2.png").arg(menu->objectName(), language)));
            menu->hide();
        }
    }
    return 0;
}
