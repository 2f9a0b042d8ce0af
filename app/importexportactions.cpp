#include "app/importexportactions.h"

#include "app/importexport.h"
#include "app/messagespane.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QUndoStack>

namespace iec::app {

namespace {

const QString kMessageSource = QStringLiteral("import");

} // namespace

ImportExportActions::ImportExportActions(model::ProjectModel &model, QUndoStack &projectStack,
    MessagesPane &messages, ProjectTreeView &tree, QWidget *window)
    : QObject(window)
    , m_model(model)
    , m_stack(projectStack)
    , m_messages(messages)
    , m_tree(tree)
    , m_window(window)
    , m_import(new QAction(this))
    , m_export(new QAction(this))
    , m_exportSelection(new QAction(this))
{
    m_import->setObjectName(QStringLiteral("importAction"));
    m_export->setObjectName(QStringLiteral("exportAction"));
    m_exportSelection->setObjectName(QStringLiteral("exportSelectionAction"));
    connect(m_import, &QAction::triggered, this, &ImportExportActions::importInteractive);
    connect(m_export, &QAction::triggered, this, [this] { exportInteractive(false); });
    connect(m_exportSelection, &QAction::triggered, this, [this] { exportInteractive(true); });
    connect(&m_tree, &ProjectTreeView::currentItemChanged, this,
        [this] { m_exportSelection->setEnabled(!selectedPous().empty()); });
    m_exportSelection->setEnabled(false);
    retranslate();
}

void ImportExportActions::retranslate()
{
    m_import->setText(tr("&Import..."));
    m_export->setText(tr("&Export Project..."));
    m_exportSelection->setText(tr("Export Se&lection..."));
}

bool ImportExportActions::importFile(const QString &path, QString *error)
{
    ImportExport::Read read = ImportExport::read(path);
    QList<Message> messages = read.messages;
    const bool ok = read.project.has_value();
    if (ok) {
        ImportExport::Merge merge = ImportExport::merge(m_model, *read.project);
        messages += merge.messages;
        if (merge.command)
            m_stack.push(merge.command);
        messages.append({.severity = Message::Severity::Info,
            .text = tr("Imported %1: %2 POU(s), %3 data type(s).")
                        .arg(QFileInfo(path).fileName())
                        .arg(merge.pous)
                        .arg(merge.dataTypes)});
    } else if (error) {
        *error = messages.isEmpty() ? tr("Nothing could be read from %1.").arg(QFileInfo(path).fileName())
                                    : messages.front().text;
    }
    m_messages.model().setMessages(kMessageSource, messages);
    return ok;
}

bool ImportExportActions::exportFile(const QString &path, const std::vector<model::PouId> &pous, QString *error)
{
    if (m_flush)
        m_flush();
    QList<Message> warnings;
    const bool ok = ImportExport::write(m_model.project(), pous, ImportExport::formatOf(path), path, error, &warnings);
    m_messages.model().setMessages(QStringLiteral("export"), warnings);
    return ok;
}

std::vector<model::PouId> ImportExportActions::selectedPous() const
{
    std::vector<model::PouId> pous;
    const auto *treeModel = qobject_cast<const ProjectTreeModel *>(m_tree.model());
    const QModelIndex current = m_tree.currentIndex();
    if (!treeModel || !current.isValid())
        return pous;
    const auto kind = treeModel->nodeKind(current);
    if (kind == ProjectTreeModel::NodeKind::Folder) {
        for (int row = 0; row < treeModel->rowCount(current); ++row) {
            const QModelIndex child = treeModel->index(row, 0, current);
            if (treeModel->nodeKind(child) == ProjectTreeModel::NodeKind::Pou)
                pous.push_back(treeModel->pouId(child));
        }
    } else if (const model::PouId pou = treeModel->pouId(current); pou.isValid()) {
        pous.push_back(pou); // a POU, or one of its actions or transitions: the POU
    }
    return pous;
}

void ImportExportActions::importInteractive()
{
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Import"), QString(),
        tr("PLCopen XML or IEC text (*.xml *.st *.exp *.iec *.txt);;PLCopen XML (*.xml);;IEC 61131-3 text (*.st *.exp *.iec *.txt)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!importFile(path, &error))
        QMessageBox::warning(m_window, tr("Import"), error);
}

void ImportExportActions::exportInteractive(bool selectionOnly)
{
    const std::vector<model::PouId> pous = selectionOnly ? selectedPous() : std::vector<model::PouId> {};
    if (selectionOnly && pous.empty())
        return;
    QString xmlFilter = tr("PLCopen XML (*.xml)");
    const QString textFilter = tr("IEC 61131-3 text (*.st)");
    const QString path = QFileDialog::getSaveFileName(m_window, tr("Export"), QString(),
        xmlFilter + QStringLiteral(";;") + textFilter, &xmlFilter);
    if (path.isEmpty())
        return;
    QString error;
    if (!exportFile(path, pous, &error))
        QMessageBox::warning(m_window, tr("Export"), error);
}

} // namespace iec::app
