#include "app/mainwindow.h"

#include "app/documentarea.h"
#include "app/messagespane.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/settingsdialog.h"
#include "app/uitranslator.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QUndoGroup>

namespace iec::app {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_projectModel(new model::ProjectModel(this))
    , m_undoGroup(new QUndoGroup(this))
    , m_translator(new UiTranslator(this))
    , m_settings(Settings::load(QSettings()))
{
    setObjectName(QStringLiteral("MainWindow"));
    m_documents = new DocumentArea(*m_projectModel, this);
    m_documents->setObjectName(QStringLiteral("documentArea"));
    setCentralWidget(m_documents);
    connect(m_projectModel, &model::ProjectModel::projectReset, this, &MainWindow::updateWindowTitle);
    // Every change bumps the revision; the title's [*] compares it with the saved one.
    for (const auto signal : {&model::ProjectModel::pouAdded, &model::ProjectModel::pouRemoved,
                              &model::ProjectModel::pouRenamed, &model::ProjectModel::pouPartsChanged,
                              &model::ProjectModel::variablesChanged})
        connect(m_projectModel, signal, this, &MainWindow::updateWindowTitle);
    connect(m_projectModel, &model::ProjectModel::dataTypesChanged, this, &MainWindow::updateWindowTitle);
    connect(m_projectModel, &model::ProjectModel::bodyTextChanged, this, &MainWindow::updateWindowTitle);
    connect(m_projectModel, &model::ProjectModel::elementsInserted, this, &MainWindow::updateWindowTitle);
    connect(m_projectModel, &model::ProjectModel::elementsRemoved, this, &MainWindow::updateWindowTitle);
    connect(m_projectModel, &model::ProjectModel::elementsChanged, this, &MainWindow::updateWindowTitle);
    connect(m_projectModel, &model::ProjectModel::connectionsChanged, this, &MainWindow::updateWindowTitle);

    createActions();
    createMenus();
    createDocks();
    statusBar();
    applyUiLanguage(m_settings.uiLanguage);
    retranslateUi();
    resize(1200, 800);
    restoreWindowLayout();
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions()
{
    m_newAction = new QAction(this);
    m_newAction->setShortcut(QKeySequence::New);
    connect(m_newAction, &QAction::triggered, this, &MainWindow::newProjectInteractive);
    m_openAction = new QAction(this);
    m_openAction->setShortcut(QKeySequence::Open);
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openProjectInteractive);
    m_saveAction = new QAction(this);
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
    m_undoAction = m_undoGroup->createUndoAction(this);
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_redoAction = m_undoGroup->createRedoAction(this);
    m_redoAction->setShortcut(QKeySequence::Redo);

    // Build and the online commands get their behaviour with the compiler and the runtime;
    // until then they are shown, disabled, so the menus already have their final shape.
    m_buildAction = new QAction(this);
    m_buildAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    m_buildAction->setEnabled(false);
    m_loginAction = new QAction(this);
    m_loginAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_loginAction->setEnabled(false);
    m_stopAction = new QAction(this);
    m_stopAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    m_stopAction->setEnabled(false);
    m_singleCycleAction = new QAction(this);
    m_singleCycleAction->setShortcut(QKeySequence(Qt::Key_F8));
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
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("fileMenu"));
    m_fileMenu->addAction(m_newAction);
    m_fileMenu->addAction(m_openAction);
    m_fileMenu->addAction(m_saveAction);
    m_fileMenu->addAction(m_saveAsAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_editMenu = menuBar()->addMenu(QString());
    m_editMenu->setObjectName(QStringLiteral("editMenu"));
    m_editMenu->addAction(m_undoAction);
    m_editMenu->addAction(m_redoAction);

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->setObjectName(QStringLiteral("viewMenu"));

    m_projectMenu = menuBar()->addMenu(QString());
    m_projectMenu->setObjectName(QStringLiteral("projectMenu"));
    m_projectMenu->addAction(m_buildAction);
    m_projectMenu->addSeparator();
    m_projectMenu->addAction(m_settingsAction);

    m_onlineMenu = menuBar()->addMenu(QString());
    m_onlineMenu->setObjectName(QStringLiteral("onlineMenu"));
    m_onlineMenu->addAction(m_loginAction);
    m_onlineMenu->addAction(m_stopAction);
    m_onlineMenu->addAction(m_singleCycleAction);

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->setObjectName(QStringLiteral("helpMenu"));
    m_helpMenu->addAction(m_aboutAction);
    m_helpMenu->addAction(m_aboutQtAction);
}

void MainWindow::createDocks()
{
    m_projectTreeModel = new ProjectTreeModel(*m_projectModel, this);
    m_projectTree = new ProjectTreeView(this);
    m_projectTree->setObjectName(QStringLiteral("projectTree"));
    m_projectTree->setProjectModel(m_projectTreeModel);
    connect(m_projectTree, &ProjectTreeView::openRequested, m_documents, &DocumentArea::openBody);
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

    m_viewMenu->addAction(m_projectDock->toggleViewAction());
    m_viewMenu->addAction(m_messagesDock->toggleViewAction());
}

void MainWindow::retranslateUi()
{
    updateWindowTitle();
    m_fileMenu->setTitle(tr("&File"));
    m_editMenu->setTitle(tr("&Edit"));
    m_viewMenu->setTitle(tr("&View"));
    m_projectMenu->setTitle(tr("&Project"));
    m_onlineMenu->setTitle(tr("&Online"));
    m_helpMenu->setTitle(tr("&Help"));

    m_newAction->setText(tr("&New Project"));
    m_openAction->setText(tr("&Open..."));
    m_saveAction->setText(tr("&Save"));
    m_saveAsAction->setText(tr("Save &As..."));
    m_quitAction->setText(tr("&Quit"));
    m_undoAction->setText(tr("&Undo"));
    m_redoAction->setText(tr("&Redo"));
    m_buildAction->setText(tr("&Build"));
    m_settingsAction->setText(tr("&Settings..."));
    m_loginAction->setText(tr("Login and &Run"));
    m_stopAction->setText(tr("&Stop"));
    m_singleCycleAction->setText(tr("Single &Cycle"));
    m_aboutAction->setText(tr("&About IEC Studio"));
    m_aboutQtAction->setText(tr("About &Qt"));

    m_projectDock->setWindowTitle(tr("Project"));
    m_messagesDock->setWindowTitle(tr("Messages"));
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
    saveWindowLayout();
    QMainWindow::closeEvent(event);
}

bool MainWindow::hasUnsavedChanges() const
{
    return m_projectModel->revision() != m_savedRevision;
}

void MainWindow::updateWindowTitle()
{
    const QString name = m_currentFile.isEmpty() ? tr("Untitled") : QFileInfo(m_currentFile).fileName();
    // [*] is where Qt shows the modified marker.
    setWindowTitle(tr("%1[*] - IEC Studio").arg(name));
    setWindowModified(hasUnsavedChanges());
}

namespace {

Message::Severity messageSeverity(model::Diagnostic::Severity severity)
{
    switch (severity) {
    case model::Diagnostic::Severity::Info:
        return Message::Severity::Info;
    case model::Diagnostic::Severity::Warning:
        return Message::Severity::Warning;
    case model::Diagnostic::Severity::Error:
        return Message::Severity::Error;
    }
    return Message::Severity::Error;
}

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

bool MainWindow::openProject(const QString &path, QString *error)
{
    model::plcopen::ReadResult result = model::plcopen::readProjectFile(path);
    const QString fileName = QFileInfo(path).fileName();
    m_messages->model().setMessages(QStringLiteral("import"), messagesOf(result.diagnostics, fileName));
    if (result.fileError || !result.isProject) {
        if (error)
            *error = result.diagnostics.empty() ? tr("%1 is not a PLCopen XML project.").arg(fileName)
                                                : result.diagnostics.front().message;
        return false;
    }
    m_projectModel->reset(std::move(result.project));
    m_currentFile = QFileInfo(path).absoluteFilePath();
    m_savedRevision = m_projectModel->revision();
    updateWindowTitle();
    return true;
}

bool MainWindow::saveProject(const QString &path, QString *error)
{
    m_documents->flushEdits();
    if (!model::plcopen::saveProjectFile(m_projectModel->project(), path, error))
        return false;
    m_currentFile = QFileInfo(path).absoluteFilePath();
    m_savedRevision = m_projectModel->revision();
    updateWindowTitle();
    return true;
}

void MainWindow::newProject()
{
    m_projectModel->reset({});
    m_currentFile.clear();
    m_savedRevision = m_projectModel->revision();
    m_messages->model().clear();
    updateWindowTitle();
}

bool MainWindow::maybeSave()
{
    m_documents->flushEdits();
    if (!hasUnsavedChanges())
        return true;
    const auto answer = QMessageBox::warning(this, tr("Unsaved Changes"),
                                             tr("The project has unsaved changes. Save them first?"),
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveInteractive();
    return answer == QMessageBox::Discard;
}

void MainWindow::newProjectInteractive()
{
    if (maybeSave())
        newProject();
}

void MainWindow::openProjectInteractive()
{
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Project"), QFileInfo(m_currentFile).path(),
                                                      tr("PLCopen XML projects (*.xml);;All files (*)"));
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
    QString path = QFileDialog::getSaveFileName(this, tr("Save Project As"), m_currentFile,
                                                tr("PLCopen XML projects (*.xml)"));
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
