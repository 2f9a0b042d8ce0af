#pragma once

#include "app/diagrammenus.h"
#include "app/projecttemplates.h"
#include "app/settings.h"

#include <QMainWindow>
#include <QPointer>

#include <memory>

class QAction;
class QDockWidget;
class QMenu;
class QToolBar;
class QUndoGroup;

namespace iec::model {
class ProjectModel;
struct Project;
}

namespace iec::app {

class BuildController;
class DocumentArea;
class EditActions;
class LibraryPane;
class LiveDiagnostics;
class SearchActions;
class SearchResultsPane;
class ExamplesMenu;
class GlobalListCommands;
class ImportExportActions;
class MessagesPane;
class DebugController;
class HistoryBar;
class TracePane;
class OnlineController;
class ProjectCommands;
class ProjectTreeActions;
class ProjectTreeModel;
class ProjectTreeView;
class RecentFilesMenu;
class RecoveryManager;
class UiTranslator;
class UndoActions;
class UndoStacks;
class WatchPane;
class WindowMenu;

// The IDE's main window: menus, the project tree and messages docks, and the central document
// area (mainwindow.cpp); the project-wide tools (mainwindowtools.cpp). Texts are set in retranslateUi() so that switching the UI language updates them live.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    [[nodiscard]] model::ProjectModel &projectModel() { return *m_projectModel; }
    [[nodiscard]] QUndoGroup &undoGroup();
    [[nodiscard]] UndoStacks &undoStacks() { return *m_undoStacks; }
    [[nodiscard]] ProjectCommands &projectCommands() { return *m_projectCommands; }
    [[nodiscard]] ProjectTreeActions &treeActions() { return *m_treeActions; }
    [[nodiscard]] GlobalListCommands &globalListCommands() { return *m_globalListCommands; }
    [[nodiscard]] RecoveryManager &recovery() { return *m_recovery; }
    [[nodiscard]] const Settings &settings() const { return m_settings; }
    [[nodiscard]] MessagesPane &messagesPane() { return *m_messages; }
    [[nodiscard]] BuildController &buildController() { return *m_build; }
    [[nodiscard]] DocumentArea &documents() { return *m_documents; }
    [[nodiscard]] OnlineController &online() { return *m_online; }
    [[nodiscard]] DebugController &debugger() { return *m_debug; }
    [[nodiscard]] WatchPane &watchPane() { return *m_watch; }
    [[nodiscard]] ProjectTreeView &projectTree() { return *m_projectTree; }
    [[nodiscard]] ImportExportActions &importExport() { return *m_importExport; }
    [[nodiscard]] EditActions &editActions() { return *m_editActions; }
    [[nodiscard]] SearchActions &searchActions() { return *m_searchActions; }
    [[nodiscard]] SearchResultsPane &searchResults() { return *m_searchResults; }
    [[nodiscard]] LiveDiagnostics &liveDiagnostics() { return *m_liveDiagnostics; }
    [[nodiscard]] LibraryPane &libraryPane() { return *m_library; }
    [[nodiscard]] TracePane &tracePane() { return *m_trace; }
    [[nodiscard]] HistoryBar &historyBar() { return *m_historyBar; }
    // The project as Save writes it: the model with the breakpoints and the trace configuration.
    [[nodiscard]] model::Project projectToSave() const;
    [[nodiscard]] QString currentFile() const { return m_currentFile; }
    // The undo stacks are not at their clean state, typing is unsaved, or the project was
    // recovered and not saved since.
    [[nodiscard]] bool hasUnsavedChanges() const;

    // Non-interactive file operations (the menu commands wrap them with dialogs). On failure they
    // return false and say why in `error`; the open project stays as it was. An IEC text file
    // (.st, .iec, .txt) opens as a new untitled project: Save asks where its PLCopen file goes, so
    // the text is never overwritten.
    bool openProject(const QString &path, QString *error = nullptr);
    bool saveProject(const QString &path, QString *error = nullptr);
    void newProject();
    // A new untitled project from a template (File → New); its main program opens.
    void newProjectFromTemplate(ProjectTemplate projectTemplate);
    // Opens the program a project starts with (mainProgramName), as CODESYS shows PLC_PRG.
    void openMainProgram();
    // Opens a project of File → Recent Projects; one that is gone is removed from the list.
    bool openRecent(const QString &path, QString *error = nullptr);
    // Opens a shipped example (a resource path from Examples::list()) as a new, untitled project.
    bool openExample(const QString &resourcePath, QString *error = nullptr);
    // Opens a recovery file (RecoveryManager::pendingRecoveries()) in place of the project; the
    // content counts as unsaved and a save goes to the project it came from.
    bool recover(const QString &recoveryFile, QString *error = nullptr);

    // Stores the settings and applies them at once: UI language, editor font, grid, autosave.
    void applySettings(const Settings &settings);

public Q_SLOTS:
    void showAboutBox();
    void showSettingsDialog();
    void newProjectInteractive();
    void openProjectInteractive();
    void openRecentInteractive(const QString &path);
    void openExampleInteractive(const QString &resourcePath);
    bool saveInteractive();
    bool saveAsInteractive();
    // At start: offers the recovery files a crashed session left (one question per file).
    void offerRecoveryInteractive();
    // Writes the recovery file when there is something unsaved; true when it wrote one.
    bool autosave();

Q_SIGNALS:
    void settingsChanged(const iec::app::Settings &settings);

protected:
    void changeEvent(QEvent *event) override;
    void closeEvent(QCloseEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createToolBar();
    void createDocks();
    // Global variable lists and configurations open from the tree (and when created).
    void connectInstanceDocuments();
    // Edit menu commands (cut ... replace, find in project, definitions, cross references) and
    // the search results dock; their menu entries (extendMenus).
    void createProjectTools();
    void extendMenus();
    void retranslateProjectTools();
    // The Trace pane and the history bar (mainwindowtrace.cpp).
    void createTraceTools();
    void retranslateTraceTools();
    // The Insert menu carries the current text editor's insert commands (IL: Operator, Operand,
    // Function, Function Block) below a separator of their own.
    void showTextInsertActions();
    void printDocumentationInteractive();
    void exportDocumentationInteractive();
    void retranslateUi();
    void restoreWindowLayout();
    void saveWindowLayout() const;
    void applyUiLanguage(const QString &localeName);
    void updateWindowTitle();
    // The project tree or no document: the project's undo stack; otherwise the current
    // document's POU stack (DESIGN.md).
    void updateActiveUndoStack();
    // Reads a project file and shows it (no history, nothing unsaved); the caller says whose it is.
    bool loadProject(const QString &path, QString *error);
    // Reads IEC text into a project and shows it, refused with the first error when it has one.
    bool loadIecText(const QString &path, QString *error);
    // Shows `project` in place of the one shown so far.
    void adoptProject(model::Project project);
    void setCurrentFile(const QString &path);
    // Asks whether to save unsaved changes; false when the user cancels.
    bool maybeSave();

    model::ProjectModel *m_projectModel = nullptr;
    UndoStacks *m_undoStacks = nullptr;
    std::unique_ptr<ProjectCommands> m_projectCommands;
    std::unique_ptr<GlobalListCommands> m_globalListCommands;
    RecoveryManager *m_recovery = nullptr;
    UiTranslator *m_translator = nullptr;
    Settings m_settings;
    QString m_currentFile;
    bool m_recoveredUnsaved = false;

    QMenu *m_fileMenu = nullptr;
    RecentFilesMenu *m_recentMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_insertMenu = nullptr;
    QMenu *m_projectMenu = nullptr;
    QMenu *m_onlineMenu = nullptr;
    WindowMenu *m_windowMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    ExamplesMenu *m_examplesMenu = nullptr;
    QToolBar *m_toolBar = nullptr;

    QAction *m_newAction = nullptr;
    QAction *m_openAction = nullptr;
    QAction *m_saveAction = nullptr;
    QAction *m_saveAsAction = nullptr;
    QAction *m_quitAction = nullptr;
    UndoActions *m_undoActions = nullptr;
    ImportExportActions *m_importExport = nullptr;
    QAction *m_buildAction = nullptr;
    QAction *m_settingsAction = nullptr;
    QAction *m_loginAction = nullptr;
    QAction *m_stopAction = nullptr;
    QAction *m_singleCycleAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QAction *m_aboutQtAction = nullptr;

    QDockWidget *m_projectDock = nullptr;
    QDockWidget *m_messagesDock = nullptr;
    ProjectTreeModel *m_projectTreeModel = nullptr;
    ProjectTreeView *m_projectTree = nullptr;
    ProjectTreeActions *m_treeActions = nullptr;
    MessagesPane *m_messages = nullptr;
    BuildController *m_build = nullptr;
    DocumentArea *m_documents = nullptr;
    QDockWidget *m_watchDock = nullptr;
    WatchPane *m_watch = nullptr;
    OnlineController *m_online = nullptr;
    DebugController *m_debug = nullptr;
    EditActions *m_editActions = nullptr;
    DiagramMenus *m_diagramMenus = nullptr;
    SearchActions *m_searchActions = nullptr;
    SearchResultsPane *m_searchResults = nullptr;
    QDockWidget *m_searchDock = nullptr;
    LiveDiagnostics *m_liveDiagnostics = nullptr;
    LibraryPane *m_library = nullptr;
    QDockWidget *m_libraryDock = nullptr;
    TracePane *m_trace = nullptr;
    QDockWidget *m_traceDock = nullptr;
    HistoryBar *m_historyBar = nullptr;
    MenuSection m_textInsert; // the current text editor's Insert commands
    QAction *m_printDocumentationAction = nullptr;
    QAction *m_exportDocumentationAction = nullptr;
};

} // namespace iec::app
