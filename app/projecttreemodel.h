#pragma once

#include "editors/common/editorlanguage.h"
#include "editors/globals/globallists.h"
#include "model/ids.h"
#include "model/pou.h"

#include <QAbstractItemModel>
#include <QHash>

#include <optional>
#include <vector>

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

// The project tree: POUs grouped by kind with their actions and transitions beneath them, data
// types, global variable lists and the configurations with their resources and tasks. It rebuilds
// itself from the model's coarse signals; every node has a stable key so that views can keep
// expansion and selection across the rebuild.
class ProjectTreeModel : public QAbstractItemModel
{
    Q_OBJECT

public:
    // Member: a method or property of a POU; Interface: an INTERFACE of the project (CODESYS keeps
    // both in addData).
    enum class NodeKind { Folder, Pou, Action, Transition, DataType, GlobalVarList, Configuration, Resource, Task, Member, Interface };
    // In the order of their keys (kept across versions), not of the tree.
    enum class Folder { Programs, FunctionBlocks, Functions, DataTypes, GlobalVariables, Configurations, Interfaces };
    enum Role { KeyRole = Qt::UserRole + 1, NodeKindRole };

    explicit ProjectTreeModel(model::ProjectModel &projectModel, QObject *parent = nullptr);

    [[nodiscard]] QString key(const QModelIndex &index) const;
    [[nodiscard]] QModelIndex indexForKey(const QString &key) const;
    [[nodiscard]] std::optional<NodeKind> nodeKind(const QModelIndex &index) const;
    // The body a node opens: a POU's own body, an action's or a transition's.
    [[nodiscard]] std::optional<model::BodyRef> bodyRef(const QModelIndex &index) const;
    [[nodiscard]] model::PouId pouId(const QModelIndex &index) const;
    // Whether the node is a method or property: its name() is the member's, pouId() its POU.
    [[nodiscard]] bool isMember(const QModelIndex &index) const;
    // Whether the node is an INTERFACE: its name() is the interface's.
    [[nodiscard]] bool isInterface(const QModelIndex &index) const;
    // The global variable list a node shows; nullopt for other nodes.
    [[nodiscard]] std::optional<editors::GlobalListRef> globalList(const QModelIndex &index) const;
    // The configuration a configuration, resource or task node belongs to; empty for other nodes.
    [[nodiscard]] QString configurationName(const QModelIndex &index) const;
    [[nodiscard]] QString name(const QModelIndex &index) const; // the model name, without decoration

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    // POUs, actions and transitions can be renamed in place: setData does not change anything
    // itself but asks for the rename (an undoable command); the tree follows the model after it.
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

    static QString folderKey(Folder folder);
    static QString pouKey(model::PouId id);
    static QString partKey(const model::BodyRef &ref);
    static QString globalListKey(const editors::GlobalListRef &list);
    static QString memberKey(model::PouId pou, const QString &name);
    static QString interfaceKey(const QString &name);

Q_SIGNALS:
    void renameRequested(const iec::model::BodyRef &item, const QString &newName);
    void globalListRenameRequested(const iec::editors::GlobalListRef &list, const QString &newName);

private:
    struct Node {
        NodeKind kind = NodeKind::Folder;
        Folder folder = Folder::Programs; // for folders
        QString key;
        QString name;
        model::PouId pou;
        model::PouKind pouKind = model::PouKind::Program;
        editors::EditorLanguage language = editors::EditorLanguage::ST;
        editors::GlobalListRef list; // global variable lists
        QString configuration;       // configurations, resources and tasks
        bool property = false;       // a member that is a property, not a method
        int parent = -1; // index into m_nodes; -1: top level
        int row = 0;     // position among its siblings
        std::vector<int> children;
    };

    void rebuild();
    int addNode(Node node);
    void addPou(int folder, const model::Pou &pou);
    void addInstances();
    [[nodiscard]] QString displayText(const Node &node) const;
    [[nodiscard]] const Node *node(const QModelIndex &index) const;

    model::ProjectModel &m_projectModel;
    std::vector<Node> m_nodes;
    std::vector<int> m_topLevel;
    QHash<QString, int> m_nodeByKey;
};

} // namespace iec::app
