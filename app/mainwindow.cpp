#include "app/mainwindow.h"

#include "app/messagespane.h"
#include "app/settingsdialog.h"
#include "app/uitranslator.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTreeWidget>
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
    auto *placeholder = new QLabel(this);
    placeholder->setAlignment(Qt::AlignCenter);
    placeholder->setObjectName(QStringLiteral("documentArea"));
    setCentralWidget(placeholder);

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
    m_projectTree = new QTreeWidget(this);
    m_projectTree->setObjectName(QStringLiteral("projectTree"));
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
    setWindowTitle(tr("IEC Studio"));
    m_fileMenu->setTitle(tr("&File"));
    m_editMenu->setTitle(tr("&Edit"));
    m_viewMenu->setTitle(tr("&View"));
    m_projectMenu->setTitle(tr("&Project"));
    m_onlineMenu->setTitle(tr("&Online"));
    m_helpMenu->setTitle(tr("&Help"));

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
    m_projectTree->setHeaderLabel(tr("Project"));
    m_messagesDock->setWindowTitle(tr("Messages"));
    if (auto *placeholder = qobject_cast<QLabel *>(centralWidget()))
        placeholder->setText(tr("Open a POU from the project tree to edit it."));
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QMainWindow::changeEvent(event);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveWindowLayout();
    QMainWindow::closeEvent(event);
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
