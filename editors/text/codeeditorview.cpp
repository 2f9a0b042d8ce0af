// The code editor's display (codeeditor.h): the gutter with line numbers, marks and fold boxes,
// the extra selections (current line, diagnostics, brackets), folding, and the online values
// painted after the lines.
#include "editors/text/codeeditor.h"

#include "editors/text/bracketmatcher.h"
#include "editors/text/codehighlighter.h"
#include "editors/text/foldingregions.h"
#include "editors/text/linenumberarea.h"

#include <QPainter>
#include <QPainterPath>
#include <QScrollBar>
#include <QTextBlock>
#include <QToolTip>

namespace iec::editors {

namespace {

constexpr int kFoldColumnWidth = 14;
constexpr int kMarkColumnWidth = 10;
constexpr int kBracketWindowLines = 150; // lines searched each way for a matching bracket

const QColor kCurrentLine(0xe8, 0xf2, 0xfe);
const QColor kHaltedLine(0xff, 0xf1, 0x76);  // CODESYS shows where the program is halted in yellow
const QColor kBreakpoint(0xd3, 0x2f, 0x2f);
const QColor kGutterBackground(0xf5, 0xf5, 0xf5);
const QColor kGutterText(0x9a, 0x9a, 0x9a);
const QColor kGutterCurrentText(0x30, 0x30, 0x30);
const QColor kBracketMatch(0xb4, 0xe6, 0xb4);
const QColor kBracketMismatch(0xff, 0xb4, 0xb4);

QColor severityColor(TextDiagnostic::Severity severity)
{
    switch (severity) {
    case TextDiagnostic::Severity::Error:
        return {0xe0, 0x1b, 0x1b};
    case TextDiagnostic::Severity::Warning:
        return {0xe0, 0x9a, 0x00};
    case TextDiagnostic::Severity::Info:
        return {0x1e, 0x7a, 0xd8};
    }
    return Qt::red;
}

} // namespace

// ---- gutter -------------------------------------------------------------------------------

int CodeEditor::lineNumberAreaWidth() const
{
    int digits = 1;
    for (int max = std::max(1, blockCount()); max >= 10; max /= 10)
        ++digits;
    digits = std::max(digits, 3);
    return kMarkColumnWidth + fontMetrics().horizontalAdvance(QLatin1Char('9')) * digits + 6 + kFoldColumnWidth;
}

void CodeEditor::updateLineNumberAreaWidth()
{
    const int width = lineNumberAreaWidth();
    setViewportMargins(width, 0, 0, 0);
    const QRect cr = contentsRect();
    m_lineNumberArea->setGeometry(QRect(cr.left(), cr.top(), width, cr.height()));
}

void CodeEditor::updateLineNumberArea(const QRect &rect, int dy)
{
    if (dy != 0)
        m_lineNumberArea->scroll(0, dy);
    else
        m_lineNumberArea->update(0, rect.y(), m_lineNumberArea->width(), rect.height());
    if (rect.contains(viewport()->rect()))
        updateLineNumberAreaWidth();
}

void CodeEditor::resizeEvent(QResizeEvent *event)
{
    QPlainTextEdit::resizeEvent(event);
    const QRect cr = contentsRect();
    m_lineNumberArea->setGeometry(QRect(cr.left(), cr.top(), lineNumberAreaWidth(), cr.height()));
}

void CodeEditor::paintLineNumberArea(QPaintEvent *event)
{
    QPainter painter(m_lineNumberArea);
    painter.fillRect(event->rect(), kGutterBackground);
    const int width = m_lineNumberArea->width();
    painter.setPen(QColor(0xe0, 0xe0, 0xe0));
    painter.drawLine(width - 1, event->rect().top(), width - 1, event->rect().bottom());

    QHash<int, const FoldRange *> rangeAt;
    for (const FoldRange &range : std::as_const(m_foldRanges))
        rangeAt.insert(range.firstLine, &range); // the outermost range wins (sorted outer first)
    QHash<int, TextDiagnostic::Severity> marks;
    for (const PlacedDiagnostic &placed : std::as_const(m_diagnostics)) {
        const int line = placed.range.block().blockNumber();
        const auto it = marks.constFind(line);
        if (it == marks.constEnd() || int(placed.diagnostic.severity) < int(*it))
            marks.insert(line, placed.diagnostic.severity);
    }

    const int currentLine = textCursor().blockNumber();
    const int numberRight = width - kFoldColumnWidth - 4;
    QFont bold = font();
    bold.setBold(true);

    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    int bottom = top + qRound(blockBoundingRect(block).height());
    painter.setRenderHint(QPainter::Antialiasing);
    while (block.isValid() && top <= event->rect().bottom()) {
        const int number = block.blockNumber();
        if (block.isVisible() && bottom >= event->rect().top()) {
            const int lineHeight = fontMetrics().height();
            const bool current = number == currentLine;
            painter.setFont(current ? bold : font());
            painter.setPen(current ? kGutterCurrentText : kGutterText);
            painter.drawText(
                0, top, numberRight, lineHeight, Qt::AlignRight | Qt::AlignVCenter, QString::number(number + 1));

            if (m_breakpointLines.contains(number + 1)) {
                const bool off = m_disabledBreakpointLines.contains(number + 1);
                painter.setPen(off ? QPen(kBreakpoint, 1.5) : QPen(Qt::white, 1));
                painter.setBrush(off ? QBrush(Qt::NoBrush) : QBrush(kBreakpoint));
                const double r = std::min(kMarkColumnWidth / 2.0, lineHeight / 2.0 - 1);
                painter.drawEllipse(QPointF(kMarkColumnWidth / 2.0 + 1, top + lineHeight / 2.0), r, r);
            }
            if (number + 1 == m_haltedLine) {
                // An arrow into the line, as debuggers show the next statement.
                const double y = top + lineHeight / 2.0;
                const QPointF arrow[] = {{1, y - 4}, {kMarkColumnWidth - 1.0, y}, {1, y + 4}};
                painter.setPen(QPen(QColor(0x80, 0x60, 0x00), 1));
                painter.setBrush(QColor(0xff, 0xd6, 0x00));
                painter.drawPolygon(arrow, 3);
            }
            if (const auto mark = marks.constFind(number); mark != marks.constEnd()) {
                painter.setPen(Qt::NoPen);
                painter.setBrush(severityColor(*mark));
                painter.drawEllipse(QPointF(kMarkColumnWidth / 2.0 + 1, top + lineHeight / 2.0), 3.5, 3.5);
            }
            if (const FoldRange *range = rangeAt.value(number)) {
                const bool folded = isFolded(range->firstLine);
                const QRectF box(width - kFoldColumnWidth + 2.5, top + (lineHeight - 9) / 2.0 + 0.5, 9, 9);
                painter.setBrush(Qt::white);
                painter.setPen(QColor(0x90, 0x90, 0x90));
                painter.drawRect(box);
                painter.setPen(QColor(0x40, 0x40, 0x40));
                const QPointF c = box.center();
                painter.drawLine(QPointF(c.x() - 2.5, c.y()), QPointF(c.x() + 2.5, c.y()));
                if (folded)
                    painter.drawLine(QPointF(c.x(), c.y() - 2.5), QPointF(c.x(), c.y() + 2.5));
            }
        }
        block = block.next();
        top = bottom;
        bottom = top + qRound(blockBoundingRect(block).height());
    }
}

void CodeEditor::lineNumberAreaClicked(const QPoint &position)
{
    const QTextBlock block = cursorForPosition(QPoint(0, position.y())).block();
    if (!block.isValid())
        return;
    if (position.x() <= kMarkColumnWidth + 2) {
        Q_EMIT breakpointToggleRequested(block.blockNumber() + 1);
        return;
    }
    if (position.x() < m_lineNumberArea->width() - kFoldColumnWidth - 2)
        return;
    for (const FoldRange &range : std::as_const(m_foldRanges)) {
        if (range.firstLine == block.blockNumber()) {
            toggleFold(range.firstLine);
            return;
        }
    }
}

// ---- extra selections: current line, diagnostics, brackets ---------------------------------

int CodeEditor::bracketMatch(int position) const
{
    const QTextBlock block = document()->findBlock(position);
    // Search a window of lines around the bracket, starting in the lexer state of its first line.
    QTextBlock first = block;
    for (int i = 0; i < kBracketWindowLines && first.previous().isValid(); ++i)
        first = first.previous();
    QTextBlock last = block;
    for (int i = 0; i < kBracketWindowLines && last.next().isValid(); ++i)
        last = last.next();
    const int start = first.position();
    const int end = last.position() + last.length() - 1;
    QTextCursor range(document());
    range.setPosition(start);
    range.setPosition(end, QTextCursor::KeepAnchor);
    QString text = range.selectedText();
    text.replace(QChar::ParagraphSeparator, QLatin1Char('\n'));
    const int match = matchingBracket(text, position - start, CodeHighlighter::stateAfter(first.previous()));
    return match < 0 ? match : match + start;
}

void CodeEditor::updateExtraSelections()
{
    QList<QTextEdit::ExtraSelection> selections;
    {
        QTextEdit::ExtraSelection line;
        line.format.setBackground(kCurrentLine);
        line.format.setProperty(QTextFormat::FullWidthSelection, true);
        line.cursor = textCursor();
        line.cursor.clearSelection();
        selections.append(line);
    }
    if (m_haltedLine > 0) {
        if (const QTextBlock block = document()->findBlockByNumber(m_haltedLine - 1); block.isValid()) {
            QTextEdit::ExtraSelection halted;
            halted.format.setBackground(kHaltedLine);
            halted.format.setProperty(QTextFormat::FullWidthSelection, true);
            halted.cursor = QTextCursor(block);
            selections.append(halted);
        }
    }
    for (const PlacedDiagnostic &placed : std::as_const(m_diagnostics)) {
        QTextEdit::ExtraSelection underline;
        underline.cursor = placed.range;
        underline.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        underline.format.setUnderlineColor(severityColor(placed.diagnostic.severity));
        selections.append(underline);
    }
    const QTextCursor cursor = textCursor();
    if (!cursor.hasSelection()) {
        const int position = cursor.position();
        auto isBracket = [this](int at) {
            const QChar c = document()->characterAt(at);
            return c == QLatin1Char('(') || c == QLatin1Char(')') || c == QLatin1Char('[') || c == QLatin1Char(']');
        };
        int at = -1;
        int match = kNoBracket;
        if (isBracket(position)) {
            at = position;
            match = bracketMatch(at);
        }
        if (match == kNoBracket && position > 0 && isBracket(position - 1)) {
            at = position - 1;
            match = bracketMatch(at);
        }
        if (match != kNoBracket) {
            for (int p : {at, match}) {
                if (p < 0)
                    continue;
                QTextEdit::ExtraSelection bracket;
                bracket.format.setBackground(match >= 0 ? kBracketMatch : kBracketMismatch);
                bracket.cursor = QTextCursor(document());
                bracket.cursor.setPosition(p);
                bracket.cursor.setPosition(p + 1, QTextCursor::KeepAnchor);
                selections.append(bracket);
            }
        }
    }
    setExtraSelections(selections);
}

// ---- diagnostics ----------------------------------------------------------------------------

void CodeEditor::setDiagnostics(const QList<TextDiagnostic> &diagnostics)
{
    m_diagnostics.clear();
    for (const TextDiagnostic &diagnostic : diagnostics) {
        const QTextBlock block = document()->findBlockByNumber(diagnostic.line - 1);
        if (!block.isValid())
            continue;
        const int lineStart = block.position();
        const int lineEnd = lineStart + block.length() - 1;
        int start = std::min(lineStart + std::max(0, diagnostic.column - 1), lineEnd);
        const int end = std::min(start + std::max(1, diagnostic.length), lineEnd);
        if (start == end && start > lineStart)
            start = end - 1; // at the end of a line: underline its last character
        QTextCursor range(document());
        range.setPosition(start);
        range.setPosition(end, QTextCursor::KeepAnchor);
        m_diagnostics.append({diagnostic, range});
    }
    updateExtraSelections();
    m_lineNumberArea->update();
}

QList<TextDiagnostic> CodeEditor::diagnostics() const
{
    QList<TextDiagnostic> result;
    for (const PlacedDiagnostic &placed : m_diagnostics) {
        TextDiagnostic diagnostic = placed.diagnostic;
        const QTextBlock block = document()->findBlock(placed.range.selectionStart());
        diagnostic.line = block.blockNumber() + 1;
        diagnostic.column = placed.range.selectionStart() - block.position() + 1;
        diagnostic.length = placed.range.selectionEnd() - placed.range.selectionStart();
        result.append(diagnostic);
    }
    return result;
}

QString CodeEditor::diagnosticMessageAt(int position) const
{
    QStringList messages;
    for (const PlacedDiagnostic &placed : m_diagnostics) {
        if (placed.range.selectionStart() <= position && position < placed.range.selectionEnd())
            messages.append(placed.diagnostic.message);
    }
    return messages.join(QLatin1Char('\n'));
}

bool CodeEditor::viewportEvent(QEvent *event)
{
    if (event->type() == QEvent::ToolTip) {
        auto *help = static_cast<QHelpEvent *>(event);
        const QTextCursor cursor = cursorForPosition(help->pos());
        // cursorForPosition rounds to the nearest gap: look at the character under the mouse.
        int position = cursor.position();
        const QRect rect = cursorRect(cursor);
        if (help->pos().x() < rect.left() && position > 0)
            --position;
        const QString message = diagnosticMessageAt(position);
        if (message.isEmpty())
            QToolTip::hideText();
        else
            QToolTip::showText(help->globalPos(), message, viewport());
        return true;
    }
    return QPlainTextEdit::viewportEvent(event);
}

// ---- folding --------------------------------------------------------------------------------

void CodeEditor::updateFoldRangesNow()
{
    m_foldTimer.stop();
    m_foldRanges = foldingRanges(toPlainText(), m_language);
    m_lastBlockCount = document()->blockCount();
    applyFoldVisibility();
    m_lineNumberArea->update();
}

bool CodeEditor::isFolded(int firstLine) const
{
    for (const FoldRange &range : m_foldRanges) {
        if (range.firstLine == firstLine) {
            const QTextBlock next = document()->findBlockByNumber(firstLine + 1);
            return next.isValid() && !next.isVisible();
        }
    }
    return false;
}

static void setBlocksVisible(QTextDocument *document, int firstLine, int lastLine, bool visible)
{
    QTextBlock block = document->findBlockByNumber(firstLine);
    const int start = block.position();
    int end = start;
    for (; block.isValid() && block.blockNumber() <= lastLine; block = block.next()) {
        block.setVisible(visible);
        block.setLineCount(visible ? std::max(1, block.layout()->lineCount()) : 0);
        end = block.position() + block.length();
    }
    document->markContentsDirty(start, end - start);
}

void CodeEditor::relayout()
{
    viewport()->update();
    m_lineNumberArea->update();
}

bool CodeEditor::fold(int firstLine)
{
    for (const FoldRange &range : std::as_const(m_foldRanges)) {
        if (range.firstLine != firstLine)
            continue;
        const bool wasSetting = m_settingText;
        m_settingText = true;
        setBlocksVisible(document(), range.firstLine + 1, range.lastLine, false);
        m_settingText = wasSetting;
        m_hasHiddenBlocks = true;
        const int line = textCursor().blockNumber();
        if (line > range.firstLine && line <= range.lastLine) {
            QTextCursor cursor(document()->findBlockByNumber(range.firstLine));
            cursor.movePosition(QTextCursor::EndOfBlock);
            setTextCursor(cursor);
            ensureCursorVisible();
        }
        relayout();
        return true;
    }
    return false;
}

bool CodeEditor::unfold(int firstLine)
{
    for (const FoldRange &range : std::as_const(m_foldRanges)) {
        if (range.firstLine != firstLine || !isFolded(firstLine))
            continue;
        const bool wasSetting = m_settingText;
        m_settingText = true;
        setBlocksVisible(document(), range.firstLine + 1, range.lastLine, true);
        m_settingText = wasSetting;
        relayout();
        return true;
    }
    return false;
}

void CodeEditor::toggleFold(int firstLine)
{
    if (isFolded(firstLine))
        unfold(firstLine);
    else
        fold(firstLine);
}

void CodeEditor::unfoldAll()
{
    if (!m_hasHiddenBlocks)
        return;
    const bool wasSetting = m_settingText;
    m_settingText = true;
    setBlocksVisible(document(), 0, document()->blockCount() - 1, true);
    m_settingText = wasSetting;
    m_hasHiddenBlocks = false;
    relayout();
}

void CodeEditor::applyFoldVisibility()
{
    if (!m_hasHiddenBlocks)
        return;
    // A block stays hidden only while a folded range still covers it.
    std::vector<bool> covered(size_t(document()->blockCount()), false);
    for (const FoldRange &range : std::as_const(m_foldRanges)) {
        const QTextBlock first = document()->findBlockByNumber(range.firstLine);
        const QTextBlock next = first.next();
        if (!first.isVisible() || !next.isValid() || next.isVisible())
            continue;
        for (int line = range.firstLine + 1; line <= range.lastLine && line < int(covered.size()); ++line)
            covered[size_t(line)] = true;
    }
    bool anyHidden = false;
    bool changed = false;
    const bool wasSetting = m_settingText;
    m_settingText = true;
    for (QTextBlock block = document()->begin(); block.isValid(); block = block.next()) {
        if (block.isVisible())
            continue;
        if (covered[size_t(block.blockNumber())]) {
            anyHidden = true;
        } else {
            setBlocksVisible(document(), block.blockNumber(), block.blockNumber(), true);
            changed = true;
        }
    }
    m_settingText = wasSetting;
    m_hasHiddenBlocks = anyHidden;
    if (changed)
        relayout();
}

void CodeEditor::paintEvent(QPaintEvent *event)
{
    QPlainTextEdit::paintEvent(event);
    paintOnlineChips(event);
    if (!m_hasHiddenBlocks)
        return;
    // A "…" box after each folded line.
    QPainter painter(viewport());
    painter.setRenderHint(QPainter::Antialiasing);
    QTextBlock block = firstVisibleBlock();
    const QPointF offset = contentOffset();
    while (block.isValid()) {
        const QRectF geometry = blockBoundingGeometry(block).translated(offset);
        if (geometry.top() > event->rect().bottom())
            break;
        if (block.isVisible() && isFolded(block.blockNumber())) {
            const QTextLayout *layout = block.layout();
            const qreal textWidth = layout->lineCount() > 0 ? layout->lineAt(0).naturalTextWidth() : 0;
            const qreal x = geometry.left() + document()->documentMargin() + textWidth + 8;
            const QRectF box(x, geometry.top() + 2, fontMetrics().horizontalAdvance(QStringLiteral("...")) + 8,
                fontMetrics().height() - 3);
            painter.setPen(QColor(0xa0, 0xa0, 0xa0));
            painter.setBrush(QColor(0xf0, 0xf0, 0xf0));
            painter.drawRoundedRect(box, 3, 3);
            painter.setPen(QColor(0x60, 0x60, 0x60));
            painter.drawText(box, Qt::AlignCenter, QStringLiteral("..."));
        }
        block = block.next();
    }
}

// ---- online mode ----------------------------------------------------------------------------

QString CodeEditor::onlineEditRefusal()
{
    return tr("The program is online, so its text cannot be changed. Choose Online > Logout to edit it.");
}

void CodeEditor::setOnline(bool online)
{
    if (online == m_online)
        return;
    m_online = online;
    setReadOnly(online);
    // Read-only hides the text cursor, which online mode still uses to point at variables.
    setTextInteractionFlags(online ? Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard
                                   : Qt::TextEditorInteraction);
    if (!online)
        m_onlineChips.clear();
    viewport()->update();
}

void CodeEditor::setOnlineChips(std::vector<QList<OnlineChip>> chipsByLine)
{
    if (chipsByLine == m_onlineChips)
        return;
    m_onlineChips = std::move(chipsByLine);
    viewport()->update();
}

bool CodeEditor::refuseEditWhileOnline(const QKeyEvent *event)
{
    if (!m_online)
        return false;
    const int key = event->key();
    const bool changesText = (!event->text().isEmpty() && event->text().front().isPrint()
                                 && !(event->modifiers() & (Qt::ControlModifier | Qt::AltModifier)))
        || key == Qt::Key_Backspace || key == Qt::Key_Delete || key == Qt::Key_Return || key == Qt::Key_Enter
        || key == Qt::Key_Tab || key == Qt::Key_Backtab || event->matches(QKeySequence::Paste)
        || event->matches(QKeySequence::Cut) || event->matches(QKeySequence::Undo)
        || event->matches(QKeySequence::Redo) || (key == Qt::Key_Slash && event->modifiers() & Qt::ControlModifier)
        || (key == Qt::Key_F2 && event->modifiers() == Qt::NoModifier)
        || (key == Qt::Key_Space && event->modifiers() & Qt::ControlModifier);
    if (!changesText)
        return false;
    QToolTip::showText(viewport()->mapToGlobal(cursorRect().bottomLeft()), onlineEditRefusal(), this);
    Q_EMIT editRefused(onlineEditRefusal());
    return true;
}

void CodeEditor::paintOnlineChips(const QPaintEvent *event)
{
    if (!m_online || m_onlineChips.empty())
        return;
    QPainter painter(viewport());
    const QPointF offset = contentOffset();
    for (QTextBlock block = firstVisibleBlock(); block.isValid(); block = block.next()) {
        const QRectF geometry = blockBoundingGeometry(block).translated(offset);
        if (geometry.top() > event->rect().bottom())
            break;
        const auto line = size_t(block.blockNumber());
        if (!block.isVisible() || line >= m_onlineChips.size() || m_onlineChips[line].isEmpty())
            continue;
        const QTextLayout *layout = block.layout();
        const qreal textWidth = layout->lineCount() > 0 ? layout->lineAt(0).naturalTextWidth() : 0;
        const qreal x = geometry.left() + document()->documentMargin() + textWidth + 16;
        const QRectF lineRect(geometry.left(), geometry.top(), geometry.width(), fontMetrics().height());
        editors::paintOnlineChips(painter, lineRect, x, m_onlineChips[line], fontMetrics());
    }
}


void CodeEditor::setBreakpointLines(const QList<int> &lines, const QList<int> &disabledLines)
{
    if (lines == m_breakpointLines && disabledLines == m_disabledBreakpointLines)
        return;
    m_breakpointLines = lines;
    m_disabledBreakpointLines = disabledLines;
    m_lineNumberArea->update();
}

void CodeEditor::setHaltedLine(int line)
{
    if (line == m_haltedLine)
        return;
    m_haltedLine = line;
    if (line > 0)
        goToLine(line);
    updateExtraSelections();
    m_lineNumberArea->update();
}

} // namespace iec::editors
