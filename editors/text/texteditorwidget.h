#pragma once

#include "editors/text/textlanguage.h"

#include <QWidget>

namespace iec::editors {

class CodeEditor;
class FindReplaceBar;

// A CodeEditor with its find/replace bar below it: Ctrl+F finds, Ctrl+H (QKeySequence::Replace) replaces, F3 / Shift+F3
// find the next / previous match, Escape closes the bar. What the application puts in a tab.
class TextEditorWidget : public QWidget
{
    Q_OBJECT

public:
    explicit TextEditorWidget(TextLanguage language = TextLanguage::ST, QWidget *parent = nullptr);

    [[nodiscard]] CodeEditor *editor() const { return m_editor; }
    [[nodiscard]] FindReplaceBar *findBar() const { return m_findBar; }

private:
    CodeEditor *m_editor;
    FindReplaceBar *m_findBar;
};

} // namespace iec::editors
