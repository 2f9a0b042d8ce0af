// The code editor (codeeditor.h): text and undo, keys and indentation, completion, the input
// assistant and go to definition; its display is in codeeditorview.cpp.
#include "editors/text/codeeditor.h"

#include "editors/text/calltext.h"

#include "editors/text/blockrules.h"
#include "editors/text/codehighlighter.h"
#include "editors/text/commenttoggle.h"
#include "editors/text/foldingregions.h"
#include "editors/text/inputassistant.h"
#include "editors/text/linenumberarea.h"
#include "model/filetext.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QContextMenuEvent>
#include <QFontDatabase>
#include <QHash>
#include <QMenu>
#include <QMimeData>
#include <QPainter>
#include <QScrollBar>
#include <QStandardItemModel>
#include <QStyledItemDelegate>
#include <QTextBlock>
#include <QToolTip>

namespace iec::editors {

namespace {

constexpr int kDetailRole = Qt::UserRole + 1;

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
    if (isReadOnly())
        return;
    const QString callType = mimeCallMimeType(m_language);
    const bool call = source->hasFormat(callType);
    if (!call && !source->hasText()) {
        QPlainTextEdit::insertFromMimeData(source);
        return;
    }
    const QString text = call ? QString::fromUtf8(source->data(callType)) : source->text();
    // Only what the project file can keep: a control character copied from elsewhere would be
    // lost or make the file unreadable when it is saved (model/filetext.h).
    QTextCursor cursor = textCursor();
    cursor.insertText(model::withoutCharactersAFileCannotKeep(text));
    setTextCursor(cursor);
}

} // namespace iec::editors
