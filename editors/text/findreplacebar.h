#pragma once

#include <QTextDocument>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QToolButton;

namespace iec::editors {

// Replaces every occurrence of `text` in `document` as ONE undo step; returns the count.
int replaceAllInDocument(
    QTextDocument *document, const QString &text, const QString &replacement, QTextDocument::FindFlags flags);

// The find/replace bar under a text editor: find next / previous (wrapping), match case, whole
// words, replace, replace all.
class FindReplaceBar : public QWidget
{
    Q_OBJECT

public:
    explicit FindReplaceBar(QPlainTextEdit *editor, QWidget *parent = nullptr);

    // Shows the bar, with the replace row when `withReplace`; takes the editor's selection as the
    // search text when it is on one line.
    void activate(bool withReplace);

    void setFindText(const QString &text);
    [[nodiscard]] QString findText() const;
    void setReplaceText(const QString &text);
    void setCaseSensitive(bool on);
    void setWholeWords(bool on);
    [[nodiscard]] QString statusText() const;
    [[nodiscard]] bool isReplaceShown() const;

public Q_SLOTS:
    bool findNext();
    bool findPrevious();
    bool replace(); // replaces the current match, then finds the next
    int replaceAll();

Q_SIGNALS:
    void closed();

protected:
    void keyPressEvent(QKeyEvent *event) override;

private:
    [[nodiscard]] QTextDocument::FindFlags flags() const;
    bool find(bool backward);
    [[nodiscard]] bool selectionMatches() const;
    void setStatus(const QString &text, bool problem);

    QPlainTextEdit *m_editor;
    QLineEdit *m_find = nullptr;
    QLineEdit *m_replace = nullptr;
    QCheckBox *m_case = nullptr;
    QCheckBox *m_words = nullptr;
    QWidget *m_replaceRow = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace iec::editors
