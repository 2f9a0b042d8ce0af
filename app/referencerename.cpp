#include "app/referencerename.h"

#include "interpreter/compiler/lexer.h"
#include "model/undo/elementcommands.h"
#include "model/undo/instancecommands.h"
#include "model/undo/partcommands.h"
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

// The SFC elements of a body that name the action (action blocks) or the transition (conditions).
void renamePartReferences(model::ProjectModel &model, const BodyRef &ref, const std::vector<model::Element> &elements,
    BodyRef::Part part, const QString &oldName, const QString &newName, QUndoCommand *parent)
{
    const auto renamedReference = [&](std::optional<model::Reference> &reference) {
        if (!reference || !sameName(reference->name, oldName))
            return false;
        reference->name = newName;
        return true;
    };
    for (const model::Element &element : elements) {
        model::Element changed = element;
        bool touched = false;
        if (auto *block = std::get_if<model::ActionBlock>(&changed); block && part == BodyRef::Part::Action) {
            for (model::ActionBlockAction &action : block->actions)
                touched = renamedReference(action.reference) || touched;
        } else if (auto *transition = std::get_if<model::Transition>(&changed);
                   transition && part == BodyRef::Part::Transition && transition->condition) {
            if (auto *reference = std::get_if<model::Reference>(&transition->condition->kind);
                reference && sameName(reference->name, oldName)) {
                reference->name = newName;
                touched = true;
            }
        }
        if (touched)
            new model::ChangeElementCommand(model, ref, changed, parent);
    }
}

} // namespace

QUndoCommand *createRenamePouPartCommand(model::ProjectModel &model, model::PouId pouId, BodyRef::Part part,
    const QString &oldName, const QString &newName)
{
    auto *command = new QUndoCommand;
    command->setText((new model::RenamePouPartCommand(model, pouId, part, oldName, newName, command))->text());
    const model::Pou *pou = model.project().findPou(pouId);
    if (!pou)
        return command;
    const auto visit = [&](const BodyRef &ref, const model::Body &body) {
        if (const std::vector<model::Element> *elements = body.elements())
            renamePartReferences(model, ref, *elements, part, oldName, newName, command);
        else if (const QString renamed = renameIdentifier(body.text(), oldName, newName); renamed != body.text())
            new model::SetBodyTextCommand(model, ref, renamed, command);
    };
    // The part's own body is left alone: once renamed it is found under another name, so a
    // command made now could not address it (and an action rarely names itself).
    if (const model::Body *body = pou->body())
        visit({pou->id, BodyRef::Part::Pou, {}}, *body);
    for (const model::PouPart &action : pou->actions) {
        if (!(part == BodyRef::Part::Action && sameName(action.name, oldName)))
            visit({pou->id, BodyRef::Part::Action, action.name}, action.body);
    }
    for (const model::PouPart &transition : pou->transitions) {
        if (!(part == BodyRef::Part::Transition && sameName(transition.name, oldName)))
            visit({pou->id, BodyRef::Part::Transition, transition.name}, transition.body);
    }
    return command;
}

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
    // The tasks that run a renamed program.
    if (auto instances = model::instancesWithProgramRenamed(model.project().instances, oldName, newName))
        new model::SetInstancesCommand(model, std::move(*instances), command);
    return command;
}

} // namespace iec::app
