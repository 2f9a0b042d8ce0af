#include "app/projecttreemodel.h"

#include "app/treeicons.h"
#include "interpreter/frontend/codesysmembers.h"
#include "model/projectmodel.h"

namespace iec::app {

using model::BodyRef;
using model::PouKind;

ProjectTreeModel::ProjectTreeModel(model::ProjectModel &projectModel, QObject *parent)
    : QAbstractItemModel(parent)
    , m_projectModel(projectModel)
{
    // Coarse signals, coarse answer: the tree is small next to the project (1,000 POUs rebuild in
    // about a millisecond), and views keep their state by key.
    const auto refresh = [this] { rebuild(); };
    connect(&projectModel, &model::ProjectModel::projectReset, this, refresh);
    connect(&projectModel, &model::ProjectModel::pouAdded, this, refresh);
    connect(&projectModel, &model::ProjectModel::pouRemoved, this, refresh);
    connect(&projectModel, &model::ProjectModel::pouRenamed, this, refresh);
    connect(&projectModel, &model::ProjectModel::pouPartsChanged, this, refresh);
    connect(&projectModel, &model::ProjectModel::dataTypesChanged, this, refresh);
    connect(&projectModel, &model::ProjectModel::instancesChanged, this, refresh);
    connect(&projectModel, &model::ProjectModel::pouAddDataChanged, this, refresh);
    connect(&projectModel, &model::ProjectModel::projectAddDataChanged, this, refresh);
    rebuild();
}

QString ProjectTreeModel::folderKey(Folder folder)
{
    return QStringLiteral("folder:%1").arg(int(folder));
}

QString ProjectTreeModel::pouKey(model::PouId id)
{
    return QStringLiteral("pou:%1").arg(id.value);
}

QString ProjectTreeModel::interfaceKey(const QString &name)
{
    return QStringLiteral("interface:%1").arg(name.toLower());
}

QString ProjectTreeModel::memberKey(model::PouId pou, const QString &name)
{
    return QStringLiteral("member:%1:%2").arg(pou.value).arg(name.toLower());
}

QString ProjectTreeModel::globalListKey(const editors::GlobalListRef &list)
{
    return QStringLiteral("gvl:") + list.key();
}

QString ProjectTreeModel::partKey(const BodyRef &ref)
{
    const QChar part = ref.part == BodyRef::Part::Action ? QLatin1Char('a') : QLatin1Char('t');
    return QStringLiteral("%1:%2:%3").arg(part).arg(ref.pou.value).arg(ref.name.toLower());
}

int ProjectTreeModel::addNode(Node node)
{
    const int index = int(m_nodes.size());
    std::vector<int> &siblings = node.parent < 0 ? m_topLevel : m_nodes[std::size_t(node.parent)].children;
    node.row = int(siblings.size());
    siblings.push_back(index);
    m_nodeByKey.insert(node.key, index);
    m_nodes.push_back(std::move(node));
    return index;
}

namespace {

editors::EditorLanguage languageOf(const model::Body *body)
{
    return body ? editors::editorLanguage(*body) : editors::EditorLanguage::ST;
}

} // namespace

void ProjectTreeModel::addPou(int folder, const model::Pou &pou)
{
    const int pouNode = addNode({.kind = NodeKind::Pou, .key = pouKey(pou.id), .name = pou.name, .pou = pou.id,
                                 .pouKind = pou.kind, .language = languageOf(pou.body()), .parent = folder});
    const auto addParts = [&](const std::vector<model::PouPart> &parts, BodyRef::Part part, NodeKind kind) {
        for (const model::PouPart &value : parts) {
            addNode({.kind = kind, .key = partKey({pou.id, part, value.name}), .name = value.name, .pou = pou.id,
                     .language = languageOf(&value.body), .parent = pouNode});
        }
    };
    // Methods and properties first, as CODESYS lists them under a function block.
    for (const interp::frontend::CodesysMemberSummary &member : interp::frontend::codesysMembers(pou)) {
        addNode({.kind = NodeKind::Member, .key = memberKey(pou.id, member.name), .name = member.name, .pou = pou.id,
                 .property = member.property, .parent = pouNode});
    }
    addParts(pou.actions, BodyRef::Part::Action, NodeKind::Action);
    addParts(pou.transitions, BodyRef::Part::Transition, NodeKind::Transition);
}

void ProjectTreeModel::addInstances()
{
    const model::Project &project = m_projectModel.project();
    const int globals = addNode({.folder = Folder::GlobalVariables, .key = folderKey(Folder::GlobalVariables)});
    // A list's sections (VAR_GLOBAL, CONSTANT, RETAIN) are one node, as CODESYS shows a GVL.
    for (const editors::GlobalListRef &list : editors::globalLists(project.instances)) {
        addNode({.kind = NodeKind::GlobalVarList, .key = globalListKey(list), .name = list.displayName(), .list = list,
                 .configuration = list.configuration, .parent = globals});
    }
    const int configurations = addNode({.folder = Folder::Configurations, .key = folderKey(Folder::Configurations)});
    for (const model::Configuration &configuration : project.instances.configurations) {
        const int configurationNode = addNode({.kind = NodeKind::Configuration,
                                               .key = QStringLiteral("cfg:%1").arg(configuration.name),
                                               .name = configuration.name, .configuration = configuration.name,
                                               .parent = configurations});
        for (const model::Resource &resource : configuration.resources) {
            const QString path = configuration.name + QLatin1Char('.') + resource.name;
            const int resourceNode = addNode({.kind = NodeKind::Resource, .key = QStringLiteral("res:%1").arg(path),
                                              .name = resource.name, .configuration = configuration.name,
                                              .parent = configurationNode});
            for (const model::Task &task : resource.tasks) {
                addNode({.kind = NodeKind::Task, .key = QStringLiteral("task:%1.%2").arg(path, task.name),
                         .name = task.name, .configuration = configuration.name, .parent = resourceNode});
            }
        }
    }
}

void ProjectTreeModel::rebuild()
{
    beginResetModel();
    m_nodes.clear();
    m_topLevel.clear();
    m_nodeByKey.clear();
    const model::Project &project = m_projectModel.project();
    const int programs = addNode({.folder = Folder::Programs, .key = folderKey(Folder::Programs)});
    const int functionBlocks = addNode({.folder = Folder::FunctionBlocks, .key = folderKey(Folder::FunctionBlocks)});
    const int functions = addNode({.folder = Folder::Functions, .key = folderKey(Folder::Functions)});
    for (const model::Pou &pou : project.types.pous) {
        const int folder = pou.kind == PouKind::Program ? programs
            : pou.kind == PouKind::FunctionBlock       ? functionBlocks
                                                       : functions;
        addPou(folder, pou);
    }
    // Shown when there are interfaces: most IEC projects have none (Add Interface makes one).
    if (const QStringList names = interp::frontend::codesysInterfaceNames(project); !names.isEmpty()) {
        const int interfaces = addNode({.folder = Folder::Interfaces, .key = folderKey(Folder::Interfaces)});
        for (const QString &name : names)
            addNode({.kind = NodeKind::Interface, .key = interfaceKey(name), .name = name, .parent = interfaces});
    }
    const int dataTypes = addNode({.folder = Folder::DataTypes, .key = folderKey(Folder::DataTypes)});
    for (const model::DataTypeDecl &type : project.types.dataTypes)
        addNode({.kind = NodeKind::DataType, .key = QStringLiteral("type:%1").arg(type.name.toLower()),
                 .name = type.name, .parent = dataTypes});
    addInstances();
    endResetModel();
}

const ProjectTreeModel::Node *ProjectTreeModel::node(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return nullptr;
    return &m_nodes[std::size_t(index.internalId())];
}

QModelIndex ProjectTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (column != 0 || row < 0)
        return {};
    const std::vector<int> &siblings = parent.isValid() ? node(parent)->children : m_topLevel;
    if (row >= int(siblings.size()))
        return {};
    return createIndex(row, column, quintptr(siblings[std::size_t(row)]));
}

QModelIndex ProjectTreeModel::parent(const QModelIndex &child) const
{
    const Node *childNode = node(child);
    if (!childNode || childNode->parent < 0)
        return {};
    const Node &parentNode = m_nodes[std::size_t(childNode->parent)];
    return createIndex(parentNode.row, 0, quintptr(childNode->parent));
}

int ProjectTreeModel::rowCount(const QModelIndex &parent) const
{
    if (parent.column() > 0)
        return 0;
    return int(parent.isValid() ? node(parent)->children.size() : m_topLevel.size());
}

int ProjectTreeModel::columnCount(const QModelIndex &) const
{
    return 1;
}

QString ProjectTreeModel::displayText(const Node &node) const
{
    switch (node.kind) {
    case NodeKind::Folder:
        switch (node.folder) {
        case Folder::Programs:
            return tr("Programs");
        case Folder::FunctionBlocks:
            return tr("Function Blocks");
        case Folder::Functions:
            return tr("Functions");
        case Folder::Interfaces:
            return tr("Interfaces");
        case Folder::DataTypes:
            return tr("Data Types");
        case Folder::GlobalVariables:
            return tr("Global Variables");
        case Folder::Configurations:
            return tr("Configurations");
        }
        break;
    case NodeKind::Pou:
        // As in CODESYS: the kind as a short suffix, PLC_PRG (PRG).
        switch (node.pouKind) {
        case PouKind::Program:
            return tr("%1 (PRG)").arg(node.name);
        case PouKind::FunctionBlock:
            return tr("%1 (FB)").arg(node.name);
        case PouKind::Function:
            return tr("%1 (FUN)").arg(node.name);
        }
        break;
    default:
        break;
    }
    if (node.kind == NodeKind::Member)
        return node.property ? tr("%1 (PROPERTY)").arg(node.name) : tr("%1 (METHOD)").arg(node.name);
    if (node.kind == NodeKind::Interface)
        return tr("%1 (ITF)").arg(node.name);
    return node.name;
}

QVariant ProjectTreeModel::data(const QModelIndex &index, int role) const
{
    const Node *item = node(index);
    if (!item)
        return {};
    switch (role) {
    case Qt::DisplayRole:
        return displayText(*item);
    case Qt::EditRole:
        return item->name;
    case Qt::ToolTipRole:
        if (item->kind == NodeKind::Pou || item->kind == NodeKind::Action || item->kind == NodeKind::Transition)
            return tr("%1, written in %2").arg(item->name, languageName(item->language));
        if (item->kind == NodeKind::Member)
            return tr("Edited as text: METHOD ... END_METHOD or PROPERTY ... END_PROPERTY");
        if (item->kind == NodeKind::Interface)
            return tr("Edited as text: INTERFACE ... END_INTERFACE");
        return {};
    case Qt::DecorationRole:
        switch (item->kind) {
        case NodeKind::Pou:
        case NodeKind::Action:
        case NodeKind::Transition:
        case NodeKind::Member:
            return languageIcon(item->language);
        default:
            return nodeIcon(item->kind);
        }
    case KeyRole:
        return item->key;
    case NodeKindRole:
        return int(item->kind);
    default:
        return {};
    }
}

Qt::ItemFlags ProjectTreeModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags flags = QAbstractItemModel::flags(index);
    if (bodyRef(index) || globalList(index))
        flags |= Qt::ItemIsEditable;
    return flags;
}

bool ProjectTreeModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const QString newName = value.toString().trimmed();
    if (role != Qt::EditRole || newName == name(index))
        return false;
    if (const std::optional<BodyRef> item = bodyRef(index))
        Q_EMIT renameRequested(*item, newName);
    else if (const auto list = globalList(index))
        Q_EMIT globalListRenameRequested(*list, newName);
    return false;
}

QString ProjectTreeModel::key(const QModelIndex &index) const
{
    const Node *item = node(index);
    return item ? item->key : QString();
}

QModelIndex ProjectTreeModel::indexForKey(const QString &key) const
{
    const auto it = m_nodeByKey.constFind(key);
    if (it == m_nodeByKey.constEnd())
        return {};
    return createIndex(m_nodes[std::size_t(*it)].row, 0, quintptr(*it));
}

std::optional<ProjectTreeModel::NodeKind> ProjectTreeModel::nodeKind(const QModelIndex &index) const
{
    const Node *item = node(index);
    return item ? std::optional(item->kind) : std::nullopt;
}

std::optional<BodyRef> ProjectTreeModel::bodyRef(const QModelIndex &index) const
{
    const Node *item = node(index);
    if (!item)
        return std::nullopt;
    switch (item->kind) {
    case NodeKind::Pou:
        return BodyRef{item->pou, BodyRef::Part::Pou, {}};
    case NodeKind::Action:
        return BodyRef{item->pou, BodyRef::Part::Action, item->name};
    case NodeKind::Transition:
        return BodyRef{item->pou, BodyRef::Part::Transition, item->name};
    default:
        return std::nullopt;
    }
}

bool ProjectTreeModel::isInterface(const QModelIndex &index) const
{
    const Node *item = node(index);
    return item && item->kind == NodeKind::Interface;
}

bool ProjectTreeModel::isMember(const QModelIndex &index) const
{
    const Node *item = node(index);
    return item && item->kind == NodeKind::Member;
}

model::PouId ProjectTreeModel::pouId(const QModelIndex &index) const
{
    const Node *item = node(index);
    return item ? item->pou : model::PouId{};
}

std::optional<editors::GlobalListRef> ProjectTreeModel::globalList(const QModelIndex &index) const
{
    const Node *item = node(index);
    if (!item || item->kind != NodeKind::GlobalVarList)
        return std::nullopt;
    return item->list;
}

QString ProjectTreeModel::configurationName(const QModelIndex &index) const
{
    const Node *item = node(index);
    return item ? item->configuration : QString();
}

QString ProjectTreeModel::name(const QModelIndex &index) const
{
    const Node *item = node(index);
    return item ? item->name : QString();
}

} // namespace iec::app
