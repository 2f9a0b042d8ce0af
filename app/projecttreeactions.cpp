#include "app/projecttreeactions.h"

#include "app/addpoudialog.h"
#include "app/addpoupartdialog.h"
#include "app/namerules.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/renamedialog.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QMenu>
#include <QMessageBox>

namespace iec::app {

using model::BodyRef;

ProjectTreeActions::ProjectTreeActions(ProjectCommands &commands, GlobalListCommands &lists, model::ProjectModel &model,
    ProjectTreeView &tree, QWidget *dialogParent)
    : QObject(dialogParent)
    , m_commands(commands)
    , m_lists(lists)
    , m_model(model)
    , m_tree(tree)
    , m_dialogParent(dialogParent)
{
    m_addPou = createAction("addPouAction", &ProjectTreeActions::addPouInteractive);
    m_addAction = createAction("addActionAction", &ProjectTreeActions::addActionInteractive);
    m_addTransition = createAction("addTransitionAction", &ProjectTreeActions::addTransitionInteractive);
    m_addMethod = createAction("addMethodAction", &ProjectTreeActions::addMethodInteractive);
    m_addProperty = createAction("addPropertyAction", &ProjectTreeActions::addPropertyInteractive);
    m_addInterface = createAction("addInterfaceAction", &ProjectTreeActions::addInterfaceInteractive);
    m_addGlobalList = new QAction(this);
    m_addGlobalList->setObjectName(QStringLiteral("addGlobalListAction"));
    connect(m_addGlobalList, &QAction::triggered, this, [this] { addGlobalListInteractive(); });
    m_taskConfiguration = createAction("taskConfigurationAction", &ProjectTreeActions::openTaskConfiguration);
    m_rename = createAction("renameAction", &ProjectTreeActions::renameInteractive);
    m_delete = createAction("deleteAction", &ProjectTreeActions::deleteInteractive);
    m_duplicate = createAction("duplicateAction", &ProjectTreeActions::duplicateCurrent);

    // Delete and F2 mean other things in the editors (F2 is the input assistant), so these two
    // shortcuts only work while the tree has the focus.
    m_rename->setShortcut(QKeySequence(Qt::Key_F2));
    m_delete->setShortcut(QKeySequence::Delete);
    for (QAction *action : {m_rename, m_delete}) {
        action->setShortcutContext(Qt::WidgetShortcut);
        m_tree.addAction(action);
    }

    m_tree.setContextMenuPolicy(Qt::CustomContextMenu);
    connect(&m_tree, &QWidget::customContextMenuRequested, this, &ProjectTreeActions::showContextMenu);
    connect(&m_tree, &ProjectTreeView::currentItemChanged, this, &ProjectTreeActions::updateEnabled);
    if (auto *treeModel = qobject_cast<ProjectTreeModel *>(m_tree.model())) {
        // Queued: the rename rebuilds the tree, which must not happen inside the editor's commit.
        connect(treeModel, &ProjectTreeModel::renameRequested, this, &ProjectTreeActions::renameInPlace,
            Qt::QueuedConnection);
        connect(treeModel, &ProjectTreeModel::globalListRenameRequested, this,
            &ProjectTreeActions::renameGlobalListInPlace, Qt::QueuedConnection);
    }
    updateEnabled();
    retranslate();
}

QAction *ProjectTreeActions::createAction(const char *objectName, void (ProjectTreeActions::*slot)())
{
    auto *action = new QAction(this);
    action->setObjectName(QString::fromLatin1(objectName));
    connect(action, &QAction::triggered, this, slot);
    return action;
}

void ProjectTreeActions::addTo(QMenu *menu) const
{
    menu->addAction(m_addPou);
    menu->addAction(m_addAction);
    menu->addAction(m_addTransition);
    menu->addAction(m_addMethod);
    menu->addAction(m_addProperty);
    menu->addAction(m_addInterface);
    menu->addAction(m_addGlobalList);
    menu->addAction(m_taskConfiguration);
    menu->addSeparator();
    menu->addAction(m_rename);
    menu->addAction(m_duplicate);
    menu->addAction(m_delete);
}

void ProjectTreeActions::retranslate()
{
    m_addPou->setText(tr("Add &POU..."));
    m_addAction->setText(tr("Add &Action..."));
    m_addTransition->setText(tr("Add &Transition..."));
    m_addMethod->setText(tr("Add &Method..."));
    m_addProperty->setText(tr("Add Propert&y..."));
    m_addInterface->setText(tr("Add &Interface..."));
    m_addGlobalList->setText(tr("Add &Global Variable List..."));
    m_taskConfiguration->setText(tr("Task &Configuration"));
    m_rename->setText(tr("&Rename..."));
    m_delete->setText(tr("&Delete"));
    m_duplicate->setText(tr("D&uplicate"));
}

std::optional<BodyRef> ProjectTreeActions::currentItem() const
{
    const auto *treeModel = qobject_cast<const ProjectTreeModel *>(m_tree.model());
    return treeModel ? treeModel->bodyRef(m_tree.currentIndex()) : std::nullopt;
}

const model::Pou *ProjectTreeActions::currentPou() const
{
    const auto *treeModel = qobject_cast<const ProjectTreeModel *>(m_tree.model());
    return treeModel ? m_model.project().findPou(treeModel->pouId(m_tree.currentIndex())) : nullptr;
}

QString ProjectTreeActions::currentMember() const
{
    const auto *treeModel = qobject_cast<const ProjectTreeModel *>(m_tree.model());
    return treeModel && treeModel->isMember(m_tree.currentIndex()) ? treeModel->name(m_tree.currentIndex()) : QString();
}

QString ProjectTreeActions::currentInterface() const
{
    const auto *treeModel = qobject_cast<const ProjectTreeModel *>(m_tree.model());
    return treeModel && treeModel->isInterface(m_tree.currentIndex()) ? treeModel->name(m_tree.currentIndex()) : QString();
}

std::optional<editors::GlobalListRef> ProjectTreeActions::currentGlobalList() const
{
    const auto *treeModel = qobject_cast<const ProjectTreeModel *>(m_tree.model());
    return treeModel ? treeModel->globalList(m_tree.currentIndex()) : std::nullopt;
}

void ProjectTreeActions::updateEnabled()
{
    const std::optional<BodyRef> item = currentItem();
    const model::Pou *pou = item ? m_model.project().findPou(item->pou) : nullptr;
    // CODESYS keeps actions and transitions for SFC programs; any program or FB may have them here.
    const bool mayHaveParts = pou && pou->kind != model::PouKind::Function;
    m_addPou->setEnabled(!m_locked);
    m_addAction->setEnabled(mayHaveParts && !m_locked);
    m_addTransition->setEnabled(mayHaveParts && !m_locked);
    // Methods and properties: function blocks, as CODESYS compiles them.
    const model::Pou *owner = currentPou();
    const bool mayHaveMembers = owner && owner->kind == model::PouKind::FunctionBlock;
    m_addMethod->setEnabled(mayHaveMembers && !m_locked);
    m_addProperty->setEnabled(mayHaveMembers && !m_locked);
    m_addInterface->setEnabled(!m_locked);
    m_addGlobalList->setEnabled(!m_locked);
    const bool named = item.has_value() || currentGlobalList().has_value();
    for (QAction *action : {m_rename, m_duplicate})
        action->setEnabled(named && !m_locked);
    m_delete->setEnabled((named || !currentMember().isEmpty() || !currentInterface().isEmpty()) && !m_locked);
}

void ProjectTreeActions::setLocked(bool locked)
{
    m_locked = locked;
    updateEnabled();
}

bool ProjectTreeActions::refuseWhenLocked()
{
    if (m_locked)
        Q_EMIT editRefused();
    return m_locked;
}

void ProjectTreeActions::showContextMenu(const QPoint &position)
{
    updateEnabled();
    QMenu menu;
    addTo(&menu);
    menu.exec(m_tree.viewport()->mapToGlobal(position));
}

void ProjectTreeActions::addPouInteractive()
{
    if (refuseWhenLocked())
        return;
    AddPouDialog dialog(m_model.project(), m_dialogParent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (const auto id = m_commands.addPou(dialog.newPou(), &error))
        Q_EMIT created({*id, BodyRef::Part::Pou, {}});
    else
        QMessageBox::warning(m_dialogParent, tr("Add POU"), error);
}

void ProjectTreeActions::addActionInteractive()
{
    addPartInteractive(BodyRef::Part::Action);
}

void ProjectTreeActions::addTransitionInteractive()
{
    addPartInteractive(BodyRef::Part::Transition);
}

void ProjectTreeActions::addPartInteractive(BodyRef::Part part)
{
    if (refuseWhenLocked())
        return;
    const std::optional<BodyRef> item = currentItem();
    if (!item)
        return;
    AddPouPartDialog dialog(m_model.project(), item->pou, part, m_dialogParent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (const auto added = m_commands.addPouPart(item->pou, dialog.newPart(), &error))
        Q_EMIT created(*added);
    else
        QMessageBox::warning(m_dialogParent, dialog.windowTitle(), error);
}

void ProjectTreeActions::addMethodInteractive()
{
    addMemberInteractive(false);
}

void ProjectTreeActions::addPropertyInteractive()
{
    addMemberInteractive(true);
}

void ProjectTreeActions::addMemberInteractive(bool property)
{
    if (refuseWhenLocked())
        return;
    const model::Pou *pou = currentPou();
    if (!pou || pou->kind != model::PouKind::FunctionBlock)
        return;
    const model::PouId id = pou->id;
    const model::Project &project = m_model.project();
    const QString suggested = NameRules::firstFree(property ? QStringLiteral("Property") : QStringLiteral("Method"),
        [&](const QString &name) { return NameRules::memberNameError(project, id, name).has_value(); });
    RenameDialog dialog(suggested, [&](const QString &name) { return NameRules::memberNameError(project, id, name); },
        m_dialogParent);
    dialog.setWindowTitle(property ? tr("Add Property") : tr("Add Method"));
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (m_commands.addMember(id, dialog.newName(), property, &error))
        Q_EMIT memberCreated(id, dialog.newName());
    else
        QMessageBox::warning(m_dialogParent, dialog.windowTitle(), error);
}

void ProjectTreeActions::addGlobalListInteractive(const std::optional<editors::GlobalListRef> &owner)
{
    if (refuseWhenLocked())
        return;
    const model::Project &project = m_model.project();
    RenameDialog dialog(
        NameRules::uniqueGlobalListName(project, QStringLiteral("GVL")),
        [&](const QString &name) { return NameRules::globalListNameError(project, name); }, m_dialogParent);
    dialog.setWindowTitle(tr("Add Global Variable List"));
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (const auto list = m_lists.add(dialog.newName(), &error, owner))
        Q_EMIT globalListCreated(*list);
    else
        QMessageBox::warning(m_dialogParent, dialog.windowTitle(), error);
}

void ProjectTreeActions::openTaskConfiguration()
{
    // Online an existing configuration opens (locked, to look at); none is made.
    if (m_model.project().instances.configurations.empty() && refuseWhenLocked())
        return;
    Q_EMIT configurationRequested(m_lists.taskConfiguration());
}

void ProjectTreeActions::renameGlobalListInteractive(const editors::GlobalListRef &list)
{
    const model::Project &project = m_model.project();
    RenameDialog dialog(
        list.displayName(),
        [&](const QString &name) { return NameRules::globalListNameError(project, name, list.key()); },
        m_dialogParent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (!m_lists.rename(list, dialog.newName(), &error))
        QMessageBox::warning(m_dialogParent, dialog.windowTitle(), error);
}

void ProjectTreeActions::renameGlobalListInPlace(const editors::GlobalListRef &list, const QString &newName)
{
    if (refuseWhenLocked())
        return;
    QString error;
    if (!m_lists.rename(list, newName, &error))
        QMessageBox::warning(m_dialogParent, tr("Rename %1").arg(list.displayName()), error);
}

void ProjectTreeActions::renameInteractive()
{
    if (refuseWhenLocked())
        return;
    if (const auto list = currentGlobalList()) {
        renameGlobalListInteractive(*list);
        return;
    }
    const std::optional<BodyRef> item = currentItem();
    if (!item)
        return;
    const QString oldName = m_commands.nameOf(*item);
    const model::Project &project = m_model.project();
    RenameDialog dialog(
        oldName,
        [&](const QString &name) {
            return item->part == BodyRef::Part::Pou ? NameRules::pouNameError(project, name, item->pou)
                                                    : NameRules::partNameError(project, item->pou, name, oldName);
        },
        m_dialogParent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (!m_commands.rename(*item, dialog.newName(), &error))
        QMessageBox::warning(m_dialogParent, dialog.windowTitle(), error);
}

void ProjectTreeActions::renameInPlace(const BodyRef &item, const QString &newName)
{
    if (refuseWhenLocked())
        return;
    QString error;
    if (!m_commands.rename(item, newName, &error))
        QMessageBox::warning(m_dialogParent, tr("Rename %1").arg(m_commands.nameOf(item)), error);
}
void ProjectTreeActions::addInterfaceInteractive()
{
    if (refuseWhenLocked())
        return;
    const model::Project &project = m_model.project();
    const QString suggested = NameRules::firstFree(QStringLiteral("I_Interface"),
        [&](const QString &name) { return NameRules::interfaceNameError(project, name).has_value(); });
    RenameDialog dialog(suggested, [&](const QString &name) { return NameRules::interfaceNameError(project, name); },
        m_dialogParent);
    dialog.setWindowTitle(tr("Add Interface"));
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString error;
    if (m_commands.addInterface(dialog.newName(), &error))
        Q_EMIT interfaceCreated(dialog.newName());
    else
        QMessageBox::warning(m_dialogParent, dialog.windowTitle(), error);
}

void ProjectTreeActions::deleteInteractive()
{
    if (refuseWhenLocked())
        return;
    const std::optional<BodyRef> item = currentItem();
    const auto list = currentGlobalList();
    const QString member = currentMember();
    const QString interface = currentInterface();
    if (!item && !list && member.isEmpty() && interface.isEmpty())
        return;
    const QString name = item ? m_commands.nameOf(*item) : list ? list->displayName() : !member.isEmpty() ? member : interface;
    const auto answer = QMessageBox::question(m_dialogParent, tr("Delete"),
        tr("Delete %1? Edit → Undo brings it back.").arg(name), QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
    if (answer != QMessageBox::Yes)
        return;
    if (item)
        m_commands.remove(*item);
    else if (list)
        m_lists.remove(*list);
    else if (!interface.isEmpty())
        m_commands.removeInterface(interface);
    else if (const model::Pou *pou = currentPou())
        m_commands.removeMember(pou->id, member);
}

void ProjectTreeActions::duplicateCurrent()
{
    if (refuseWhenLocked())
        return;
    if (const std::optional<BodyRef> item = currentItem()) {
        if (const auto copy = m_commands.duplicate(*item))
            Q_EMIT created(*copy);
    } else if (const auto list = currentGlobalList()) {
        if (const auto copy = m_lists.duplicate(*list))
            Q_EMIT globalListCreated(*copy);
    }
}

} // namespace iec::app
