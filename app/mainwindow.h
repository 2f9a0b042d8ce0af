#pragma once

#include "app/settings.h"

#include <QMainWindow>

class QAction;
class QDockWidget;
class QMenu;
class QUndoGroup;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

class DocumentArea;
class MessagesPane;
class ProjectTreeModel;
class ProjectTreeView;
class UiTranslator;

// The IDE's main window: menus, the project tree and messages docks, and the central document
// area. Texts are set in retranslateUi() so that switching the UI language updates them live.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    [[nodiscard]] model::ProjectModel &projectModel() { return *m_projectModel; }
    [[nodiscard]] QUndoGroup &undoGroup() { return *m_undoGroup; }
    [[nodiscard]] const Settings &settings() const { return m_settings; }
    [[nodiscard]] MessagesPane &messagesPane() { return *m_messages; }
    [[nodiscard]] DocumentArea &documents() { return *m_documents; }
    [[nodiscard]] ProjectTreeView &projectTree() { return *m_projectTree; }
    [[nodiscard]] QString currentFile() const { return m_currentFile; }
    [[nodiscard]] bool hasUnsavedChanges() const;

    // Non-interactive file operations (the menu commands wrap them with dialogs). On failure they
    // return false and say why in `error`; the open project stays as it was.
    bool openProject(const QString &path, QString *error = nullptr);
    bool saveProject(const QString &path, QString *error = nullptr);
    void newProject();

    // Stores the settings and applies them at once: UI language, editor font, grid, autosave.
    void applySettings(const Settings &settings);

public Q_SLOTS:
    void showAboutBox();
    void showSettingsDialog();
    void newProjectInteractive();
    void openProjectInteractive();
    bool saveInteractive();
    bool saveAsInteractive();

Q_SIGNALS:
    void settingsChanged(const iec::app::Settings &settings);

protected:
    void changeEvent(QEvent *event) override;
    void closeEvent(QCloseEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createDocks();
    void retranslateUi();
    void restoreWindowLayout();
    void saveWindowLayout() const;
    void applyUiLanguage(const QString &localeName);
    void updateWindowTitle();
    // Asks whether to save unsaved changes; false when the user cancels.
    bool maybeSave();

    model::ProjectModel *m_projectModel = nullptr;
    QUndoGroup *m_undoGroup = nullptr;
    UiTranslator *m_translator = nullptr;
    Settings m_settings;
    QString m_currentFile;
    quint64 m_savedRevision = 0;

    QMenu *m_fileMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_projectMenu = nullptr;
    QMenu *m_onlineMenu = nullptr;
    QMenu *m_helpMenu = nullptr;

    QAction *m_newAction = nullptr;
    QAction *m_openAction = nullptr;
    QAction *m_saveAction = nullptr;
    QAction *m_saveAsAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
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
    MessagesPane *m_messages = nullptr;
    DocumentArea *m_documents = nullptr;
};

} // namespace iec::app
