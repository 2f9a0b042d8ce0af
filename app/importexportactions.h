#pragma once

#include "model/ids.h"

#include <QObject>

#include <functional>
#include <vector>

class QAction;
class QUndoStack;
class QWidget;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

class MessagesPane;
class ProjectTreeView;

// File → Import... (PLCopen XML from other tools, IEC text .st; merged into the open project as
// one undo step on the project stack), File → Export Project... and Export Selection... (the
// POUs selected in the tree: a POU, or every POU of a selected folder) as PLCopen XML or IEC text.
class ImportExportActions : public QObject
{
    Q_OBJECT

public:
    ImportExportActions(model::ProjectModel &model, QUndoStack &projectStack, MessagesPane &messages,
        ProjectTreeView &tree, QWidget *window);

    [[nodiscard]] QAction *importAction() const { return m_import; }
    [[nodiscard]] QAction *exportAction() const { return m_export; }
    [[nodiscard]] QAction *exportSelectionAction() const { return m_exportSelection; }
    void retranslate();
    // Called before reading the model, so that typing still held by the editors is exported.
    void setFlushPendingEdits(std::function<void()> flush) { m_flush = std::move(flush); }

    // Without dialogs: false with the reason in `error` (the messages pane lists the details).
    bool importFile(const QString &path, QString *error = nullptr);
    bool exportFile(const QString &path, const std::vector<model::PouId> &pous, QString *error = nullptr);
    // The POUs the tree's current node stands for (none: the whole project).
    [[nodiscard]] std::vector<model::PouId> selectedPous() const;

public Q_SLOTS:
    void importInteractive();
    void exportInteractive(bool selectionOnly);

private:
    model::ProjectModel &m_model;
    QUndoStack &m_stack;
    MessagesPane &m_messages;
    ProjectTreeView &m_tree;
    QWidget *m_window;
    std::function<void()> m_flush;
    QAction *m_import;
    QAction *m_export;
    QAction *m_exportSelection;
};

} // namespace iec::app
