// Loaded into the real iecstudio executable with LD_PRELOAD by tst_recovery; it drives the window
// only through what a user reaches (the project tree, the body editor, the recovery question,
// File → Save), so the application needs no test hook. A startup function (run when the
// QApplication is created) starts a timer that plays one part, chosen by IEC_RECOVERY_DRIVER:
//   edit     opens Main from the project tree and types IEC_RECOVERY_MARKER at the start of its
//            body, then waits to be killed;
//   recover  answers the recovery question with Recover, saves with File → Save and quits.
// What it did goes to stderr as "driver: ..." lines, for the test's messages.
#include <QAbstractItemModel>
#include <QAction>
#include <QApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTextCursor>
#include <QTimer>
#include <QTreeView>

#include <cstdio>
#include <deque>
#include <memory>

namespace {

void say(const QString &what)
{
    std::fprintf(stderr, "driver: %s\n", qPrintable(what));
}

QMainWindow *mainWindow()
{
    for (QWidget *widget : QApplication::topLevelWidgets()) {
        if (widget->objectName() == QLatin1String("MainWindow") && widget->isVisible())
            return qobject_cast<QMainWindow *>(widget);
    }
    return nullptr;
}

// The first item of the tree (breadth first) named `text` (the name is the edit role: the display
// adds the kind, "Main (PRG)").
QModelIndex findItem(const QAbstractItemModel &model, const QString &text)
{
    std::deque<QModelIndex> pending {QModelIndex()};
    while (!pending.empty()) {
        const QModelIndex parent = pending.front();
        pending.pop_front();
        for (int row = 0; row < model.rowCount(parent); ++row) {
            const QModelIndex index = model.index(row, 0, parent);
            if (index.data(Qt::EditRole).toString() == text)
                return index;
            pending.push_back(index);
        }
    }
    return {};
}

bool insideDeclarations(const QWidget *widget)
{
    for (const QWidget *w = widget; w; w = w->parentWidget()) {
        if (w->objectName() == QLatin1String("declarationEditor"))
            return true;
    }
    return false;
}

// The body editor of the current document.
QPlainTextEdit *bodyEditor(QMainWindow &window)
{
    auto *documents = window.findChild<QTabWidget *>(QStringLiteral("documentArea"));
    if (!documents || !documents->currentWidget())
        return nullptr;
    for (QPlainTextEdit *editor : documents->currentWidget()->findChildren<QPlainTextEdit *>()) {
        if (editor->isVisible() && !editor->isReadOnly() && !insideDeclarations(editor))
            return editor;
    }
    return nullptr;
}

QAction *saveAction(QMainWindow &window)
{
    auto *fileMenu = window.findChild<QMenu *>(QStringLiteral("fileMenu"));
    for (QAction *action : fileMenu ? fileMenu->actions() : QList<QAction *>()) {
        if (action->shortcut() == QKeySequence(QKeySequence::Save))
            return action;
    }
    return nullptr;
}

// One step of the edit part; true when it is done.
bool editStep(int &stage)
{
    QMainWindow *window = mainWindow();
    if (!window)
        return false;
    if (stage == 0) {
        auto *tree = window->findChild<QTreeView *>(QStringLiteral("projectTree"));
        const QModelIndex main = tree && tree->model() ? findItem(*tree->model(), QStringLiteral("Main")) : QModelIndex();
        if (!main.isValid())
            return false;
        tree->setCurrentIndex(main);
        Q_EMIT tree->activated(main); // what a double click or Enter does
        say(QStringLiteral("opened Main"));
        stage = 1;
        return false;
    }
    QPlainTextEdit *editor = bodyEditor(*window);
    if (!editor)
        return false;
    QTextCursor cursor(editor->document());
    cursor.movePosition(QTextCursor::Start);
    editor->setTextCursor(cursor);
    editor->textCursor().insertText(qEnvironmentVariable("IEC_RECOVERY_MARKER"));
    say(QStringLiteral("typed the marker"));
    return true;
}

// One step of the recover part; true when it is done.
bool recoverStep(int &stage)
{
    if (stage == 0) {
        auto *question = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!question)
            return false;
        for (QAbstractButton *button : question->buttons()) {
            if (button->text() == QLatin1String("&Recover")) {
                say(QStringLiteral("answered Recover"));
                stage = 1;
                button->click();
                return false;
            }
        }
        return false;
    }
    QMainWindow *window = mainWindow();
    if (!window || QApplication::activeModalWidget())
        return false;
    QAction *save = saveAction(*window);
    if (!save)
        return false;
    save->trigger();
    say(QStringLiteral("saved"));
    QCoreApplication::exit(0);
    return true;
}

void start()
{
    const QString part = qEnvironmentVariable("IEC_RECOVERY_DRIVER");
    if (part != QLatin1String("edit") && part != QLatin1String("recover"))
        return;
    auto *timer = new QTimer(QCoreApplication::instance());
    auto stage = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, part, stage] {
        if (part == QLatin1String("edit") ? editStep(*stage) : recoverStep(*stage))
            timer->stop();
    });
    timer->start(50);
}

} // namespace

Q_COREAPP_STARTUP_FUNCTION(start)
