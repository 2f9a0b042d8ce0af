#pragma once

#include "app/adddatatexteditor.h"
#include "model/ids.h"

#include <QList>
#include <QString>

#include <optional>

namespace iec::app {

struct Message;

// A method or property of a function block, which CODESYS keeps in the POU's addData, edited as
// one text (interp::frontend::printCodesysMember): METHOD ... END_METHOD, PROPERTY ... END_PROPERTY.
class MemberEditor : public AddDataTextEditor
{
    Q_OBJECT

public:
    MemberEditor(model::ProjectModel &model, model::PouId pou, const QString &name, QWidget *parent = nullptr);

    [[nodiscard]] model::PouId pou() const { return m_pou; }
    [[nodiscard]] QString title() const override; // Base.Add
    // The compiler's messages about this member ("Counter.Add", and a property's
    // "Counter.Count.GET" and "Counter.Count.SET"; lines counted in that body) moved to the lines
    // of its text; nullopt when the text is not what the model holds (typed since: messages of
    // older text are not shown on newer text).
    [[nodiscard]] std::optional<QList<Message>> messagesAtLines(const QList<Message> &messages) const;
    // One such message moved to its line and column in the text (the header when its body is
    // not known); messagesAtLines and the Messages pane's "open the place" both use it.
    [[nodiscard]] Message atTextLine(Message message) const;

protected:
    [[nodiscard]] Reading read(const QString &text) const override;
    [[nodiscard]] const model::AddData *kept() const override;
    [[nodiscard]] QString print(bool *editable) const override;
    void store(const model::AddData &addData) override;

private:
    // Where the body a message names starts in the text; 0 when the text has no such body.
    [[nodiscard]] int bodyLineOf(const QString &codeName) const;
    [[nodiscard]] bool isMine(const QString &codeName) const;

    model::PouId m_pou;
};

} // namespace iec::app
