#pragma once

#include "app/globallistcommands.h"
#include "app/projectcommands.h"

#include <QObject>

class QAction;
class QMenu;
class QWidget;

namespace iec::app {

class ProjectTreeView;

// The project tree's commands as actions for the Project menu and the tree's context menu: Add
// POU, Add Action, Add Transition, Add Global Variable List, Task Configuration, Rename, Delete,
// Duplicate (the last three for POUs, actions, transitions and global variable lists). Each asks
// what it needs with a dialog and hands the answer to ProjectCommands (GlobalListCommands), which
// does the work undoably. The actions are
// enabled for the tree's current item; Delete and F2 work while the tree has the focus.
class ProjectTreeActions : public QObject
{
    Q_OBJECT

public:
    ProjectTreeActions(ProjectCommands &commands, GlobalListCommands &lists, model::ProjectModel &model,
        ProjectTreeView &tree, QWidget *dialogParent);

    void addTo(QMenu *menu) const;
    void retranslate();

    [[nodiscard]] QAction *addPouAction() const { return m_addPou; }
    [[nodiscard]] QAction *addActionAction() const { return m_addAction; }
    [[nodiscard]] QAction *addTransitionAction() const { return m_addTransition; }
    [[nodiscard]] QAction *addMethodAction() const { return m_addMethod; }
    [[nodiscard]] QAction *addPropertyAction() const { return m_addProperty; }
    [[nodiscard]] QAction *addInterfaceAction() const { return m_addInterface; }
    [[nodiscard]] QAction *addGlobalListAction() const { return m_addGlobalList; }
    [[nodiscard]] QAction *taskConfigurationAction() const { return m_taskConfiguration; }
    [[nodiscard]] QAction *renameAction() const { return m_rename; }
    [[nodiscard]] QAction *deleteAction() const { return m_delete; }
    [[nodiscard]] QAction *duplicateAction() const { return m_duplicate; }
    // Online the project's structure stays as it is: every action is off and the in-place
    // rename is refused (editRefused tells the window to say why).
    void setLocked(bool locked);
    [[nodiscard]] bool isLocked() const { return m_locked; }

public Q_SLOTS:
    void addPouInteractive();
    void addActionInteractive();
    void addTransitionInteractive();
    void addMethodInteractive();
    void addPropertyInteractive();
    void addInterfaceInteractive();
    // Asks for the name of a new global variable list in `owner` (by default where
    // GlobalListCommands puts it) and adds it.
    void addGlobalListInteractive(const std::optional<iec::editors::GlobalListRef> &owner = std::nullopt);
    // Shows the task configuration (the first configuration, made first when there is none).
    void openTaskConfiguration();
    void renameInteractive();
    void deleteInteractive();
    void duplicateCurrent();
    // The tree's in-place editor was closed with `newName`.
    void renameInPlace(const iec::model::BodyRef &item, const QString &newName);
    void renameGlobalListInPlace(const iec::editors::GlobalListRef &list, const QString &newName);

Q_SIGNALS:
    // A POU, action or transition was created (added or duplicated): the window opens it.
    void created(const iec::model::BodyRef &item);
    // A method or property was added: the window opens it.
    void memberCreated(iec::model::PouId pou, const QString &name);
    void interfaceCreated(const QString &name);
    // A global variable list was created (added or duplicated): the window opens it.
    void globalListCreated(const iec::editors::GlobalListRef &list);
    // The task configuration of `configuration` is to be shown.
    void configurationRequested(const QString &configuration);
    // A change was asked for while locked (online) and not made.
    void editRefused();

private:
    QAction *createAction(const char *objectName, void (ProjectTreeActions::*slot)());
    void addPartInteractive(model::BodyRef::Part part);
    void addMemberInteractive(bool property);
    // The POU of the current node: a POU, or one of its actions, transitions or members.
    [[nodiscard]] const model::Pou *currentPou() const;
    // The method or property the current node is; empty for other nodes.
    [[nodiscard]] QString currentMember() const;
    [[nodiscard]] QString currentInterface() const;
    void updateEnabled();
    bool refuseWhenLocked();
    void showContextMenu(const QPoint &position);
    [[nodiscard]] std::optional<model::BodyRef> currentItem() const;
    [[nodiscard]] std::optional<editors::GlobalListRef> currentGlobalList() const;
    void renameGlobalListInteractive(const editors::GlobalListRef &list);

    ProjectCommands &m_commands;
    GlobalListCommands &m_lists;
    model::ProjectModel &m_model;
    ProjectTreeView &m_tree;
    QWidget *m_dialogParent;
    QAction *m_addPou = nullptr;
    QAction *m_addAction = nullptr;
    QAction *m_addTransition = nullptr;
    QAction *m_addMethod = nullptr;
    QAction *m_addProperty = nullptr;
    QAction *m_addInterface = nullptr;
    QAction *m_addGlobalList = nullptr;
    QAction *m_taskConfiguration = nullptr;
    QAction *m_rename = nullptr;
    QAction *m_delete = nullptr;
    QAction *m_duplicate = nullptr;
    bool m_locked = false;
};

} // namespace iec::app
