#pragma once

#include <QList>
#include <QObject>
#include <QPointer>

class QAction;
class QLabel;
class QMenu;
class QStatusBar;

namespace iec::editors {
class DiagramEditor;
}

namespace iec::app {

class DocumentArea;

// A separator at the end of a menu and the current document's actions after it, replaced when
// another document becomes current; the separator shows only while there are actions.
struct MenuSection {
    QMenu *menu = nullptr;
    QAction *separator = nullptr;
    QList<QPointer<QAction>> actions; // owned by the editor, which may close first

    static MenuSection atEndOf(QMenu &menu);
    void show(const QList<QAction *> &editorActions);
};

// The current diagram editor's commands in the window's menus, for every graphical language
// alike (they come from the editor's action table, DiagramEditor::actionsIn): its Insert commands
// at the end of the Insert menu, its element commands (Step Properties..., Arrange Chart, ...) at
// the end of the Edit menu, its view commands (zoom, fit, export, print) at the end of the View
// menu, each below a separator of its own; and its zoom percentage in the status bar. Another tab
// takes them out again. (Cut, Copy, Paste and Delete reach the editor through EditActions.)
class DiagramMenus : public QObject
{
    Q_OBJECT

public:
    DiagramMenus(DocumentArea &documents, QMenu &insertMenu, QMenu &editMenu, QMenu &viewMenu, QStatusBar &statusBar,
        QObject *parent = nullptr);

    // The status bar's zoom percentage ("Zoom: 150 %"); hidden while no diagram is current.
    [[nodiscard]] QLabel *zoomLabel() const { return m_zoomLabel; }
    void retranslate();

private:
    void currentChanged();
    void showZoom();

    DocumentArea &m_documents;
    MenuSection m_insert;
    MenuSection m_edit;
    MenuSection m_view;
    QLabel *m_zoomLabel = nullptr;
    QPointer<editors::DiagramEditor> m_editor;
};

} // namespace iec::app
