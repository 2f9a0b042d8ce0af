#pragma once

#include <QLineEdit>

class QCompleter;
class QStringListModel;

namespace iec::editors {

class CompletionProvider;

// The line a graphical editor opens over an element to edit its name, variable or condition in
// place (CODESYS style): the text preselected (a new element's "???" is replaced by typing),
// a completion popup from the declared names as one types, F2 for the input assistant. Enter and
// leaving the field commit; Escape cancels. Either way it closes itself.
class InPlaceEditor : public QLineEdit
{
    Q_OBJECT

public:
    enum class Completion { None, Names, BlockTypes };

    InPlaceEditor(const QString &text, Completion completion, const CompletionProvider *provider, QWidget *parent);

    // The completions offered for the word at the cursor now (for tests and the popup).
    [[nodiscard]] QStringList completions() const;
    [[nodiscard]] QCompleter *completer() const { return m_completer; }
    void cancel() { finish(false); }

Q_SIGNALS:
    void committed(const QString &text);
    void cancelled();

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;

private:
    void finish(bool commit);
    void updatePopup();
    void insertCompletion(const QString &completion);
    void openAssistant();

    Completion m_completion;
    const CompletionProvider *m_provider;
    QCompleter *m_completer = nullptr;
    QStringListModel *m_model = nullptr;
    bool m_done = false;
    bool m_inAssistant = false;
};

} // namespace iec::editors
