#include "app/mainwindow.h"

#include "app/buildcontroller.h"
#include "app/diagrammenus.h"
#include "app/documentarea.h"
#include "app/editactions.h"
#include "app/librarypane.h"
#include "app/livediagnostics.h"
#include "app/searchactions.h"
#include "app/searchresultspane.h"
#include "app/globallistcommands.h"
#include "app/importexport.h"
#include "app/importexportactions.h"
#include "app/listmenus.h"
#include "app/messagespane.h"
#include "app/newprojectdialog.h"
#include "app/online/debugcontroller.h"
#include "app/online/historybar.h"
#include "app/online/onlinecontroller.h"
#include "app/online/watchpane.h"
#include "app/projectcommands.h"
#include "app/projecttreeactions.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/recentfiles.h"
#include "app/recoverymanager.h"
#include "app/settingsdialog.h"
#include "app/uitranslator.h"
#include "app/undoactions.h"
#include "app/undostacks.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/common/diagrameditor.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QUndoGroup>

namespace iec::app {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_projectModel(new model::ProjectModel(this))
    , m_undoStacks(new UndoStacks(this))
    , m_projectCommands(std::make_unique<ProjectCommands>(*m_projectModel, m_undoStacks->projectStack()))
    , m_globalListCommands(std::make_unique<GlobalListCommands>(*m_projectModel, m_undoStacks->projectStack()))
    , m_recovery(new RecoveryManager(this))
    , m_translator(new UiTranslator(this))
    , m_settings(Settings::load(QSettings()))
{
    setObjectName(QStringLiteral("MainWindow"));
    m_documents = new DocumentArea(*m_projectModel, this);
    m_documents->setObjectName(QStringLiteral("documentArea"));
    setCentralWidget(m_documents);
    m_projectCommands->setFlushPendingEdits([this] { m_documents->flushEdits(); });
    // Modified = some undo stack left its clean state, or typing (which has no stack) is unsaved.
    connect(m_projectModel, &model::ProjectModel::projectReset, this, &MainWindow::updateWindowTitle);
    connect(m_undoStacks, &UndoStacks::cleanChanged, this, &MainWindow::updateWindowTitle);
    connect(m_documents, &DocumentArea::typingModifiedChanged, this, &MainWindow::updateWindowTitle);
    connect(m_recovery, &RecoveryManager::autosaveDue, this, &MainWindow::autosave);

    createActions();
    createDocks();
    createMenus();
    createToolBar();
    connect(m_documents, &QTabWidget::currentChanged, this, &MainWindow::updateActiveUndoStack);
    connect(qApp, &QApplication::focusChanged, this, &MainWindow::updateActiveUndoStack);
    // While a diagram editor is the current tab, its commands join the Insert, Edit and View
    // menus (CODESYS puts them there) and its zoom shows in the status bar.
    m_diagramMenus = new DiagramMenus(*m_documents, *m_insertMenu, *m_editMenu, *m_viewMenu, *statusBar(), this);
    // Online nothing of the project may change: the editors only show, the tree's commands,
    // Import and Undo/Redo are off, and the status bar says how to edit again.
    const auto sayLogOutToEdit = [this] { statusBar()->showMessage(tr("Log out to edit (Online → Logout)."), 10000); };
    // (The controller's "Logged in" message already says how.)
    connect(m_online, &OnlineController::onlineChanged, this, [this](bool online) {
        m_treeActions->setLocked(online);
        m_undoActions->setLocked(online);
        m_documents->setEditingLocked(online);
        m_importExport->importAction()->setEnabled(!online);
    });
    connect(m_treeActions, &ProjectTreeActions::editRefused, this, sayLogOutToEdit);
    connect(m_documents, &DocumentArea::editRefused, this, sayLogOutToEdit);
    statusBar();
    applyUiLanguage(m_settings.uiLanguage);
    m_recovery->setIntervalMinutes(m_settings.autosaveMinutes);
    m_documents->setGridSize(m_settings.gridSize);
    retranslateUi();
    resize(1200, 800);
    restoreWindowLayout();
}

MainWindow::~MainWindow()
{
    // The children are destroyed after this destructor has run; signals they send on the way
    // (a closing tab changes the current one, focus moves) must not reach this half-gone window.
    disconnect(qApp, nullptr, this, nullptr);
    // Online: the runtime thread ends and the editors are given back while they all still exist.
    m_online->logout();
    m_documents->disconnect(m_online);
    m_documents->disconnect(this);
    m_undoStacks->disconnect(this);
}

QUndoGroup &MainWindow::undoGroup()
{
    return m_undoStacks->group();
}

void MainWindow::createActions()
{
    const QStyle *style = this->style();
    m_newAction = new QAction(
        QIcon::fromTheme(QStringLiteral("document-new"), style->standardIcon(QStyle::SP_FileIcon)), QString(), this);
    m_newAction->setShortcut(QKeySequence::New);
    connect(m_newAction, &QAction::triggered, this, &MainWindow::newProjectInteractive);
    m_openAction = new QAction(
        QIcon::fromTheme(QStringLiteral("document-open"), style->standardIcon(QStyle::SP_DialogOpenButton)), QString(),
        this);
    m_openAction->setShortcut(QKeySequence::Open);
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openProjectInteractive);
    m_saveAction = new QAction(
        QIcon::fromTheme(QStringLiteral("document-save"), style->standardIcon(QStyle::SP_DialogSaveButton)), QString(),
        this);
    m_saveAction->setShortcut(QKeySequence::Save);
    connect(m_saveAction, &QAction::triggered, this, &MainWindow::saveInteractive);
    m_saveAsAction = new QAction(this);
    m_saveAsAction->setShortcut(QKeySequence::SaveAs);
    connect(m_saveAsAction, &QAction::triggered, this, &MainWindow::saveAsInteractive);
    m_quitAction = new QAction(this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    // Undo and redo follow whichever stack (project or POU) is active in the group.
    m_undoActions = new UndoActions(m_undoStacks->group(), this);

    // Build and the online commands get their behaviour with the compiler and the runtime;
    // until then they are shown, disabled, so the menus already have their final shape.
    m_buildAction = new QAction(style->standardIcon(QStyle::SP_DialogApplyButton), QString(), this);
    m_buildAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    m_loginAction = new QAction(style->standardIcon(QStyle::SP_MediaPlay), QString(), this);
    m_loginAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_loginAction->setEnabled(false);
    m_stopAction = new QAction(style->standardIcon(QStyle::SP_MediaStop), QString(), this);
    m_stopAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    m_stopAction->setEnabled(false);
    m_singleCycleAction = new QAction(this);
    m_singleCycleAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F5)); // F8 is Step Into, as in CODESYS
    m_singleCycleAction->setEnabled(false);

    m_settingsAction = new QAction(this);
    m_settingsAction->setMenuRole(QAction::PreferencesRole);
    connect(m_settingsAction, &QAction::triggered, this, &MainWindow::showSettingsDialog);

    m_aboutAction = new QAction(this);
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::showAboutBox);
    m_aboutQtAction = new QAction(this);
    m_aboutQtAction->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQtAction, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::createMenus()
{
    const auto addMenu = [this](const char *objectName) {
        QMenu *menu = menuBar()->addMenu(QString());
        menu->setObjectName(QString::fromLatin1(objectName));
        return menu;
    };
    m_fileMenu = addMenu("fileMenu");
    m_fileMenu->addAction(m_newAction);
    m_fileMenu->addAction(m_openAction);
    m_recentMenu = new RecentFilesMenu(this);
    connect(m_recentMenu, &RecentFilesMenu::fileChosen, this, &MainWindow::openRecentInteractive);
    m_fileMenu->addMenu(m_recentMenu);
    m_fileMenu->addAction(m_saveAction);
    m_fileMenu->addAction(m_saveAsAction);
    m_fileMenu->addSeparator();
    m_importExport = new ImportExportActions(
        *m_projectModel, m_undoStacks->projectStack(), *m_messages, *m_projectTree, this);
    m_importExport->setFlushPendingEdits([this] { m_documents->flushEdits(); });
    m_fileMenu->addAction(m_importExport->importAction());
    m_fileMenu->addAction(m_importExport->exportAction());
    m_fileMenu->addAction(m_importExport->exportSelectionAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_editMenu = addMenu("editMenu");
    m_editMenu->addAction(m_undoActions->undoAction());
    m_editMenu->addAction(m_undoActions->redoAction());

    m_viewMenu = addMenu("viewMenu");
    m_viewMenu->addAction(m_projectDock->toggleViewAction());
    m_viewMenu->addAction(m_messagesDock->toggleViewAction());
    m_viewMenu->addAction(m_watchDock->toggleViewAction());
    m_viewMenu->addAction(m_traceDock->toggleViewAction());
    m_viewMenu->addAction(m_historyBar->toggleViewAction());

    // CODESYS inserts objects through the Insert menu; here they are the tree's add commands.
    m_insertMenu = addMenu("insertMenu");
    m_insertMenu->addAction(m_treeActions->addPouAction());
    m_insertMenu->addAction(m_treeActions->addActionAction());
    m_insertMenu->addAction(m_treeActions->addTransitionAction());
    m_insertMenu->addAction(m_treeActions->addMethodAction());
    m_insertMenu->addAction(m_treeActions->addPropertyAction());
    m_insertMenu->addAction(m_treeActions->addInterfaceAction());
    m_insertMenu->addAction(m_treeActions->addGlobalListAction());

    m_projectMenu = addMenu("projectMenu");
    m_treeActions->addTo(m_projectMenu);
    m_projectMenu->addSeparator();
    m_projectMenu->addAction(m_buildAction);
    m_projectMenu->addSeparator();
    m_projectMenu->addAction(m_settingsAction);

    m_onlineMenu = addMenu("onlineMenu");
    m_onlineMenu->addAction(m_loginAction);
    m_onlineMenu->addAction(m_stopAction);
    m_onlineMenu->addAction(m_singleCycleAction);
    m_online->addTo(m_onlineMenu);
    m_debug->addTo(m_onlineMenu, nullptr);

    m_windowMenu = new WindowMenu(*m_documents, this);
    menuBar()->addMenu(m_windowMenu);

    m_helpMenu = addMenu("helpMenu");
    m_examplesMenu = new ExamplesMenu(this);
    connect(m_examplesMenu, &ExamplesMenu::exampleChosen, this, &MainWindow::openExampleInteractive);
    m_helpMenu->addMenu(m_examplesMenu);
    m_helpMenu->addSeparator();
    m_helpMenu->addAction(m_aboutAction);
    m_helpMenu->addAction(m_aboutQtAction);
    extendMenus();
}

void MainWindow::createToolBar()
{
    m_toolBar = addToolBar(QString());
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    m_toolBar->addAction(m_newAction);
    m_toolBar->addAction(m_openAction);
    m_toolBar->addAction(m_saveAction);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_undoActions->undoAction());
    m_toolBar->addAction(m_undoActions->redoAction());
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_buildAction);
    m_toolBar->addAction(m_loginAction);
    m_toolBar->addAction(m_stopAction);
    m_toolBar->addAction(m_singleCycleAction);
    m_toolBar->addAction(m_debug->stepOverAction());
    m_toolBar->addAction(m_debug->stepIntoAction());
    m_toolBar->addAction(m_debug->stepOutAction());
    addToolBarBreak();
    addToolBar(m_historyBar);
}

void MainWindow::createDocks()
{
    m_projectTreeModel = new ProjectTreeModel(*m_projectModel, this);
    m_projectTree = new ProjectTreeView(this);
    m_projectTree->setObjectName(QStringLiteral("projectTree"));
    m_projectTree->setProjectModel(m_projectTreeModel);
    connect(m_projectTree, &ProjectTreeView::openRequested, m_documents, &DocumentArea::openBody);
    connect(m_projectTree, &ProjectTreeView::openDataTypeRequested, m_documents, &DocumentArea::openDataType);
    connect(m_projectTree, &ProjectTreeView::openMemberRequested, m_documents, &DocumentArea::openMember);
    connect(m_projectTree, &ProjectTreeView::openInterfaceRequested, m_documents, &DocumentArea::openInterface);
    m_treeActions
        = new ProjectTreeActions(*m_projectCommands, *m_globalListCommands, *m_projectModel, *m_projectTree, this);
    connectInstanceDocuments();
    connect(m_treeActions, &ProjectTreeActions::memberCreated, m_documents, &DocumentArea::openMember);
    connect(m_treeActions, &ProjectTreeActions::interfaceCreated, m_documents, &DocumentArea::openInterface);
    connect(m_treeActions, &ProjectTreeActions::created, this, [this](const model::BodyRef &item) {
        m_projectTree->selectKey(item.part == model::BodyRef::Part::Pou ? ProjectTreeModel::pouKey(item.pou)
                                                                        : ProjectTreeModel::partKey(item));
        m_documents->openBody(item);
    });
    m_projectDock = new QDockWidget(this);
    m_projectDock->setObjectName(QStringLiteral("projectDock"));
    m_projectDock->setWidget(m_projectTree);
    addDockWidget(Qt::LeftDockWidgetArea, m_projectDock);

    m_messages = new MessagesPane(this);
    m_messages->setObjectName(QStringLiteral("messages"));
    m_messagesDock = new QDockWidget(this);
    m_messagesDock->setObjectName(QStringLiteral("messagesDock"));
    m_messagesDock->setWidget(m_messages);
    addDockWidget(Qt::BottomDockWidgetArea, m_messagesDock);

    m_build = new BuildController(*m_projectModel, *m_documents, *m_messages, this);
    connect(m_buildAction, &QAction::triggered, m_build, [this] { m_build->build(); });
    connect(m_build, &BuildController::built, this, [this](int errors, int warnings) {
        m_messagesDock->show();
        statusBar()->showMessage(tr("Build finished. Errors: %1, warnings: %2.").arg(errors).arg(warnings));
    });

    m_watch = new WatchPane(this);
    m_watch->setObjectName(QStringLiteral("watch"));
    m_watchDock = new QDockWidget(this);
    m_watchDock->setObjectName(QStringLiteral("watchDock"));
    m_watchDock->setWidget(m_watch);
    addDockWidget(Qt::BottomDockWidgetArea, m_watchDock);
    m_online = new OnlineController(*m_projectModel, *m_documents, *m_messages, *m_build, *m_watch, *statusBar(),
        {m_loginAction, m_stopAction, m_singleCycleAction}, this);
    m_debug = new DebugController(*m_projectModel, *m_documents, *m_online, *m_messages, *statusBar(), this);
    createProjectTools();
    createTraceTools();
}

void MainWindow::retranslateUi()
{
    updateWindowTitle();
    m_fileMenu->setTitle(tr("&File"));
    m_editMenu->setTitle(tr("&Edit"));
    m_viewMenu->setTitle(tr("&View"));
    m_insertMenu->setTitle(tr("&Insert"));
    m_projectMenu->setTitle(tr("&Project"));
    m_onlineMenu->setTitle(tr("&Online"));
    m_windowMenu->setTitle(tr("&Window"));
    m_helpMenu->setTitle(tr("&Help"));
    m_recentMenu->setTitle(tr("Recent &Projects"));
    m_examplesMenu->setTitle(tr("&Examples"));
    m_toolBar->setWindowTitle(tr("Toolbar"));
    m_windowMenu->retranslate();
    m_diagramMenus->retranslate();
    m_treeActions->retranslate();
    m_undoActions->retranslate();
    m_importExport->retranslate();

    m_newAction->setText(tr("&New Project"));
    m_openAction->setText(tr("&Open..."));
    m_saveAction->setText(tr("&Save"));
    m_saveAsAction->setText(tr("Save &As..."));
    m_quitAction->setText(tr("&Quit"));
    m_buildAction->setText(tr("&Build"));
    m_settingsAction->setText(tr("&Settings..."));
    m_loginAction->setText(tr("Login and &Run"));
    m_stopAction->setText(tr("&Stop"));
    m_singleCycleAction->setText(tr("Single &Cycle"));
    m_aboutAction->setText(tr("&About IEC Studio"));
    m_aboutQtAction->setText(tr("About &Qt"));

    m_projectDock->setWindowTitle(tr("Project"));
    m_messagesDock->setWindowTitle(tr("Messages"));
    m_watchDock->setWindowTitle(tr("Watch"));
    m_online->retranslate();
    m_debug->retranslate();
    retranslateProjectTools();
    retranslateTraceTools();
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QMainWindow::changeEvent(event);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    // Saved or discarded on purpose: nothing to recover from this session.
    m_recovery->discardCurrent();
    saveWindowLayout();
    QMainWindow::closeEvent(event);
}

bool MainWindow::hasUnsavedChanges() const
{
    return !m_undoStacks->isClean() || m_documents->hasUnsavedTyping() || m_recoveredUnsaved;
}

void MainWindow::updateWindowTitle()
{
    // The project's own name (contentHeader) first, then the file it is stored in.
    const QString projectName = m_projectModel->project().contentHeader.name;
    const QString fileName = QFileInfo(m_currentFile).fileName();
    QString name;
    if (projectName.isEmpty())
        name = fileName.isEmpty() ? tr("Untitled") : fileName;
    else
        name = fileName.isEmpty() ? projectName : tr("%1 (%2)").arg(projectName, fileName);
    // [*] is where Qt shows the modified marker.
    setWindowTitle(tr("%1[*] - IEC Studio").arg(name));
    setWindowModified(hasUnsavedChanges());
}

void MainWindow::updateActiveUndoStack()
{
    QWidget *focus = QApplication::focusWidget();
    const bool treeHasFocus = focus && (focus == m_projectTree || m_projectTree->isAncestorOf(focus));
    const std::optional<model::BodyRef> document = m_documents->currentBody();
    // The declaration text being typed (a POU's or a global list's) undoes its own typing, as its
    // Ctrl+Z does; the table beside it undoes the commands of its stack.
    editors::DeclarationEditorBase *declarations = nullptr;
    for (QWidget *widget = focus; widget && !declarations; widget = widget->parentWidget())
        declarations = qobject_cast<editors::DeclarationEditorBase *>(widget);
    QPlainTextEdit *declarationText = declarations && focus == declarations->textEditor() ? declarations->textEditor() : nullptr;
    if (treeHasFocus || !document) {
        m_undoStacks->activateProjectStack();
        m_undoActions->setTextEditor(treeHasFocus ? nullptr : declarationText);
        return;
    }
    m_undoStacks->activatePouStack(document->pou);
    // In the body the text editor's own history undoes, as long as typing is not yet a command.
    m_undoActions->setTextEditor(declarations ? declarationText : m_documents->textEditorFor(*document));
}

namespace {

QList<Message> messagesOf(const std::vector<model::Diagnostic> &diagnostics, const QString &fileName)
{
    QList<Message> messages;
    for (const model::Diagnostic &diagnostic : diagnostics) {
        // Reader diagnostics point into the file, so the location names the file and its line.
        messages.append({.severity = messageSeverity(diagnostic.severity),
            .text = diagnostic.message,
            .pouName = diagnostic.pouName.value_or(fileName),
            .line = diagnostic.line,
            .column = diagnostic.column,
            .localId = diagnostic.localId});
    }
    return messages;
}

} // namespace

bool MainWindow::loadProject(const QString &path, QString *error)
{
    model::plcopen::ReadResult result = model::plcopen::readProjectFile(path);
    const QString fileName = QFileInfo(path).fileName();
    // The messages of the project shown so far (build, runtime) say nothing about this one.
    m_messages->model().clear();
    m_messages->model().setMessages(QStringLiteral("import"), messagesOf(result.diagnostics, fileName));
    if (result.fileError || !result.isProject) {
        if (error)
            *error = result.diagnostics.empty() ? tr("%1 is not a PLCopen XML project.").arg(fileName)
                                                : result.diagnostics.front().message;
        return false;
    }
    adoptProject(std::move(result.project));
    return true;
}

bool MainWindow::loadIecText(const QString &path, QString *error)
{
    ImportExport::Read read = ImportExport::read(path);
    m_messages->model().clear();
    m_messages->model().setMessages(QStringLiteral("import"), read.messages);
    const auto firstError = std::find_if(read.messages.cbegin(), read.messages.cend(),
        [](const Message &message) { return message.severity == Message::Severity::Error; });
    if (read.project && read.whole) { // its {error} pragmas stay listed, and the build lists them again
        adoptProject(std::move(*read.project));
        return true;
    }
    // A text without a project, or with part of it not read, always comes with an error.
    if (error && firstError != read.messages.cend()) {
        const QString fileName = QFileInfo(path).fileName();
        *error = firstError->line > 0 ? tr("%1, line %2: %3").arg(fileName, QString::number(firstError->line), firstError->text)
                                      : tr("%1: %2").arg(fileName, firstError->text);
    }
    return false;
}

void MainWindow::adoptProject(model::Project project)
{
    // The project shown so far is replaced on purpose (maybeSave asked), so its recovery file goes.
    m_recovery->discardCurrent();
    m_projectModel->reset(std::move(project));
    m_undoStacks->clear();
    m_documents->markTypingSaved();
    m_recoveredUnsaved = false;
}

void MainWindow::setCurrentFile(const QString &path)
{
    m_currentFile = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    m_recovery->setProject(m_currentFile);
    if (!m_currentFile.isEmpty()) {
        QSettings store;
        RecentFiles::add(store, m_currentFile);
    }
    updateWindowTitle();
}

bool MainWindow::openProject(const QString &path, QString *error)
{
    const bool text = ImportExport::formatOf(path) == ImportExport::Format::IecText;
    if (!(text ? loadIecText(path, error) : loadProject(path, error)))
        return false;
    setCurrentFile(text ? QString() : path);
    openMainProgram();
    return true;
}

bool MainWindow::openExample(const QString &resourcePath, QString *error)
{
    if (!loadProject(resourcePath, error))
        return false;
    setCurrentFile({});
    openMainProgram();
    return true;
}

bool MainWindow::recover(const QString &recoveryFile, QString *error)
{
    const Recovery recovery = RecoveryManager::describe(recoveryFile);
    if (!loadProject(recoveryFile, error))
        return false;
    m_currentFile = recovery.projectFile;
    // Later autosaves go on in the same file; a clean save removes it.
    m_recovery->adopt(recovery);
    m_recoveredUnsaved = true;
    updateWindowTitle();
    return true;
}

bool MainWindow::saveProject(const QString &path, QString *error)
{
    m_documents->flushEdits();
    if (!model::plcopen::saveProjectFile(projectToSave(), path, error))
        return false;
    m_recovery->discardCurrent();
    m_undoStacks->setClean();
    m_documents->markTypingSaved();
    m_recoveredUnsaved = false;
    setCurrentFile(path);
    return true;
}

void MainWindow::newProject()
{
    m_recovery->discardCurrent();
    model::Project fresh;
    model::plcopen::stampCreationTime(fresh.fileHeader, QDateTime::currentDateTimeUtc());
    m_projectModel->reset(std::move(fresh));
    m_undoStacks->clear();
    m_documents->markTypingSaved();
    m_recoveredUnsaved = false;
    m_messages->model().clear();
    setCurrentFile({});
}

bool MainWindow::autosave()
{
    if (!hasUnsavedChanges()) {
        // Undone back to the saved state: an older recovery file would only bring back changes
        // the user took back.
        m_recovery->discardCurrent();
        return false;
    }
    m_documents->flushEdits();
    QString error;
    if (!m_recovery->write(m_projectModel->project(), &error)) {
        statusBar()->showMessage(tr("Autosave failed: %1").arg(error));
        return false;
    }
    return true;
}

bool MainWindow::maybeSave()
{
    m_documents->flushEdits();
    if (!hasUnsavedChanges())
        return true;
    const auto answer
        = QMessageBox::warning(this, tr("Unsaved Changes"), tr("The project has unsaved changes. Save them first?"),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveInteractive();
    return answer == QMessageBox::Discard;
}

void MainWindow::newProjectInteractive()
{
    if (!maybeSave())
        return;
    NewProjectDialog dialog(this);
    if (dialog.exec() == QDialog::Accepted)
        newProjectFromTemplate(dialog.chosen());
}

bool MainWindow::openRecent(const QString &path, QString *error)
{
    if (QFileInfo::exists(path))
        return openProject(path, error);
    QSettings store;
    RecentFiles::remove(store, path);
    if (error)
        *error = tr("%1 does not exist any more; it was removed from the recent projects.")
                     .arg(QDir::toNativeSeparators(path));
    return false;
}

void MainWindow::openRecentInteractive(const QString &path)
{
    if (QFileInfo::exists(path) && !maybeSave())
        return;
    QString error;
    if (!openRecent(path, &error))
        QMessageBox::warning(this, tr("Open Project"), error);
}

void MainWindow::openExampleInteractive(const QString &resourcePath)
{
    if (!maybeSave())
        return;
    QString error;
    if (!openExample(resourcePath, &error))
        QMessageBox::critical(this, tr("Open Project"), tr("The project could not be opened: %1").arg(error));
}

void MainWindow::offerRecoveryInteractive()
{
    for (const Recovery &recovery : RecoveryManager::pendingRecoveries()) {
        const QString project
            = recovery.projectFile.isEmpty() ? tr("(untitled)") : QDir::toNativeSeparators(recovery.projectFile);
        QMessageBox question(QMessageBox::Question, tr("Recover Project"),
            tr("IEC Studio did not close properly. Recover the autosaved changes?"), QMessageBox::NoButton, this);
        question.setInformativeText(
            tr("Project: %1\nAutosaved: %2").arg(project, QLocale().toString(recovery.savedAt, QLocale::ShortFormat)));
        QPushButton *recoverButton = question.addButton(tr("&Recover"), QMessageBox::AcceptRole);
        QPushButton *discardButton = question.addButton(QMessageBox::Discard);
        // Later keeps the file, so the next start asks again.
        question.addButton(tr("Ask &Later"), QMessageBox::RejectRole);
        question.setDefaultButton(recoverButton);
        question.exec();
        if (question.clickedButton() == discardButton)
            RecoveryManager::discard(recovery.recoveryFile);
        if (question.clickedButton() != recoverButton)
            continue;
        QString error;
        if (recover(recovery.recoveryFile, &error))
            return; // one project per window
        QMessageBox::critical(this, tr("Recover Project"), tr("The project could not be recovered: %1").arg(error));
    }
}

void MainWindow::openProjectInteractive()
{
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Project"), QFileInfo(m_currentFile).path(), tr("PLCopen XML projects (*.xml);;IEC 61131-3 text (*.st *.exp *.iec *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!openProject(path, &error))
        QMessageBox::critical(this, tr("Open Project"), tr("The project could not be opened: %1").arg(error));
}

bool MainWindow::saveInteractive()
{
    if (m_currentFile.isEmpty())
        return saveAsInteractive();
    QString error;
    if (saveProject(m_currentFile, &error))
        return true;
    QMessageBox::critical(this, tr("Save Project"), tr("The project could not be saved: %1").arg(error));
    return false;
}

bool MainWindow::saveAsInteractive()
{
    QString path
        = QFileDialog::getSaveFileName(this, tr("Save Project As"), m_currentFile, tr("PLCopen XML projects (*.xml)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".xml");
    QString error;
    if (saveProject(path, &error))
        return true;
    QMessageBox::critical(this, tr("Save Project"), tr("The project could not be saved: %1").arg(error));
    return false;
}

void MainWindow::restoreWindowLayout()
{
    const QSettings store;
    restoreGeometry(store.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(store.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::saveWindowLayout() const
{
    QSettings store;
    store.setValue(QStringLiteral("window/geometry"), saveGeometry());
    store.setValue(QStringLiteral("window/state"), saveState());
}

void MainWindow::applyUiLanguage(const QString &localeName)
{
    m_translator->apply(localeName.isEmpty() ? QLocale::system() : QLocale(localeName));
}

void MainWindow::applySettings(const Settings &settings)
{
    if (settings.uiLanguage != m_settings.uiLanguage)
        applyUiLanguage(settings.uiLanguage);
    m_settings = settings;
    m_recovery->setIntervalMinutes(m_settings.autosaveMinutes);
    m_documents->setGridSize(m_settings.gridSize);
    QSettings store;
    m_settings.save(store);
    Q_EMIT settingsChanged(m_settings);
}

void MainWindow::showSettingsDialog()
{
    SettingsDialog dialog(m_settings, this);
    if (dialog.exec() == QDialog::Accepted)
        applySettings(dialog.settings());
}

void MainWindow::showAboutBox()
{
    QMessageBox::about(this, tr("About IEC Studio"),
        tr("<h3>IEC Studio %1</h3>"
           "<p>An IDE for the five IEC 61131-3 languages: Ladder Diagram, Function Block "
           "Diagram with CFC, Sequential Function Chart, Instruction List and Structured Text.</p>"
           "<p>Projects are stored as PLCopen TC6 XML v2.01.</p>")
            .arg(QCoreApplication::applicationVersion()));
}

} // namespace iec::app
