#include "app/diagrammenus.h"

#include "app/documentarea.h"
#include "editors/common/diagrameditor.h"

#include <QAction>
#include <QLabel>
#include <QMenu>
#include <QStatusBar>

namespace iec::app {

using editors::DiagramEditor;

MenuSection MenuSection::atEndOf(QMenu &menu)
{
    MenuSection section;
    section.menu = &menu;
    section.separator = menu.addSeparator();
    section.separator->setVisible(false);
    return section;
}

void MenuSection::show(const QList<QAction *> &editorActions)
{
    for (const QPointer<QAction> &action : std::as_const(actions)) {
        if (action)
            menu->removeAction(action);
    }
    actions.clear();
    for (QAction *action : editorActions)
        actions.append(action);
    separator->setVisible(!editorActions.isEmpty());
    const QList<QAction *> entries = menu->actions();
    const qsizetype next = entries.indexOf(separator) + 1;
    menu->insertActions(next < entries.size() ? entries[next] : nullptr, editorActions);
}

DiagramMenus::DiagramMenus(
    DocumentArea &documents, QMenu &insertMenu, QMenu &editMenu, QMenu &viewMenu, QStatusBar &statusBar, QObject *parent)
    : QObject(parent)
    , m_documents(documents)
    , m_insert(MenuSection::atEndOf(insertMenu))
    , m_edit(MenuSection::atEndOf(editMenu))
    , m_view(MenuSection::atEndOf(viewMenu))
{
    m_zoomLabel = new QLabel;
    m_zoomLabel->setObjectName(QStringLiteral("zoomLabel"));
    m_zoomLabel->hide();
    statusBar.addPermanentWidget(m_zoomLabel);
    connect(&documents, &QTabWidget::currentChanged, this, &DiagramMenus::currentChanged);
}

void DiagramMenus::currentChanged()
{
    DiagramEditor *editor = m_documents.currentDiagramEditor();
    if (m_editor && m_editor != editor)
        m_editor->disconnect(this);
    if (editor && editor != m_editor)
        connect(editor, &DiagramEditor::zoomChanged, this, &DiagramMenus::showZoom);
    m_editor = editor;
    m_insert.show(editor ? editor->actionsIn(DiagramEditor::ActionGroup::Insert) : QList<QAction *> {});
    m_edit.show(editor ? editor->actionsIn(DiagramEditor::ActionGroup::Element) : QList<QAction *> {});
    m_view.show(editor ? editor->actionsIn(DiagramEditor::ActionGroup::View) : QList<QAction *> {});
    showZoom();
}

void DiagramMenus::showZoom()
{
    m_zoomLabel->setVisible(m_editor != nullptr);
    if (m_editor)
        m_zoomLabel->setText(tr("Zoom: %1 %").arg(m_editor->zoomPercent()));
}

void DiagramMenus::retranslate()
{
    showZoom();
}

} // namespace iec::app
