#include "editors/text/linenumberarea.h"

#include "editors/text/codeeditor.h"

#include <QMouseEvent>

namespace iec::editors {

LineNumberArea::LineNumberArea(CodeEditor *editor)
    : QWidget(editor)
    , m_editor(editor)
{
    setObjectName(QStringLiteral("lineNumberArea"));
    setCursor(Qt::ArrowCursor);
}

QSize LineNumberArea::sizeHint() const
{
    return {m_editor->lineNumberAreaWidth(), 0};
}

void LineNumberArea::paintEvent(QPaintEvent *event)
{
    m_editor->paintLineNumberArea(event);
}

void LineNumberArea::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton)
        m_editor->lineNumberAreaClicked(event->position().toPoint());
    QWidget::mousePressEvent(event);
}

} // namespace iec::editors
