#include "app/projecttreeview.h"

#include "app/projecttreemodel.h"

#include <QEvent>
#include <QHeaderView>

namespace iec::app {

ProjectTreeView::ProjectTreeView(QWidget *parent)
    : QTreeView(parent)
{
    setHeaderHidden(true);
    setUniformRowHeights(true);
    setSelectionMode(QAbstractItemView::SingleSelection);
    // A click on the selected POU edits its name in place, as in a file manager; F2 opens the
    // rename dialog (ProjectTreeActions), which explains a name it cannot take.
    setEditTriggers(QAbstractItemView::SelectedClicked);
    connect(this, &QTreeView::activated, this, [this](const QModelIndex &index) {
        if (!m_model)
            return;
        if (const auto body = m_model->bodyRef(index))
            Q_EMIT openRequested(*body);
        else if (m_model->isMember(index))
            Q_EMIT openMemberRequested(m_model->pouId(index), m_model->name(index));
        else if (m_model->isInterface(index))
            Q_EMIT openInterfaceRequested(m_model->name(index));
        else if (m_model->nodeKind(index) == ProjectTreeModel::NodeKind::DataType)
            Q_EMIT openDataTypeRequested(m_model->name(index));
        else if (const auto list = m_model->globalList(index))
            Q_EMIT openGlobalListRequested(*list);
        else if (const QString configuration = m_model->configurationName(index); !configuration.isEmpty())
            openConfigurationAt(index, configuration);
    });
}

void ProjectTreeView::openConfigurationAt(const QModelIndex &index, const QString &configuration)
{
    QString resource;
    QString task;
    switch (m_model->nodeKind(index).value_or(ProjectTreeModel::NodeKind::Configuration)) {
    case ProjectTreeModel::NodeKind::Task:
        task = m_model->name(index);
        resource = m_model->name(index.parent());
        break;
    case ProjectTreeModel::NodeKind::Resource:
        resource = m_model->name(index);
        break;
    default:
        break;
    }
    Q_EMIT openConfigurationRequested(configuration, resource, task);
}

void ProjectTreeView::setProjectModel(ProjectTreeModel *model)
{
    m_model = model;
    setModel(model);
    connect(selectionModel(), &QItemSelectionModel::currentChanged, this, &ProjectTreeView::currentItemChanged);
    connect(model, &QAbstractItemModel::modelReset, this, &ProjectTreeView::currentItemChanged);
    connect(model, &QAbstractItemModel::modelAboutToBeReset, this, &ProjectTreeView::rememberState);
    connect(model, &QAbstractItemModel::modelReset, this, &ProjectTreeView::restoreState);
    restoreState();
}

QString ProjectTreeView::currentKey() const
{
    return m_model ? m_model->key(currentIndex()) : QString();
}

void ProjectTreeView::selectKey(const QString &key)
{
    const QModelIndex index = m_model->indexForKey(key);
    if (!index.isValid())
        return;
    for (QModelIndex parent = index.parent(); parent.isValid(); parent = parent.parent())
        expand(parent);
    setCurrentIndex(index);
    scrollTo(index);
}

void ProjectTreeView::rememberState()
{
    m_expandedKeys.clear();
    const std::function<void(const QModelIndex &)> visit = [&](const QModelIndex &parent) {
        for (int row = 0; row < m_model->rowCount(parent); ++row) {
            const QModelIndex child = m_model->index(row, 0, parent);
            if (isExpanded(child)) {
                m_expandedKeys.insert(m_model->key(child));
                visit(child);
            }
        }
    };
    visit({});
    m_currentKey = currentKey();
}

void ProjectTreeView::restoreState()
{
    if (m_firstFill) {
        // A project opens with its top-level folders expanded, as CODESYS shows it.
        for (int row = 0; row < m_model->rowCount(); ++row)
            m_expandedKeys.insert(m_model->key(m_model->index(row, 0)));
        m_firstFill = false;
    }
    for (const QString &key : std::as_const(m_expandedKeys)) {
        const QModelIndex index = m_model->indexForKey(key);
        if (index.isValid())
            expand(index);
    }
    if (!m_currentKey.isEmpty())
        selectKey(m_currentKey);
}

void ProjectTreeView::changeEvent(QEvent *event)
{
    // Folder names and kind suffixes are translated by the model's data(): ask for them again.
    if (event->type() == QEvent::LanguageChange)
        doItemsLayout();
    QTreeView::changeEvent(event);
}

} // namespace iec::app
