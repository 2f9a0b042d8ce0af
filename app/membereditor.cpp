#include "app/membereditor.h"

#include "app/messagespane.h"
#include "editors/text/codeeditor.h"
#include "interpreter/compiler/ast.h"
#include "interpreter/frontend/codesysmembers.h"
#include "model/plcopen/codesysoop.h"
#include "model/projectmodel.h"

#include <algorithm>
#include <initializer_list>

namespace iec::app {

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

} // namespace

MemberEditor::MemberEditor(model::ProjectModel &model, model::PouId pou, const QString &name, QWidget *parent)
    : AddDataTextEditor(model, name, parent)
    , m_pou(pou)
{
    setObjectName(QStringLiteral("memberEditor"));
    load();
    connect(&model, &model::ProjectModel::pouAddDataChanged, this, [this](model::PouId id) {
        if (id == m_pou)
            followModel();
    });
    connect(&model, &model::ProjectModel::pouRenamed, this, &MemberEditor::titleChanged);
    connect(&model, &model::ProjectModel::pouRemoved, this, [this](model::PouId id) {
        if (id == m_pou)
            Q_EMIT removed();
    });
}

QString MemberEditor::title() const
{
    const model::Pou *pou = m_model.project().findPou(m_pou);
    return pou ? pou->name + QLatin1Char('.') + name() : name();
}

const model::AddData *MemberEditor::kept() const
{
    const model::Pou *pou = m_model.project().findPou(m_pou);
    return pou ? &pou->addData : nullptr;
}

QString MemberEditor::print(bool *editable) const
{
    const model::Pou *pou = m_model.project().findPou(m_pou);
    return pou ? interp::frontend::printCodesysMember(*pou, name(), editable) : QString();
}

void MemberEditor::store(const model::AddData &addData)
{
    m_model.setPouAddData(m_pou, addData);
}

AddDataTextEditor::Reading MemberEditor::read(const QString &text) const
{
    const model::Pou *pou = m_model.project().findPou(m_pou);
    if (!pou)
        return {};
    const interp::frontend::CodesysMemberText read = interp::frontend::readCodesysMemberText(text, pou->name);
    Reading reading;
    reading.marks = marksOf(read.diagnostics);
    if (!read.definition)
        return reading;
    const QString newName = read.definition->name;
    const bool taken = !sameName(newName, name())
        && std::ranges::any_of(interp::frontend::codesysMembers(*pou),
            [&](const interp::frontend::CodesysMemberSummary &m) { return sameName(m.name, newName); });
    if (taken) {
        editors::TextDiagnostic mark;
        mark.message = tr("%1 already has a method or property called %2.").arg(pou->name, newName);
        reading.marks << mark;
        return reading;
    }
    reading.addData = model::plcopen::addDataWithMember(pou->addData, name(), *read.definition);
    reading.name = newName;
    return reading;
}

// The compiler names a method's code "Counter.Add" and a property's accessors "Counter.Count.GET"
// and "Counter.Count.SET" (ast::methodCodeName): which of this member's bodies `codeName` is.
int MemberEditor::bodyLineOf(const QString &codeName) const
{
    using Role = interp::ast::Method::Role;
    const QString owner = title().section(QLatin1Char('.'), 0, 0);
    const interp::frontend::MemberBodyLines lines = interp::frontend::memberBodyLines(editor()->toPlainText());
    if (sameName(codeName, interp::ast::methodCodeName(owner, name(), Role::Getter)))
        return lines.getter;
    if (sameName(codeName, interp::ast::methodCodeName(owner, name(), Role::Setter)))
        return lines.setter;
    return lines.body;
}

bool MemberEditor::isMine(const QString &codeName) const
{
    using Role = interp::ast::Method::Role;
    const QString owner = title().section(QLatin1Char('.'), 0, 0);
    return std::ranges::any_of(std::initializer_list<Role> {Role::Method, Role::Getter, Role::Setter},
        [&](Role role) { return sameName(codeName, interp::ast::methodCodeName(owner, name(), role)); });
}

Message MemberEditor::atTextLine(Message message) const
{
    const int first = bodyLineOf(message.pouName);
    const bool placed = first > 0 && message.line > 0;
    message.line = placed ? first + message.line - 1 : 1;
    message.column = placed ? std::max(message.column, 1) : 1;
    return message;
}

std::optional<QList<Message>> MemberEditor::messagesAtLines(const QList<Message> &messages) const
{
    if (!showsModelText())
        return std::nullopt;
    QList<Message> own;
    for (const Message &message : messages) {
        if (!isMine(message.pouName))
            continue;
        Message placed = atTextLine(message);
        placed.pouName = title(); // its lines are now the tab's, whichever body it was in
        own << placed;
    }
    return own;
}

} // namespace iec::app
