#include "editors/text/texteditorwidget.h"

#include "editors/text/codeeditor.h"
#include "editors/text/findreplacebar.h"

#include <QAction>
#include <QVBoxLayout>

namespace iec::editors {

TextEditorWidget::TextEditorWidget(TextLanguage language, QWidget *parent)
    : QWidget(parent)
    , m_editor(new CodeEditor(language, this))
    , m_findBar(new FindReplaceBar(m_editor, this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_editor, 1);
    layout->addWidget(m_findBar);
    m_findBar->hide();
    setFocusProxy(m_editor);

    auto addShortcut = [this](const QKeySequence &keys, auto slot) {
        auto *action = new QAction(this);
        action->setShortcut(keys);
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        connect(action, &QAction::triggered, this, slot);
        addAction(action);
    };
    addShortcut(QKeySequence::Find, [this] { m_findBar->activate(false); });
    addShortcut(QKeySequence::Replace, [this] { m_findBar->activate(true); });
    addShortcut(QKeySequence::FindNext, [this] { m_findBar->findNext(); });
    addShortcut(QKeySequence::FindPrevious, [this] { m_findBar->findPrevious(); });
}

} // namespace iec::editors
