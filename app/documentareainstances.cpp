// The document area's tabs for global variable lists and configurations (DocumentArea members
// kept apart from the body editors in documentarea.cpp).

#include "app/documentarea.h"

#include "app/referencerename.h"
#include "app/undostacks.h"
#include "editors/globals/globallisteditor.h"
#include "editors/tasks/configurationeditor.h"
#include "model/projectmodel.h"

#include <QUndoStack>

namespace iec::app {

editors::GlobalListEditor *DocumentArea::globalListEditorFor(const editors::GlobalListRef &list) const
{
    for (int index = 0; index < count(); ++index) {
        auto *editor = qobject_cast<editors::GlobalListEditor *>(widget(index));
        if (editor && editor->list().sameList(list))
            return editor;
    }
    return nullptr;
}

QWidget *DocumentArea::openGlobalList(const editors::GlobalListRef &list)
{
    if (editors::GlobalListEditor *open = globalListEditorFor(list)) {
        setCurrentWidget(open);
        return open;
    }
    if (!editors::globalListExists(m_projectModel.project().instances, list))
        return nullptr;
    auto *editor = new editors::GlobalListEditor(m_projectModel, list, m_undoStacks->projectStack());
    editor->setProperty(kWholeTabEditorProperty, true);
    // A renamed global renames its uses; typing not yet in the model is pushed first.
    editor->setRenameReferences([this](const Renames &renames, QUndoCommand *gesture) {
        flushEdits();
        addGlobalReferenceRenames(m_projectModel, renames, gesture);
    });
    connect(editor, &editors::GlobalListEditor::listRenamed, this, [this, editor](const editors::GlobalListRef &renamed) {
        if (const int index = indexOf(editor); index >= 0)
            setTabText(index, renamed.displayName());
    });
    // Queued: the editor is inside its own signal when it reports the removal.
    connect(editor, &editors::GlobalListEditor::listRemoved, editor, [this, editor] {
        if (const int index = indexOf(editor); index >= 0)
            closeDocument(index);
    }, Qt::QueuedConnection);
    const int index = addTab(editor, list.displayName());
    setCurrentIndex(index);
    if (m_editingLocked)
        setEditingLocked(true);
    return editor;
}

bool DocumentArea::showGlobalVariable(const QString &list, const QString &variable)
{
    const auto declaring = editors::globalListDeclaring(m_projectModel.project().instances, variable, list);
    auto *editor = declaring ? qobject_cast<editors::GlobalListEditor *>(openGlobalList(*declaring)) : nullptr;
    return editor && editor->showVariable(variable);
}

editors::ConfigurationEditor *DocumentArea::configurationEditorFor(const QString &configuration) const
{
    for (int index = 0; index < count(); ++index) {
        auto *editor = qobject_cast<editors::ConfigurationEditor *>(widget(index));
        if (editor && editor->configuration().compare(configuration, Qt::CaseInsensitive) == 0)
            return editor;
    }
    return nullptr;
}

QWidget *DocumentArea::openConfiguration(const QString &configuration, const QString &resource, const QString &task)
{
    editors::ConfigurationEditor *editor = configurationEditorFor(configuration);
    if (!editor) {
        const auto &configurations = m_projectModel.project().instances.configurations;
        if (std::ranges::none_of(configurations, [&](const model::Configuration &c) {
                return c.name.compare(configuration, Qt::CaseInsensitive) == 0;
            }))
            return nullptr;
        editor = new editors::ConfigurationEditor(m_projectModel, configuration, m_undoStacks->projectStack());
        editor->setProperty(kWholeTabEditorProperty, true);
        connect(editor, &editors::ConfigurationEditor::openGlobalListRequested, this, &DocumentArea::openGlobalList);
        connect(editor, &editors::ConfigurationEditor::addGlobalListRequested, this, &DocumentArea::addGlobalListRequested);
        connect(editor, &editors::ConfigurationEditor::configurationRemoved, editor, [this, editor] {
            if (const int index = indexOf(editor); index >= 0)
                closeDocument(index);
        }, Qt::QueuedConnection);
        addTab(editor, configuration);
        if (m_editingLocked)
            setEditingLocked(true);
    }
    editor->showTask(resource, task);
    setCurrentWidget(editor);
    return editor;
}

} // namespace iec::app
