#include "model/undo/elementcommands.h"

#include <QCoreApplication>

namespace iec::model {

namespace {

QString moveText(std::size_t count)
{
    return QCoreApplication::translate("iec::model::MoveElementsCommand", "Move %n element(s)", nullptr, int(count));
}

} // namespace

InsertElementCommand::InsertElementCommand(
    ProjectModel &model, BodyRef ref, Element element, int index, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_element(std::move(element))
    , m_index(index)
{
    setText(QCoreApplication::translate("iec::model::InsertElementCommand", "Insert %1")
                .arg(QString::fromLatin1(elementTagName(m_element))));
}

void InsertElementCommand::redo()
{
    header(m_element).localId = m_model.insertElement(m_ref, m_element, m_index);
}

void InsertElementCommand::undo()
{
    m_model.removeElement(m_ref, localId());
}

RemoveElementCommand::RemoveElementCommand(ProjectModel &model, BodyRef ref, quint64 localId, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_index(model.elementIndex(m_ref, localId))
{
    if (const Element *element = model.element(m_ref, localId))
        m_element = *element;
    if (const Body *body = model.body(m_ref); body && body->isGraphical()) {
        for (const Element &candidate : *body->elements()) {
            for (const ConnectionPointIn *point : inputPoints(candidate)) {
                if (std::ranges::any_of(
                        point->connections, [&](const Connection &c) { return c.refLocalId == localId; })) {
                    m_fedElements.push_back(candidate);
                    break;
                }
            }
        }
    }
    setText(QCoreApplication::translate("iec::model::RemoveElementCommand", "Delete %1")
                .arg(QString::fromLatin1(elementTagName(m_element))));
}

void RemoveElementCommand::redo()
{
    m_model.removeElement(m_ref, header(m_element).localId);
}

void RemoveElementCommand::undo()
{
    m_model.insertElement(m_ref, m_element, m_index);
    for (const Element &fed : m_fedElements)
        m_model.changeElement(m_ref, fed);
}

MoveElementsCommand::MoveElementsCommand(
    ProjectModel &model, BodyRef ref, std::vector<Move> moves, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
{
    for (const Move &move : moves) {
        const Element *element = model.element(m_ref, move.localId);
        m_localIds.push_back(move.localId);
        m_from.push_back(element ? header(*element).position : move.to);
        m_to.push_back(move.to);
    }
    setText(moveText(moves.size()));
}

void MoveElementsCommand::redo()
{
    for (std::size_t i = 0; i < m_localIds.size(); ++i)
        m_model.moveElement(m_ref, m_localIds[i], m_to[i]);
}

void MoveElementsCommand::undo()
{
    for (std::size_t i = 0; i < m_localIds.size(); ++i)
        m_model.moveElement(m_ref, m_localIds[i], m_from[i]);
}

bool MoveElementsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *move = static_cast<const MoveElementsCommand *>(other);
    if (!(move->m_ref == m_ref) || move->m_localIds != m_localIds)
        return false;
    m_to = move->m_to;
    return true;
}

ChangeElementCommand::ChangeElementCommand(ProjectModel &model, BodyRef ref, Element element, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_before(element)
    , m_after(std::move(element))
{
    if (const Element *before = model.element(m_ref, header(m_after).localId))
        m_before = *before;
    setText(QCoreApplication::translate("iec::model::ChangeElementCommand", "Change %1")
                .arg(QString::fromLatin1(elementTagName(m_after))));
}

void ChangeElementCommand::redo()
{
    m_model.changeElement(m_ref, m_after);
}

void ChangeElementCommand::undo()
{
    m_model.changeElement(m_ref, m_before);
}

bool ChangeElementCommand::mergeWith(const QUndoCommand *other)
{
    const auto *change = static_cast<const ChangeElementCommand *>(other);
    if (!(change->m_ref == m_ref) || header(change->m_after).localId != header(m_after).localId)
        return false;
    m_after = change->m_after;
    return true;
}

ConnectCommand::ConnectCommand(
    ProjectModel &model, BodyRef ref, quint64 target, int pin, Connection connection, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_target(target)
    , m_pin(pin)
    , m_connection(std::move(connection))
{
    setText(QCoreApplication::translate("iec::model::ConnectCommand", "Connect"));
}

void ConnectCommand::redo()
{
    m_model.connect(m_ref, m_target, m_pin, m_connection);
}

void ConnectCommand::undo()
{
    m_model.disconnect(m_ref, m_target, m_pin, m_connection.refLocalId, m_connection.formalParameter);
}

DisconnectCommand::DisconnectCommand(ProjectModel &model, BodyRef ref, quint64 target, int pin, quint64 source,
    std::optional<QString> formalParameter, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_target(target)
    , m_pin(pin)
    , m_source(source)
    , m_formalParameter(std::move(formalParameter))
{
    if (const Element *element = model.element(m_ref, target))
        m_before = *element;
    setText(QCoreApplication::translate("iec::model::DisconnectCommand", "Disconnect"));
}

void DisconnectCommand::redo()
{
    m_model.disconnect(m_ref, m_target, m_pin, m_source, m_formalParameter);
}

void DisconnectCommand::undo()
{
    m_model.changeElement(m_ref, m_before); // the wire goes back to its place among the others
}

SetBodyTextCommand::SetBodyTextCommand(ProjectModel &model, BodyRef ref, QString text, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_after(std::move(text))
{
    if (const Body *body = model.body(m_ref))
        m_before = body->text();
    setText(QCoreApplication::translate("iec::model::SetBodyTextCommand", "Edit text"));
}

void SetBodyTextCommand::redo()
{
    m_model.setBodyText(m_ref, m_after);
}

void SetBodyTextCommand::undo()
{
    m_model.setBodyText(m_ref, m_before);
}

bool SetBodyTextCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const SetBodyTextCommand *>(other);
    if (!(edit->m_ref == m_ref))
        return false;
    m_after = edit->m_after;
    return true;
}

SetBodyAddDataCommand::SetBodyAddDataCommand(ProjectModel &model, BodyRef ref, AddData addData, const QString &text,
    QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_after(std::move(addData))
{
    if (const Body *body = model.body(m_ref))
        m_before = body->addData;
    setText(text);
    setObsolete(m_before == m_after);
}

void SetBodyAddDataCommand::redo()
{
    m_model.setBodyAddData(m_ref, m_after);
}

void SetBodyAddDataCommand::undo()
{
    m_model.setBodyAddData(m_ref, m_before);
}

} // namespace iec::model
