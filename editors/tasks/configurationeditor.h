#pragma once

#include "editors/globals/globallists.h"
#include "editors/tasks/taskrows.h"

#include <QPointer>
#include <QWidget>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QUndoStack;

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

class MessageLabel;
class RowTable;

// One configuration as CODESYS's task configuration shows it: its resources (chosen above), the
// chosen resource's tasks (name, cyclic interval, SINGLE trigger variable, priority, watchdog
// time), the programs the chosen task runs, and the resource's global variable lists. Every
// gesture (a cell committed, a row added, removed or moved, a resource added, removed or renamed)
// is checked (validateConfiguration) and, when the configuration has no problem, pushed as one
// SetInstancesCommand on `undoStack`; otherwise each message is shown at its cell and nothing
// changes. Changes from elsewhere (undo, a program renamed) refresh it.
class ConfigurationEditor : public QWidget
{
    Q_OBJECT

public:
    ConfigurationEditor(model::ProjectModel &projectModel, const QString &configuration, QUndoStack &undoStack,
        QWidget *parent = nullptr);

    [[nodiscard]] QString configuration() const { return m_configuration; }
    // Shows the resource named `resource` (the first when empty or unknown) with task `task` current.
    void showTask(const QString &resource, const QString &task);
    [[nodiscard]] int currentResource() const { return m_resource; }
    [[nodiscard]] int currentTask() const;

    [[nodiscard]] RowTable *taskTable() const { return m_tasks; }
    [[nodiscard]] RowTable *instanceTable() const { return m_instances; }
    [[nodiscard]] QLineEdit *resourceNameEdit() const { return m_resourceName; }
    [[nodiscard]] QListWidget *globalListView() const { return m_globalLists; }
    // Every message shown now, one per line (empty when the configuration is valid).
    [[nodiscard]] QString problemText() const { return m_problemText; }

    void addResource();
    void removeCurrentResource();

Q_SIGNALS:
    void openGlobalListRequested(const iec::editors::GlobalListRef &list);
    // "Add List" for the shown resource; the app asks for the name (its name rules).
    void addGlobalListRequested(const iec::editors::GlobalListRef &owner);
    void configurationRemoved();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void fitTaskColumns();
    void refreshFromModel();
    void showInstancesOfCurrentTask();
    void updateNewRows();
    void applyTasks();
    void applyInstances();
    void applyResourceName();
    // Checks `changed` and pushes it when it has no problem; `parsed` are problems found while
    // reading the rows. Returns whether it was applied.
    bool apply(const model::Configuration &changed, std::vector<ConfigurationProblem> parsed, const QString &text);
    void showProblems(const std::vector<ConfigurationProblem> &problems);
    [[nodiscard]] const model::Configuration *current() const;

    model::ProjectModel &m_projectModel;
    QString m_configuration;
    QPointer<QUndoStack> m_undoStack;
    int m_resource = 0;
    QString m_problemText;

    QLabel *m_title = nullptr;
    QLabel *m_resourceLabel = nullptr;
    QComboBox *m_resourceBox = nullptr;
    QLineEdit *m_resourceName = nullptr;
    QPushButton *m_addResource = nullptr;
    QPushButton *m_removeResource = nullptr;
    MessageLabel *m_resourceMessage = nullptr;
    QLabel *m_tasksLabel = nullptr;
    RowTable *m_tasks = nullptr;
    QLabel *m_instancesLabel = nullptr;
    RowTable *m_instances = nullptr;
    QLabel *m_globalsLabel = nullptr;
    QListWidget *m_globalLists = nullptr;
    QPushButton *m_addGlobalList = nullptr;
    MessageLabel *m_otherMessages = nullptr;
};

} // namespace iec::editors
