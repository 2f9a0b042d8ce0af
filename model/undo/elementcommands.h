#pragma once

#include "model/undo/modelcommand.h"

#include <vector>

namespace iec::model {

// Inserts one graphical element. The first redo assigns its localId; later redos reuse it.
class InsertElementCommand : public ModelCommand
{
public:
    InsertElementCommand(
        ProjectModel &model, BodyRef ref, Element element, int index = -1, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

    [[nodiscard]] quint64 localId() const { return header(m_element).localId; }

private:
    BodyRef m_ref;
    Element m_element;
    int m_index;
};

// Removes one element; the model also drops the wires that start at it, so undo restores the
// element and the elements it fed.
class RemoveElementCommand : public ModelCommand
{
public:
    RemoveElementCommand(ProjectModel &model, BodyRef ref, quint64 localId, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    BodyRef m_ref;
    Element m_element;
    int m_index = -1;
    std::vector<Element> m_fedElements; // before the removal
};

// Moves elements (one drag). A drag that continues with the same elements merges.
class MoveElementsCommand : public ModelCommand
{
public:
    struct Move {
        quint64 localId = 0;
        Position to;
    };

    MoveElementsCommand(ProjectModel &model, BodyRef ref, std::vector<Move> moves, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return MoveElementsMerge; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    BodyRef m_ref;
    std::vector<quint64> m_localIds;
    std::vector<Position> m_from;
    std::vector<Position> m_to;
};

// Sets the properties of one element (the value with the same localId replaces it). Successive
// edits of the same element merge.
class ChangeElementCommand : public ModelCommand
{
public:
    ChangeElementCommand(ProjectModel &model, BodyRef ref, Element element, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return ChangeElementMerge; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    BodyRef m_ref;
    Element m_before;
    Element m_after;
};

// Wires `connection.refLocalId` to input pin `pin` of `target`.
class ConnectCommand : public ModelCommand
{
public:
    ConnectCommand(ProjectModel &model, BodyRef ref, quint64 target, int pin, Connection connection,
        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    BodyRef m_ref;
    quint64 m_target;
    int m_pin;
    Connection m_connection;
};

// Removes the wire from `source` on input pin `pin` of `target`.
class DisconnectCommand : public ModelCommand
{
public:
    DisconnectCommand(ProjectModel &model, BodyRef ref, quint64 target, int pin, quint64 source,
        std::optional<QString> formalParameter = {}, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    BodyRef m_ref;
    quint64 m_target;
    int m_pin;
    quint64 m_source;
    std::optional<QString> m_formalParameter;
    Element m_before;
};

// Sets the text of an ST or IL body. Consecutive edits of the same body merge.
class SetBodyTextCommand : public ModelCommand
{
public:
    SetBodyTextCommand(ProjectModel &model, BodyRef ref, QString text, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return SetBodyTextMerge; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    BodyRef m_ref;
    QString m_before;
    QString m_after;
};

// Replaces a body's addData: an edit of a diagram another tool keeps there (a CODESYS CFC). One
// command per gesture; no merging.
class SetBodyAddDataCommand : public ModelCommand
{
public:
    SetBodyAddDataCommand(ProjectModel &model, BodyRef ref, AddData addData, const QString &text,
        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    BodyRef m_ref;
    AddData m_before;
    AddData m_after;
};

} // namespace iec::model
