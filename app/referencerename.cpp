#include "app/referencerename.h"

#include "interpreter/compiler/lexer.h"
#include "model/undo/elementcommands.h"
#include "model/undo/poucommands.h"
#include "model/undo/variablecommands.h"

namespace iec::app {

using model::BodyRef;

QString renameIdentifier(const QString &text, const QString &oldName, const QString &newName)
{
    QString result;
    int copiedUpTo = 0;
    bool afterDot = false;
    for (const interp::Token &token : interp::tokenize(text)) {
        const QStringView word = QStringView(text).mid(token.offset, token.length);
        const bool isReference = token.kind == interp::TokenKind::Identifier && !afterDot
            && word.compare(oldName, Qt::CaseInsensitive) == 0;
        afterDot = token.kind == interp::TokenKind::Operator && word == u".";
        if (!isReference)
            continue;
        result += QStringView(text).mid(copiedUpTo, token.offset - copiedUpTo);
        result += newName;
        copiedUpTo = token.offset + token.length;
    }
    if (copiedUpTo == 0)
        return text;
    result += QStringView(text).mid(copiedUpTo);
    return result;
}

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

// LD and FBD call function blocks and functions through blocks that name them in typeName.
void renameInBlocks(model::ProjectModel &model, const BodyRef &ref, const std::vector<model::Element> &elements,
    const QString &oldName, const QString &newName, QUndoCommand *parent)
{
    for (const model::Element &element : elements) {
        const auto *block = std::get_if<model::Block>(&element);
        if (!block || !sameName(block->typeName, oldName))
            continue;
        model::Block renamed = *block;
        renamed.typeName = newName;
        new model::ChangeElementCommand(model, ref, model::Element {std::move(renamed)}, parent);
    }
}

void renameInBody(model::ProjectModel &model, const BodyRef &ref, const model::Body &body, const QString &oldName,
    const QString &newName, QUndoCommand *parent)
{
    if (const std::vector<model::Element> *elements = body.elements()) {
        renameInBlocks(model, ref, *elements, oldName, newName, parent);
        return;
    }
    const QString text = body.text();
    const QString renamed = renameIdentifier(text, oldName, newName);
    if (renamed != text)
        new model::SetBodyTextCommand(model, ref, renamed, parent);
}

void renameInBodies(model::ProjectModel &model, const model::Pou &pou, const QString &oldName, const QString &newName,
    QUndoCommand *parent)
{
    if (const model::Body *body = pou.body())
        renameInBody(model, {pou.id, BodyRef::Part::Pou, {}}, *body, oldName, newName, parent);
    for (const model::PouPart &action : pou.actions)
        renameInBody(model, {pou.id, BodyRef::Part::Action, action.name}, action.body, oldName, newName, parent);
    for (const model::PouPart &transition : pou.transitions) {
        renameInBody(
            model, {pou.id, BodyRef::Part::Transition, transition.name}, transition.body, oldName, newName, parent);
    }
}

void renameInDeclarations(model::ProjectModel &model, const model::Pou &pou, const QString &oldName,
    const QString &newName, QUndoCommand *parent)
{
    if (!pou.pouInterface)
        return;
    for (const model::VarList &list : pou.pouInterface->varLists) {
        for (const model::Variable &variable : list.variables) {
            const auto *derived = std::get_if<model::DerivedType>(&variable.type.kind);
            if (!derived || !sameName(derived->name, oldName))
                continue;
            model::Variable changed = variable;
            std::get<model::DerivedType>(changed.type.kind).name = newName;
            new model::ChangeVariableCommand(model, pou.id, variable.name, changed, parent);
        }
    }
}

} // namespace

QUndoCommand *createRenamePouCommand(model::ProjectModel &model, model::PouId pou, const QString &newName)
{
    const model::Pou *renamed = model.project().findPou(pou);
    const QString oldName = renamed ? renamed->name : QString();
    auto *command = new QUndoCommand;
    // The step reads as the rename itself; the reference updates are its details.
    command->setText((new model::RenamePouCommand(model, pou, newName, command))->text());
    if (oldName.isEmpty())
        return command;
    for (const model::Pou &each : model.project().types.pous) {
        renameInBodies(model, each, oldName, newName, command);
        renameInDeclarations(model, each, oldName, newName, command);
    }
    return command;
}

} // namespace iec::app
