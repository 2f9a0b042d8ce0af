#pragma once

#include "editors/globals/globallists.h"
#include "model/ids.h"

#include <QSet>
#include <QTreeView>

namespace iec::app {

class ProjectTreeModel;

// Shows a ProjectTreeModel and keeps the expanded nodes and the current node (by key) when the
// model rebuilds. Activating a POU, action or transition asks to open its body.
class ProjectTreeView : public QTreeView
{
    Q_OBJECT

public:
    explicit ProjectTreeView(QWidget *parent = nullptr);

    void setProjectModel(ProjectTreeModel *model);
    [[nodiscard]] QString currentKey() const;
    void selectKey(const QString &key);

Q_SIGNALS:
    void openRequested(const iec::model::BodyRef &body);
    // A data type node was activated (double-click, Enter).
    void openDataTypeRequested(const QString &typeName);
    // A method or property of a POU was activated.
    void openMemberRequested(iec::model::PouId pou, const QString &name);
    void openInterfaceRequested(const QString &name);
    // A global variable list was activated.
    void openGlobalListRequested(const iec::editors::GlobalListRef &list);
    // A configuration, one of its resources or tasks was activated: its editor opens there.
    void openConfigurationRequested(const QString &configuration, const QString &resource, const QString &task);
    // The current node changed (also when a rebuild moved or removed it).
    void currentItemChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    void openConfigurationAt(const QModelIndex &index, const QString &configuration);
    void rememberState();
    void restoreState();

    ProjectTreeModel *m_model = nullptr;
    QSet<QString> m_expandedKeys;
    QString m_currentKey;
    bool m_firstFill = true;
};

} // namespace iec::app
