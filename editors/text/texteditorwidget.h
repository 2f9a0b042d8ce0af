#pragma once

#include "editors/common/onlineview.h"
#include "editors/text/textlanguage.h"

#include <QElapsedTimer>
#include <QWidget>

#include <functional>
#include <vector>

class QLabel;

namespace iec::editors {

class CodeEditor;
class FindReplaceBar;

// A CodeEditor with its find/replace bar below it: Ctrl+F finds, Ctrl+H (QKeySequence::Replace) replaces, F3 / Shift+F3
// find the next / previous match, Escape closes the bar. What the application puts in a tab.
//
// Online (OnlineView) it shows the current value of every variable a line mentions after the
// end of that line, a banner with the cycle, and refuses edits with a clear message.
class TextEditorWidget : public QWidget, public OnlineView
{
    Q_OBJECT

public:
    explicit TextEditorWidget(TextLanguage language = TextLanguage::ST, QWidget *parent = nullptr);

    [[nodiscard]] CodeEditor *editor() const { return m_editor; }
    [[nodiscard]] FindReplaceBar *findBar() const { return m_findBar; }
    // What the window's Insert menu shows while this editor is current: for IL, RunPro's
    // Operator (O), Operand (P), Function (F) and Function Block (B), each opening the input
    // assistant on that category; nothing for ST.
    [[nodiscard]] QList<QAction *> insertActions() const { return m_insertActions; }

    // The instance whose variables the body uses ("Main"), asked for when going online, so a
    // renamed POU is found under its new name. Unset or empty: nothing is shown online.
    void setOnlineInstanceProvider(std::function<QString()> provider) { m_instanceProvider = std::move(provider); }
    QString onlineInstance() const override;
    QStringList onlineNames() const override;
    void setOnlineSnapshot(const interp::RuntimeSnapshot *snapshot) override;
    std::optional<Place> breakpointPlace() const override;
    void setBreakpointMarks(const std::vector<Place> &breakpoints, std::optional<Place> halted) override;
    [[nodiscard]] QLabel *onlineBanner() const { return m_onlineBanner; }

Q_SIGNALS:
    // "Add to Watch" on a variable, with the full name the runtime knows ("Main.Count").
    void addToWatchRequested(const QString &name);

protected:
    void changeEvent(QEvent *event) override;

private:
    void createInsertActions();
    void retranslate();
    const std::vector<QStringList> &linePaths() const;
    void showBanner(const QString &text, bool warning);

    std::function<QString()> m_instanceProvider;
    QLabel *m_onlineBanner = nullptr;
    bool m_online = false;
    QElapsedTimer m_refusalShown; // the refusal stays a few seconds before the cycle banner returns
    mutable std::vector<QStringList> m_linePaths;
    mutable int m_linePathsRevision = -1;

    CodeEditor *m_editor;
    FindReplaceBar *m_findBar;
    QList<QAction *> m_insertActions;
};

} // namespace iec::editors
