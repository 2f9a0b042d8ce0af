#include "editors/globals/globallisteditor.h"

#include "model/projectmodel.h"
#include "model/undo/instancecommands.h"

#include <QCoreApplication>

namespace iec::editors {

namespace {

bool sameOwner(const GlobalListRef &a, const GlobalListRef &b)
{
    return a.configuration.compare(b.configuration, Qt::CaseInsensitive) == 0
        && a.resource.compare(b.resource, Qt::CaseInsensitive) == 0;
}

std::vector<GlobalListRef> listsOfOwner(const model::Instances &instances, const GlobalListRef &owner)
{
    std::vector<GlobalListRef> lists = globalLists(instances);
    std::erase_if(lists, [&](const GlobalListRef &list) { return !sameOwner(list, owner); });
    return lists;
}

} // namespace

GlobalListEditor::GlobalListEditor(
    model::ProjectModel &projectModel, const GlobalListRef &list, QUndoStack &undoStack, QWidget *parent)
    : DeclarationEditorBase(undoStack, globalClasses(), parent)
    , m_projectModel(projectModel)
    , m_list(list)
{
    setObjectName(QStringLiteral("globalListEditor"));
    m_ownerLists = listsOfOwner(projectModel.project().instances, list);
    connect(&projectModel, &model::ProjectModel::instancesChanged, this, &GlobalListEditor::followModel);
    connect(&projectModel, &model::ProjectModel::projectReset, this, &GlobalListEditor::followModel);
    refreshFromModel();
}

QStringList GlobalListEditor::globalClasses()
{
    // PERSISTENT as CODESYS V2.3 offers it: kept over a download, RETAIN PERSISTENT also over a cold start.
    return {QStringLiteral("VAR_GLOBAL"), QStringLiteral("VAR_GLOBAL CONSTANT"), QStringLiteral("VAR_GLOBAL RETAIN"),
        QStringLiteral("VAR_GLOBAL PERSISTENT"), QStringLiteral("VAR_GLOBAL RETAIN PERSISTENT")};
}

void GlobalListEditor::followModel()
{
    const model::Instances &instances = m_projectModel.project().instances;
    const std::vector<GlobalListRef> lists = listsOfOwner(instances, m_list);
    if (!globalListExists(instances, m_list)) {
        const auto place = std::ranges::find_if(m_ownerLists, [&](const GlobalListRef &l) { return l.sameList(m_list); });
        const size_t at = size_t(place - m_ownerLists.begin());
        const auto isNew = [&](const GlobalListRef &candidate) {
            return std::ranges::none_of(m_ownerLists, [&](const GlobalListRef &l) { return l.sameList(candidate); });
        };
        if (lists.size() != m_ownerLists.size() || at >= lists.size() || !isNew(lists[at])) {
            Q_EMIT listRemoved();
            return;
        }
        m_list = lists[at];
        Q_EMIT listRenamed(m_list);
    }
    m_ownerLists = lists;
    refreshFromModel();
}

model::Interface GlobalListEditor::declarations() const
{
    return globalListDeclarations(m_projectModel.project().instances, m_list);
}

void GlobalListEditor::applyDeclarations(const model::Interface &declarations)
{
    model::Instances before = m_projectModel.project().instances;
    const std::vector<model::VariableRename> renames
        = model::renamedVariables(globalListDeclarations(before, m_list).varLists, declarations.varLists);
    // A task started by a renamed global (SINGLE) follows it.
    for (const model::VariableRename &rename : renames) {
        if (auto renamed = model::instancesWithGlobalRenamed(before, rename.oldName, rename.newName))
            before = std::move(*renamed);
    }
    std::optional<model::Instances> after = withGlobalListDeclarations(before, m_list, declarations);
    if (!after)
        return;
    auto *gesture = new QUndoCommand(tr("Change global variable list %1").arg(m_list.displayName()));
    new model::SetInstancesCommand(m_projectModel, std::move(*after), gesture);
    if (!renames.empty() && m_renameReferences) {
        m_renameReferences(renames, gesture);
        gesture->setText(renames.size() == 1
                ? tr("Rename global variable %1 to %2").arg(renames.front().oldName, renames.front().newName)
                : tr("Rename %n global variable(s)", nullptr, int(renames.size())));
    }
    undoStack()->push(gesture);
}

QString GlobalListEditor::sectionProblem(const model::VarList &list) const
{
    if (list.kind == model::VarListKind::Global)
        return {};
    return tr("A global variable list holds VAR_GLOBAL sections only; %1 belongs in a POU.").arg(sectionHeader(list));
}

QString GlobalListEditor::variableProblem(const model::VarList &, const model::Variable &variable) const
{
    const auto other = otherListDeclaring(m_projectModel.project().instances, m_list.configuration, variable.name, m_list);
    if (!other)
        return {};
    return tr("%1 is declared in the global variable list %2 already.").arg(variable.name, other->displayName());
}

} // namespace iec::editors
