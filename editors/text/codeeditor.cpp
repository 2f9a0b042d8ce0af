#include "editors/text/codeeditor.h"

#include "editors/text/calltext.h"

#include "editors/text/blockrules.h"
#include "editors/text/bracketmatcher.h"
#include "editors/text/codehighlighter.h"
#include "editors/text/commenttoggle.h"
#include "editors/text/foldingregions.h"
#include "editors/text/inputassistant.h"
#include "editors/text/linenumberarea.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QContextMenuEvent>
#include <QFontDatabase>
#include <QHash>
#include <QMenu>
#include <QMimeData>
#include <QPainter>
#include <QPainterPath>
#include <QScrollBar>
#include <QStandardItemModel>
#include <QStyledItemDelegate>
#include <QTextBlock>
#include <QToolTip>

namespace iec::editors {

namespace {

constexpr int kDetailRole = Qt::UserRole + 1;
constexpr int kFoldColumnWidth = 14;
constexpr int kMarkColumnWidth = 10;
constexpr int kBracketWindowLines = 150; // lines searched each way for a matching bracket

const QColor kCurrentLine(0xe8, 0xf2, 0xfe);
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

QIcon kindIcon(CompletionItem::Kind kind, QHash<int, QIcon> &cache)
{
    const auto it = cache.constFind(int(kind));
    if (it != cache.constEnd())
        return *it;
    using K = CompletionItem::Kind;
    struct Look {
        char letter;
        QColor color;
    };
    Look look {'?', Qt::gray};
    switch (kind) {
    case K::Keyword:
        look = {'K', QColor(0x00, 0x33, 0xb3)};
        break;
    case K::TypeName:
        look = {'T', QColor(0x00, 0x80, 0x80)};
        break;
    case K::Variable:
        look = {'V', QColor(0xb0, 0x5a, 0x00)};
        break;
    case K::Member:
        look = {'M', QColor(0xb0, 0x5a, 0x00)};
        break;
    case K::Function:
        look = {'F', QColor(0x6f, 0x42, 0xc1)};
        break;
    case K::FunctionBlock:
        look = {'B', QColor(0x6f, 0x42, 0xc1)};
        break;
    case K::Program:
        look = {'P', QColor(0x3f, 0x7f, 0x3f)};
        break;
    case K::Operator:
        look = {'O', QColor(0x50, 0x50, 0x50)};
        break;
    case K::Constant:
        look = {'C', QColor(0x17, 0x50, 0xeb)};
        break;
    }
    QPixmap pixmap(28, 28);
    pixmap.setDevicePixelRatio(2.0);
    pixmap.fill(Qt::transparent);
    {
        QPainter painter(&pixmap);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(Qt::NoPen);
        painter.setBrush(look.color);
        painter.drawRoundedRect(QRectF(0.5, 0.5, 13, 13), 3, 3);
        QFont font;
        font.setPixelSize(10);
        font.setBold(true);
        painter.setFont(font);
        painter.setPen(Qt::white);
        painter.drawText(QRectF(0.5, 0.5, 13, 13), Qt::AlignCenter, QString(QLatin1Char(look.letter)));
    }
    const QIcon icon(pixmap);
    cache.insert(int(kind), icon);
    return icon;
}

// Draws a completion entry as "name  detail", the detail (a type or the parameters) in grey.
class CompletionDelegate : public QStyledItemDelegate
{
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    void paint(QPainter *painter, const QStyleOptionViewItem &option, const QModelIndex &index) const override
    {
        QStyledItemDelegate::paint(painter, option, index);
        const QString detail = index.data(kDetailRole).toString();
        if (detail.isEmpty())
            return;
        QStyleOptionViewItem opt = option;
        initStyleOption(&opt, index);
        const int nameWidth = opt.fontMetrics.horizontalAdvance(opt.text);
        QRect rect = opt.rect.adjusted(opt.decorationSize.width() + 8 + nameWidth + 12, 0, -4, 0);
        painter->save();
        painter->setPen((option.state & QStyle::State_Selected) ? option.palette.highlightedText().color()
                                                                : QColor(0x80, 0x80, 0x80));
        painter->drawText(
            rect, Qt::AlignVCenter | Qt::AlignLeft, opt.fontMetrics.elidedText(detail, Qt::ElideRight, rect.width()));
        painter->restore();
    }
};

QString spaces(int count)
{
    return QString(std::max(0, count), QLatin1Char(' '));
}

int leadingWhitespaceLength(const QString &text)
{
    int i = 0;
    while (i < text.size() && (text[i] == QLatin1Char(' ') || text[i] == QLatin1Char('\t')))
        ++i;
    return i;
}

} // namespace

CodeEditor::CodeEditor(TextLanguage language, QWidget *parent)
    : QPlainTextEdit(parent)
    , m_language(language)
{
    setObjectName(QStringLiteral("codeEditor"));
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setStyleHint(QFont::TypeWriter);
    if (font.pointSizeF() < 10)
        font.setPointSizeF(10);
    setFont(font);
    setLineWrapMode(QPlainTextEdit::NoWrap);
    setTabStopDistance(fontMetrics().horizontalAdvance(QLatin1Char(' ')) * kIndentWidth);
    setCursorWidth(2);

    m_highlighter = new CodeHighlighter(language, document());
    m_lineNumberArea = new LineNumberArea(this);

    connect(this, &QPlainTextEdit::blockCountChanged, this, [this] { updateLineNumberAreaWidth(); });
    connect(this, &QPlainTextEdit::updateRequest, this, &CodeEditor::updateLineNumberArea);
    connect(this, &QPlainTextEdit::cursorPositionChanged, this, [this] {
        if (m_hasHiddenBlocks && !textCursor().block().isVisible()) {
            const int line = textCursor().blockNumber();
            for (const FoldRange &range : std::as_const(m_foldRanges)) {
                if (range.firstLine < line && line <= range.lastLine && isFolded(range.firstLine))
                    unfold(range.firstLine);
            }
        }
        updateExtraSelections();
        m_lineNumberArea->update();
    });
    connect(document(), &QTextDocument::contentsChange, this, &CodeEditor::onContentsChange);

    m_editTimer.setSingleShot(true);
    m_editTimer.setInterval(300);
    connect(&m_editTimer, &QTimer::timeout, this, &CodeEditor::textEdited);
    m_foldTimer.setSingleShot(true);
    m_foldTimer.setInterval(250);
    connect(&m_foldTimer, &QTimer::timeout, this, &CodeEditor::updateFoldRangesNow);

    m_completionModel = new QStandardItemModel(this);
    m_completer = new QCompleter(m_completionModel, this);
    m_completer->setWidget(this);
    m_completer->setCompletionMode(QCompleter::PopupCompletion);
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setModelSorting(QCompleter::UnsortedModel);
    m_completer->setMaxVisibleItems(12);
    m_completer->setWrapAround(false);
    m_completer->popup()->setItemDelegate(new CompletionDelegate(m_completer->popup()));
    m_completer->popup()->setObjectName(QStringLiteral("completionPopup"));
    connect(m_completer, qOverload<const QString &>(&QCompleter::activated), this, &CodeEditor::insertCompletion);

    updateLineNumberAreaWidth();
    updateExtraSelections();
}

CodeEditor::~CodeEditor() = default;

void CodeEditor::setBodyTextKeepingCursor(const QString &text)
{
    const QTextCursor before = textCursor();
    const int line = before.blockNumber();
    const int column = before.positionInBlock();
    const int scroll = verticalScrollBar()->value();
    setBodyText(text);
    const QTextBlock block = document()->findBlockByNumber(std::min(line, document()->blockCount() - 1));
    QTextCursor cursor(block);
    cursor.setPosition(block.position() + std::min(column, int(block.length()) - 1));
    setTextCursor(cursor);
    verticalScrollBar()->setValue(scroll);
}

InputAssistantDialog *CodeEditor::inputAssistant() const
{
    return m_assistant;
}

void CodeEditor::setLanguage(TextLanguage language)
{
    if (language == m_language)
        return;
    m_language = language;
    m_highlighter->setLanguage(language);
    updateFoldRangesNow();
}

void CodeEditor::setBodyText(const QString &text)
{
    m_settingText = true;
    unfoldAll();
    m_diagnostics.clear();
    setPlainText(text); // also starts a fresh undo history
    m_settingText = false;
    m_editTimer.stop();
    updateFoldRangesNow();
    updateExtraSelections();
}

void CodeEditor::flushPendingEdit()
{
    if (!m_editTimer.isActive())
        return;
    m_editTimer.stop();
    Q_EMIT textEdited();
}

void CodeEditor::onContentsChange(int position, int removed, int added)
{
    if (removed == 0 && added == 0)
        return;
    // Keep the fold markers roughly in place until the debounced recomputation.
    const int blocks = document()->blockCount();
    const int delta = blocks - m_lastBlockCount;
    if (delta != 0 && !m_foldRanges.isEmpty()) {
        const int line = document()->findBlock(position).blockNumber();
        for (FoldRange &range : m_foldRanges) {
            if (range.firstLine > line)
                range.firstLine += delta;
            if (range.lastLine > line)
                range.lastLine += delta;
        }
        m_foldRanges.removeIf([](const FoldRange &r) { return r.lastLine <= r.firstLine || r.firstLine < 0; });
    }
    m_lastBlockCount = blocks;
    if (m_settingText)
        return;
    m_editTimer.start();
    m_foldTimer.start();
}

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
    if (position.x() < m_lineNumberArea->width() - kFoldColumnWidth - 2)
        return;
    const QTextBlock block = cursorForPosition(QPoint(0, position.y())).block();
    if (!block.isValid())
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

// ---- editing --------------------------------------------------------------------------------

void CodeEditor::keyPressEvent(QKeyEvent *event)
{
    if (refuseEditWhileOnline(event))
        return;
    const bool popupVisible = m_completer->popup()->isVisible();
    if (popupVisible) {
        switch (event->key()) {
        case Qt::Key_Enter:
        case Qt::Key_Return:
        case Qt::Key_Escape:
        case Qt::Key_Tab:
        case Qt::Key_Backtab:
            event->ignore(); // the completer takes these
            return;
        default:
            break;
        }
    }
    const Qt::KeyboardModifiers modifiers = event->modifiers() & ~Qt::KeypadModifier;
    if (event->key() == Qt::Key_Space && modifiers == Qt::ControlModifier) {
        showCompletion();
        return;
    }
    if (event->key() == Qt::Key_F2 && modifiers == Qt::NoModifier) {
        openInputAssistant();
        return;
    }
    if (event->key() == Qt::Key_F12 && modifiers == Qt::NoModifier) {
        requestDefinition();
        return;
    }
    if (event->key() == Qt::Key_Slash && modifiers == Qt::ControlModifier) {
        toggleComment();
        return;
    }
    if ((event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter)
        && (modifiers == Qt::NoModifier || modifiers == Qt::ShiftModifier) && !isReadOnly()) {
        handleEnter();
        return;
    }
    if (event->key() == Qt::Key_Tab && modifiers == Qt::NoModifier && !isReadOnly()) {
        handleTab(false);
        return;
    }
    if (event->key() == Qt::Key_Backtab && !isReadOnly()) {
        handleTab(true);
        return;
    }

    QPlainTextEdit::keyPressEvent(event);

    const QString typed = event->text();
    if (typed == QLatin1String(" ") || typed == QLatin1String(";"))
        reindentClosingKeyword();
    if (m_completer->popup()->isVisible()) {
        updateCompletionPrefix();
    } else if (typed == QLatin1String(".") && m_provider) {
        const QTextCursor cursor = textCursor();
        const CompletionContext context = completionContext(cursor.block().text(), cursor.positionInBlock());
        if (!context.memberPath.isEmpty() && !context.memberPath.front().isDigit())
            showCompletion();
    }
}

void CodeEditor::handleEnter()
{
    QTextCursor cursor = textCursor();
    cursor.beginEditBlock();
    if (cursor.hasSelection())
        cursor.removeSelectedText();
    setTextCursor(cursor);
    reindentClosingKeyword();
    cursor = textCursor();

    const QTextBlock block = cursor.block();
    const QString following = toPlainText().mid(block.position() + block.length());
    const EnterEdit edit = enterEdit(block.text(), cursor.positionInBlock(), following, m_language);
    if (edit.removeAfter > 0) {
        cursor.setPosition(cursor.position() + edit.removeAfter, QTextCursor::KeepAnchor);
        cursor.removeSelectedText();
    }
    const int start = cursor.position();
    cursor.insertText(edit.text);
    cursor.setPosition(start + edit.cursorOffset);
    cursor.endEditBlock();
    setTextCursor(cursor);
    ensureCursorVisible();
}

void CodeEditor::reindentClosingKeyword()
{
    const QTextBlock block = textCursor().block();
    QTextBlock previous = block.previous();
    while (previous.isValid() && previous.text().trimmed().isEmpty())
        previous = previous.previous();
    if (!previous.isValid())
        return;
    const QString text = block.text();
    const int wanted = closingKeywordIndent(text, previous.text(), m_language);
    if (wanted < 0)
        return;
    QTextCursor edit(block);
    edit.joinPreviousEditBlock();
    edit.setPosition(block.position() + leadingWhitespaceLength(text), QTextCursor::KeepAnchor);
    edit.insertText(spaces(wanted));
    edit.endEditBlock();
}

void CodeEditor::handleTab(bool backward)
{
    QTextCursor cursor = textCursor();
    const QTextBlock first = document()->findBlock(cursor.selectionStart());
    const QTextBlock last = document()->findBlock(cursor.selectionEnd());
    if (!backward && first == last) {
        const int column = cursor.positionInBlock();
        cursor.insertText(spaces(kIndentWidth - column % kIndentWidth));
        setTextCursor(cursor);
        return;
    }
    cursor.beginEditBlock();
    for (QTextBlock block = first; block.isValid(); block = block.next()) {
        const QString text = block.text();
        QTextCursor edit(block);
        if (backward) {
            const int remove = std::min<int>(leadingWhitespaceLength(text), kIndentWidth);
            edit.setPosition(block.position() + remove, QTextCursor::KeepAnchor);
            edit.removeSelectedText();
        } else if (!text.trimmed().isEmpty()) {
            edit.insertText(spaces(kIndentWidth));
        }
        if (block == last)
            break;
    }
    cursor.endEditBlock();
}

void CodeEditor::toggleComment()
{
    if (m_online) {
        Q_EMIT editRefused(onlineEditRefusal());
        return;
    }
    QTextCursor cursor = textCursor();
    const QTextBlock first = document()->findBlock(cursor.selectionStart());
    QTextBlock last = document()->findBlock(cursor.selectionEnd());
    // A selection that ends at the start of a line does not include that line.
    if (cursor.hasSelection() && last != first && cursor.selectionEnd() == last.position())
        last = last.previous();

    QStringList lines;
    for (QTextBlock block = first;; block = block.next()) {
        lines.append(block.text());
        if (block == last)
            break;
    }
    const QStringList toggled = toggleLineComments(lines);
    if (toggled == lines)
        return;

    const bool wasSelection = cursor.hasSelection();
    const int column = cursor.positionInBlock();
    const int firstPosition = first.position();
    QTextCursor edit(document());
    edit.beginEditBlock();
    edit.setPosition(first.position());
    edit.setPosition(last.position() + last.length() - 1, QTextCursor::KeepAnchor);
    edit.insertText(toggled.join(QLatin1Char('\n')));
    edit.endEditBlock();

    QTextCursor after(document());
    if (wasSelection) {
        after.setPosition(firstPosition);
        after.setPosition(edit.position(), QTextCursor::KeepAnchor);
    } else {
        after.setPosition(firstPosition + std::min<int>(column, int(toggled.first().size())));
    }
    setTextCursor(after);
}

// ---- completion, input assistant, go to definition -----------------------------------------

void CodeEditor::showCompletion()
{
    const QTextCursor cursor = textCursor();
    const CompletionContext context = completionContext(cursor.block().text(), cursor.positionInBlock());
    const QList<CompletionItem> items = completionItems(context, m_provider, m_language);
    m_completionStart = cursor.block().position() + context.prefixStart;
    if (items.isEmpty()) {
        m_completer->popup()->hide();
        return;
    }
    if (items.size() == 1 && !context.prefix.isEmpty()) {
        insertCompletion(items.first().text);
        return;
    }
    m_completionModel->clear();
    for (const CompletionItem &item : items) {
        auto *row = new QStandardItem(kindIcon(item.kind, m_kindIcons), item.text);
        row->setData(item.detail, kDetailRole);
        row->setToolTip(item.detail);
        row->setEditable(false);
        m_completionModel->appendRow(row);
    }
    m_completer->setCompletionPrefix(context.prefix);
    QRect rect = cursorRect();
    rect.translate(viewportMargins().left(), 0);
    rect.setWidth(std::max(360, m_completer->popup()->sizeHintForColumn(0) + 220));
    m_completer->complete(rect);
    m_completer->popup()->setCurrentIndex(m_completer->completionModel()->index(0, 0));
}

void CodeEditor::updateCompletionPrefix()
{
    const QTextCursor cursor = textCursor();
    const int position = cursor.position();
    if (m_completionStart < 0 || position < m_completionStart
        || document()->findBlock(m_completionStart) != cursor.block()) {
        m_completer->popup()->hide();
        return;
    }
    QTextCursor prefixCursor(document());
    prefixCursor.setPosition(m_completionStart);
    prefixCursor.setPosition(position, QTextCursor::KeepAnchor);
    const QString prefix = prefixCursor.selectedText();
    if (!std::all_of(prefix.begin(), prefix.end(), isIdentifierChar)) {
        m_completer->popup()->hide();
        return;
    }
    m_completer->setCompletionPrefix(prefix);
    if (m_completer->completionCount() == 0) {
        m_completer->popup()->hide();
        return;
    }
    m_completer->popup()->setCurrentIndex(m_completer->completionModel()->index(0, 0));
}

void CodeEditor::insertCompletion(const QString &text)
{
    QTextCursor cursor = textCursor();
    const int end = cursor.position();
    if (m_completionStart >= 0 && m_completionStart <= end)
        cursor.setPosition(m_completionStart);
    cursor.setPosition(end, QTextCursor::KeepAnchor);
    cursor.insertText(text);
    setTextCursor(cursor);
    m_completionStart = -1;
}

void CodeEditor::openInputAssistant()
{
    if (m_online) {
        Q_EMIT editRefused(onlineEditRefusal());
        return;
    }
    if (m_assistant)
        m_assistant->close();
    auto *dialog = new InputAssistantDialog(m_language, m_provider, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &InputAssistantDialog::itemChosen, this, [this](const QString &text) {
        QTextCursor cursor = textCursor();
        cursor.insertText(text); // replaces the selection, as RunPro does
        setTextCursor(cursor);
        setFocus();
    });
    m_assistant = dialog;
    dialog->open();
}

void CodeEditor::openInputAssistantOn(InputAssistantDialog::Category category)
{
    openInputAssistant();
    if (m_assistant)
        m_assistant->setCategory(category);
}

QString CodeEditor::identifierPathAt(int position) const
{
    const QTextBlock block = document()->findBlock(position);
    if (!block.isValid())
        return {};
    const QString line = block.text();
    int end = position - block.position();
    while (end < line.size() && isIdentifierChar(line[end]))
        ++end;
    const CompletionContext context = completionContext(line, end);
    if (context.prefix.isEmpty() || context.prefix.front().isDigit())
        return {};
    return context.memberPath.isEmpty() ? context.prefix : context.memberPath + QLatin1Char('.') + context.prefix;
}

void CodeEditor::requestDefinition()
{
    const QTextCursor cursor = textCursor();
    const QString path = identifierPathAt(cursor.position());
    if (path.isEmpty())
        return;
    const QString line = cursor.block().text();
    int start = cursor.positionInBlock();
    while (start > 0 && isIdentifierChar(line[start - 1]))
        --start;
    Q_EMIT definitionRequested(path, cursor.blockNumber() + 1, start + 1);
}

void CodeEditor::goToLine(int line, int column)
{
    const QTextBlock block = document()->findBlockByNumber(std::clamp(line - 1, 0, blockCount() - 1));
    QTextCursor cursor(block);
    cursor.setPosition(block.position() + std::clamp(column - 1, 0, block.length() - 1));
    setTextCursor(cursor); // unfolds through cursorPositionChanged
    centerCursor();
}

void CodeEditor::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && event->modifiers() == Qt::ControlModifier) {
        setTextCursor(cursorForPosition(event->position().toPoint()));
        requestDefinition();
        event->accept();
        return;
    }
    QPlainTextEdit::mousePressEvent(event);
}

void CodeEditor::contextMenuEvent(QContextMenuEvent *event)
{
    QMenu *menu = createStandardContextMenu(event->pos());
    menu->addSeparator();
    QAction *definition = menu->addAction(tr("Go to Definition"), this, &CodeEditor::requestDefinition);
    definition->setShortcut(Qt::Key_F12);
    definition->setEnabled(!identifierPathAt(cursorForPosition(event->pos()).position()).isEmpty());
    QAction *complete = menu->addAction(tr("Complete"), this, &CodeEditor::showCompletion);
    complete->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Space));
    QAction *assistant = menu->addAction(tr("Input Assistant..."), this, &CodeEditor::openInputAssistant);
    assistant->setShortcut(Qt::Key_F2);
    QAction *comment = menu->addAction(tr("Toggle Comment"), this, &CodeEditor::toggleComment);
    comment->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Slash));
    // Commands the application adds to the editor (Declare Variable...).
    menu->addActions(actions());
    menu->addSeparator();
    menu->addAction(tr("Fold All"), this, [this] {
        for (const FoldRange &range : std::as_const(m_foldRanges))
            fold(range.firstLine);
    });
    menu->addAction(tr("Unfold All"), this, &CodeEditor::unfoldAll);
    menu->addSeparator();
    const QString watchPath = identifierPathAt(cursorForPosition(event->pos()).position());
    QAction *watch = menu->addAction(tr("Add to Watch"), this, [this, watchPath] { Q_EMIT addToWatchRequested(watchPath); });
    watch->setEnabled(!watchPath.isEmpty());
    menu->exec(event->globalPos());
    delete menu;
}

bool CodeEditor::canInsertFromMimeData(const QMimeData *source) const
{
    return source->hasFormat(mimeCallMimeType(m_language)) || QPlainTextEdit::canInsertFromMimeData(source);
}

void CodeEditor::insertFromMimeData(const QMimeData *source)
{
    const QString callType = mimeCallMimeType(m_language);
    if (!source->hasFormat(callType) || isReadOnly()) {
        QPlainTextEdit::insertFromMimeData(source);
        return;
    }
    QTextCursor cursor = textCursor();
    cursor.insertText(QString::fromUtf8(source->data(callType)));
    setTextCursor(cursor);
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

} // namespace iec::editors
