#pragma once

#include "model/ids.h"
#include "model/opaque.h"

#include <QList>
#include <QString>
#include <QWidget>

#include <optional>

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {
class CodeEditor;
class TextEditorWidget;
} // namespace iec::editors

namespace iec::app {

struct Message;

// A method or property of a function block, which CODESYS keeps in the POU's addData, edited as
// one text in the form of IEC 61131-3 edition 3 (METHOD ... END_METHOD, PROPERTY ... END_PROPERTY;
// interp::frontend::printCodesysMember). What is typed goes into the model after a pause, as a
// body's text does: the text document's own undo is the authority while typing. Text that does
// not read as one member is marked where it goes wrong and not taken: the model keeps the last
// text that was. A new name in the header renames the member.
class MemberEditor : public QWidget
{
    Q_OBJECT

public:
    MemberEditor(model::ProjectModel &model, model::PouId pou, const QString &name, QWidget *parent = nullptr);

    [[nodiscard]] model::PouId pou() const { return m_pou; }
    [[nodiscard]] QString name() const { return m_name; }
    [[nodiscard]] QString title() const; // Base.Add
    [[nodiscard]] editors::CodeEditor *editor() const;
    // The compiler's messages about this member ("Counter.Add", and a property's
    // "Counter.Count.GET" and "Counter.Count.SET"; lines counted in that body) moved to the lines
    // of its text; nullopt when the text is not what the model holds (typed since: messages of
    // older text are not shown on newer text).
    [[nodiscard]] std::optional<QList<Message>> messagesAtLines(const QList<Message> &messages) const;
    // One such message moved to its line and column in the text (the header when its body is
    // not known); messagesAtLines and the Messages pane's "open the place" both use it.
    [[nodiscard]] Message atTextLine(Message message) const;

Q_SIGNALS:
    void titleChanged();
    // The member, or its POU, is gone (an undo, a removal): the tab closes.
    void removed();

private:
    // Where the body a message names starts in the text; 0 when the text has no such body.
    [[nodiscard]] int bodyLineOf(const QString &codeName) const;
    [[nodiscard]] bool isMine(const QString &codeName) const;
    void apply();
    void followModel(model::PouId id);

    model::ProjectModel &m_model;
    model::PouId m_pou;
    QString m_name;
    model::AddData m_written; // the POU's addData as this editor last wrote it
    QString m_shown;          // the text the model holds (as loaded, or last taken)
    editors::TextEditorWidget *m_text = nullptr;
};

} // namespace iec::app
