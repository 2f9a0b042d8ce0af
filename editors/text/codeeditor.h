#pragma once

#include "editors/text/completion.h"
#include "editors/text/inputassistant.h"
#include "editors/text/onlinevalues.h"
#include "editors/text/textlanguage.h"

#include <QHash>
#include <QIcon>
#include <QPlainTextEdit>
#include <QPointer>
#include <QTimer>

class QCompleter;
class QStandardItemModel;

namespace iec::editors {

class CodeHighlighter;
class InputAssistantDialog;
class LineNumberArea;

// The ST and IL body editor: lexer-based highlighting, line numbers, current line, auto-indent
// and block completion, bracket matching, folding, comment toggling, completion (Ctrl+Space),
// the input assistant (F2), go to definition (F12, Ctrl+click) and compiler diagnostics as wavy
// underlines with tooltips. One class for both languages; what differs is data.
//
// Typing uses the QTextDocument's own undo stack (DESIGN.md); textEdited tells the application,
// debounced, that the text changed so it can push it into the model.
class CodeEditor : public QPlainTextEdit
{
    Q_OBJECT

public:
    explicit CodeEditor(TextLanguage language = TextLanguage::ST, QWidget *parent = nullptr);
    ~CodeEditor() override;

    [[nodiscard]] TextLanguage language() const { return m_language; }
    void setLanguage(TextLanguage language);

    // Replaces the whole text (opening a body, or a change that came from the model): no
    // textEdited, the undo history starts afresh, diagnostics are cleared.
    void setBodyText(const QString &text);
    // The same for a change made elsewhere to an open body (a rename rewrote it): the cursor stays
    // on its line and column and the view does not scroll.
    void setBodyTextKeepingCursor(const QString &text);

    // Not owned; may be null (then only keywords and the standard library are offered).
    void setCompletionProvider(const CompletionProvider *provider) { m_provider = provider; }
    [[nodiscard]] const CompletionProvider *completionProvider() const { return m_provider; }

    // Diagnostics follow the text as it is edited until the next call.
    void setDiagnostics(const QList<TextDiagnostic> &diagnostics);
    [[nodiscard]] QList<TextDiagnostic> diagnostics() const;
    // The messages of the diagnostics that cover document position `position`, one per line.
    [[nodiscard]] QString diagnosticMessageAt(int position) const;

    // Folding; lines are 0-based block numbers.
    [[nodiscard]] QList<FoldRange> foldRanges() const { return m_foldRanges; }
    [[nodiscard]] bool isFolded(int firstLine) const;
    bool fold(int firstLine);
    bool unfold(int firstLine);
    void toggleFold(int firstLine);
    void unfoldAll();
    void updateFoldRangesNow();

    // The dotted name under `position` up to the end of the word there ("Tank.Level" on "Level").
    [[nodiscard]] QString identifierPathAt(int position) const;

    // Moves the cursor to a 1-based line and column, unfolding as needed.
    void goToLine(int line, int column = 1);

    [[nodiscard]] CodeHighlighter *highlighter() const { return m_highlighter; }
    [[nodiscard]] QCompleter *completer() const { return m_completer; }
    [[nodiscard]] InputAssistantDialog *inputAssistant() const;

    // Milliseconds of quiet before textEdited (default 300).
    void setEditDebounceInterval(int milliseconds) { m_editTimer.setInterval(milliseconds); }
    // Emits a pending textEdited now (before saving, switching documents, tests).
    void flushPendingEdit();

    // Online mode: the text is read-only, attempts to edit it are refused with editRefused and a
    // tooltip, and boxes with current values follow the ends of lines (index = 0-based line).
    void setOnline(bool online);
    [[nodiscard]] bool isOnline() const { return m_online; }
    void setOnlineChips(std::vector<QList<OnlineChip>> chipsByLine);
    [[nodiscard]] const std::vector<QList<OnlineChip>> &onlineChips() const { return m_onlineChips; }
    [[nodiscard]] static QString onlineEditRefusal();

    // Debugging: red dots in the margin on breakpoint lines, the line the program is halted at
    // in yellow (1-based lines; 0: none). A click in the margin's left column asks for a toggle.
    void setBreakpointLines(const QList<int> &lines, const QList<int> &disabledLines = {});
    [[nodiscard]] const QList<int> &breakpointLines() const { return m_breakpointLines; }
    [[nodiscard]] const QList<int> &disabledBreakpointLines() const { return m_disabledBreakpointLines; }
    void setHaltedLine(int line);
    [[nodiscard]] int haltedLine() const { return m_haltedLine; }

    [[nodiscard]] int lineNumberAreaWidth() const;
    void paintLineNumberArea(QPaintEvent *event);
    void lineNumberAreaClicked(const QPoint &position);

public Q_SLOTS:
    void toggleComment();
    void showCompletion();
    void openInputAssistant();
    // The input assistant on one category (RunPro's IL Insert menu: Operator, Operand, ...).
    void openInputAssistantOn(iec::editors::InputAssistantDialog::Category category);
    void requestDefinition();

Q_SIGNALS:
    // The user changed the text (debounced). Not emitted by setBodyText.
    void textEdited();
    // Go to definition on `identifier` (a dotted path) at a 1-based line and column; the
    // application resolves it and calls goToLine or opens another POU.
    void definitionRequested(const QString &identifier, int line, int column);
    // Online: the user tried to change the text; `message` says why that is not possible.
    void editRefused(const QString &message);
    // Context menu "Add to Watch" on a variable (a dotted path as written).
    void addToWatchRequested(const QString &path);
    // A click in the margin's breakpoint column, on a 1-based line.
    void breakpointToggleRequested(int line);

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    bool viewportEvent(QEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    // A POU dragged from the library pane drops as a call in this editor's language.
    bool canInsertFromMimeData(const QMimeData *source) const override;
    void insertFromMimeData(const QMimeData *source) override;

private:
    struct PlacedDiagnostic {
        TextDiagnostic diagnostic;
        QTextCursor range;
    };

    void updateLineNumberAreaWidth();
    void updateLineNumberArea(const QRect &rect, int dy);
    void updateExtraSelections();
    void onContentsChange(int position, int removed, int added);
    void applyFoldVisibility();
    void relayout();

    void handleEnter();
    void handleTab(bool backward);
    void reindentClosingKeyword();
    void updateCompletionPrefix();
    void insertCompletion(const QString &text);
    [[nodiscard]] int bracketMatch(int position) const;

    TextLanguage m_language;
    CodeHighlighter *m_highlighter = nullptr;
    LineNumberArea *m_lineNumberArea = nullptr;
    const CompletionProvider *m_provider = nullptr;
    QCompleter *m_completer = nullptr;
    QStandardItemModel *m_completionModel = nullptr;
    QHash<int, QIcon> m_kindIcons;
    int m_completionStart = -1;
    QPointer<InputAssistantDialog> m_assistant;

    QList<PlacedDiagnostic> m_diagnostics;
    QList<FoldRange> m_foldRanges;
    bool m_hasHiddenBlocks = false;
    int m_lastBlockCount = 1;

    QTimer m_editTimer;
    QTimer m_foldTimer;
    bool m_settingText = false;

    [[nodiscard]] bool refuseEditWhileOnline(const QKeyEvent *event);
    void paintOnlineChips(const QPaintEvent *event);
    bool m_online = false;
    std::vector<QList<OnlineChip>> m_onlineChips;
    QList<int> m_breakpointLines;
    QList<int> m_disabledBreakpointLines; // drawn hollow
    int m_haltedLine = 0;
};

} // namespace iec::editors
