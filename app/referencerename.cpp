#include "app/referencerename.h"

#include "app/bodyrewrite.h"
#include "app/renametypescope.h"
#include "app/textrename.h"
#include "editors/globals/globallists.h"
#include "interpreter/compiler/lexer.h"
#include "model/projectmodel.h"
#include "model/sfcoptions.h"
#include "model/undo/datatypecommands.h"
#include "model/undo/elementcommands.h"
#include "model/undo/instancecommands.h"
#include "model/undo/partcommands.h"
#include "model/undo/poucommands.h"
#include "model/undo/variablecommands.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <algorithm>
#include <functional>

namespace iec::app {

using model::BodyRef;

namespace {

QString tr(const char *source)
{
    return QCoreApplication::translate("iec::app::ReferenceRename", source);
}

bool sameName(QStringView a, QStringView b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

// ---- what each kind of rename changes

bool renameReference(std::optional<model::Reference> &reference, const Renames &renames)
{
    if (!reference)
        return false;
    const QString *newName = newNameOf(renames, reference->name);
    if (newName)
        reference->name = *newName;
    return newName != nullptr;
}

// Uses of variables (locals of the POU, or globals it sees) in its bodies.
BodyRewrite variableRewrite(const model::Pou &pou, const Renames &renames)
{
    BodyRewrite rewrite;
    rewrite.text = [renames](const QString &text, TextDialect dialect) {
        return renameIdentifiers(text, renames, dialect);
    };
    // An action block may name a BOOL variable instead of an action (CODESYS); an action of the
    // same name would win, so those references stay.
    Renames notActions;
    for (const model::VariableRename &rename : renames) {
        if (std::ranges::none_of(pou.actions, [&](const model::PouPart &a) { return sameName(a.name, rename.oldName); }))
            notActions.push_back(rename);
    }
    rewrite.element = [renames, notActions](model::Element &element, const std::vector<model::Element> &) {
        if (auto *block = std::get_if<model::Block>(&element); block && block->instanceName) {
            if (const QString *newName = newNameOf(renames, *block->instanceName)) {
                block->instanceName = *newName;
                return true;
            }
        }
        bool changed = false;
        if (auto *actions = std::get_if<model::ActionBlock>(&element)) {
            for (model::ActionBlockAction &action : actions->actions)
                changed |= renameReference(action.reference, notActions);
        }
        return changed;
    };
    return rewrite;
}

bool renamePins(std::vector<model::BlockVariable> &pins, const Renames &renames)
{
    bool changed = false;
    for (model::BlockVariable &pin : pins) {
        if (const QString *newName = newNameOf(renames, pin.formalParameter)) {
            pin.formalParameter = *newName;
            changed = true;
        }
    }
    return changed;
}

// Members of `typeName` (a struct, or the inputs and outputs of a function block or function)
// where the declarations of `pou` say an expression has that type, and the pins of its blocks.
BodyRewrite memberRewrite(const model::Project &project, const model::Pou &pou, const QString &typeName,
    const Renames &renames)
{
    BodyRewrite rewrite;
    rewrite.text = [&project, &pou, typeName, renames](const QString &text, TextDialect) {
        return renameMembers(text, TypeScope(project, pou), typeName, renames);
    };
    rewrite.element = [typeName, renames](model::Element &element, const std::vector<model::Element> &siblings) {
        bool changed = false;
        if (auto *block = std::get_if<model::Block>(&element); block && sameName(block->typeName, typeName)) {
            changed |= renamePins(block->inputVariables, renames);
            changed |= renamePins(block->inOutVariables, renames);
            changed |= renamePins(block->outputVariables, renames);
        }
        // A wire from an output pin of such a block names the pin.
        for (model::ConnectionPointIn *point : model::inputPoints(element)) {
            for (model::Connection &connection : point->connections) {
                const auto source = std::ranges::find_if(siblings,
                    [&](const model::Element &e) { return model::header(e).localId == connection.refLocalId; });
                const auto *block = source == siblings.end() ? nullptr : std::get_if<model::Block>(&*source);
                if (!block || !sameName(block->typeName, typeName) || !connection.formalParameter)
                    continue;
                if (const QString *newName = newNameOf(renames, *connection.formalParameter)) {
                    connection.formalParameter = *newName;
                    changed = true;
                }
            }
        }
        return changed;
    };
    return rewrite;
}

// The renames of variables that others see as members: inputs, outputs and in-outs of a
// function block or function.
Renames interfaceRenames(const model::Pou &pou, const Renames &renames)
{
    if (pou.kind == model::PouKind::Program || !pou.pouInterface)
        return {};
    Renames visible;
    for (const model::VarList &list : pou.pouInterface->varLists) {
        const bool isInterface = list.kind == model::VarListKind::Input || list.kind == model::VarListKind::Output
            || list.kind == model::VarListKind::InOut;
        for (const model::Variable &variable : list.variables) {
            const QString *newName = isInterface ? newNameOf(renames, variable.name) : nullptr;
            if (newName)
                visible.push_back({variable.name, *newName});
        }
    }
    return visible;
}

// Variables the POU declares itself (VAR_EXTERNAL excluded): a global of that name is hidden.
bool declaresLocally(const model::Pou &pou, const QString &name)
{
    if (!pou.pouInterface)
        return false;
    return std::ranges::any_of(pou.pouInterface->varLists, [&](const model::VarList &list) {
        return list.kind != model::VarListKind::External
            && std::ranges::any_of(list.variables, [&](const model::Variable &v) { return sameName(v.name, name); });
    });
}

const model::Variable *findExternal(const model::Pou &pou, const QString &name)
{
    if (!pou.pouInterface)
        return nullptr;
    for (const model::VarList &list : pou.pouInterface->varLists) {
        if (list.kind != model::VarListKind::External)
            continue;
        for (const model::Variable &variable : list.variables) {
            if (sameName(variable.name, name))
                return &variable;
        }
    }
    return nullptr;
}

// ---- POU and part renames

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

// Calls of renamed POUs (several at once): names in text, and blocks that name them as type.
BodyRewrite pouNamesRewrite(const Renames &renames)
{
    BodyRewrite rewrite;
    rewrite.text = [renames](const QString &text, TextDialect dialect) {
        return renameIdentifiers(text, renames, dialect);
    };
    rewrite.element = [renames](model::Element &element, const std::vector<model::Element> &) {
        auto *block = std::get_if<model::Block>(&element);
        const QString *newName = block ? newNameOf(renames, block->typeName) : nullptr;
        if (newName)
            block->typeName = *newName;
        return newName != nullptr;
    };
    return rewrite;
}

BodyRewrite pouNameRewrite(const QString &oldName, const QString &newName)
{
    return pouNamesRewrite({{oldName, newName}});
}

void renameTypes(model::DataType &type, const Renames &renames);

void renameTypes(model::Box<model::DataType> &type, const Renames &renames)
{
    renameTypes(*type, renames);
}

void renameTypes(std::vector<model::VarList> &lists, const Renames &renames)
{
    for (model::VarList &list : lists) {
        for (model::Variable &variable : list.variables)
            renameTypes(variable.type, renames);
    }
}

// Every type name inside a type: derived types, and what arrays, enums, structs, subranges and
// pointers are built on.
void renameTypes(model::DataType &type, const Renames &renames)
{
    if (auto *derived = std::get_if<model::DerivedType>(&type.kind)) {
        if (const QString *newName = newNameOf(renames, derived->name))
            derived->name = *newName;
    } else if (auto *array = std::get_if<model::ArrayType>(&type.kind)) {
        renameTypes(array->baseType, renames);
    } else if (auto *enumeration = std::get_if<model::EnumType>(&type.kind); enumeration && enumeration->baseType) {
        renameTypes(*enumeration->baseType, renames);
    } else if (auto *structure = std::get_if<model::StructType>(&type.kind)) {
        for (model::Variable &member : structure->members)
            renameTypes(member.type, renames);
    } else if (auto *subrange = std::get_if<model::SubrangeType>(&type.kind)) {
        renameTypes(subrange->baseType, renames);
    } else if (auto *pointer = std::get_if<model::PointerType>(&type.kind)) {
        renameTypes(pointer->baseType, renames);
    }
}

void renameTypesInInstances(model::Instances &instances, const Renames &renames)
{
    const auto renameInstances = [&](std::vector<model::PouInstance> &pouInstances) {
        for (model::PouInstance &instance : pouInstances) {
            if (const QString *newName = newNameOf(renames, instance.typeName))
                instance.typeName = *newName;
        }
    };
    for (model::Configuration &configuration : instances.configurations) {
        renameTypes(configuration.globalVars, renames);
        for (model::Resource &resource : configuration.resources) {
            renameTypes(resource.globalVars, renames);
            renameInstances(resource.pouInstances);
            for (model::Task &task : resource.tasks)
                renameInstances(task.pouInstances);
        }
    }
}

// Action blocks name actions; transitions name transitions by reference; text calls actions.
BodyRewrite partNameRewrite(BodyRef::Part part, const QString &oldName, const QString &newName)
{
    BodyRewrite rewrite;
    const Renames renames {{oldName, newName}};
    rewrite.inGraphics = false;
    rewrite.text = [renames](const QString &text, TextDialect dialect) {
        return renameIdentifiers(text, renames, dialect);
    };
    rewrite.element = [part, renames](model::Element &element, const std::vector<model::Element> &) {
        bool changed = false;
        if (auto *block = std::get_if<model::ActionBlock>(&element); block && part == BodyRef::Part::Action) {
            for (model::ActionBlockAction &action : block->actions)
                changed |= renameReference(action.reference, renames);
        } else if (auto *step = std::get_if<model::Step>(&element); step && part == BodyRef::Part::Action) {
            // A step's entry, exit and active actions (CoDeSys step options) name actions too.
            model::StepOptions options = model::stepOptions(*step);
            for (QString *action : {&options.entryAction, &options.exitAction, &options.activeAction}) {
                if (const QString *renamed = newNameOf(renames, *action)) {
                    *action = *renamed;
                    changed = true;
                }
            }
            if (changed)
                model::setStepOptions(*step, options);
        } else if (auto *transition = std::get_if<model::Transition>(&element);
                   transition && part == BodyRef::Part::Transition && transition->condition) {
            if (auto *reference = std::get_if<model::Reference>(&transition->condition->kind)) {
                std::optional<model::Reference> named = *reference;
                changed = renameReference(named, renames);
                *reference = *named;
            }
        }
        return changed;
    };
    return rewrite;
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
    // The part's own body is left alone: once renamed it is found under another name, so a
    // command made now could not address it (and an action rarely names itself).
    addPouRewrite(model, *pou, partNameRewrite(part, oldName, newName), command, BodyRef {pouId, part, oldName});
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
    const BodyRewrite rewrite = pouNameRewrite(oldName, newName);
    for (const model::Pou &each : model.project().types.pous) {
        addPouRewrite(model, each, rewrite, command);
        renameInDeclarations(model, each, oldName, newName, command);
    }
    // The tasks that run a renamed program.
    if (auto instances = model::instancesWithProgramRenamed(model.project().instances, oldName, newName))
        new model::SetInstancesCommand(model, std::move(*instances), command);
    return command;
}

void addVariableReferenceRenames(
    model::ProjectModel &model, model::PouId pouId, const Renames &renames, QUndoCommand *gesture)
{
    const model::Project &project = model.project();
    const model::Pou *owner = project.findPou(pouId);
    if (!owner || renames.empty())
        return;
    const Renames members = interfaceRenames(*owner, renames);
    for (const model::Pou &pou : project.types.pous) {
        // Members first: they find types by the names the declarations still have.
        std::vector<BodyRewrite> rewrites;
        if (!members.empty())
            rewrites.push_back(memberRewrite(project, pou, owner->name, members));
        if (pou.id == pouId)
            rewrites.push_back(variableRewrite(pou, renames));
        if (!rewrites.empty())
            addPouRewrite(model, pou, composed(std::move(rewrites)), gesture);
    }
}

QUndoCommand *createRenameVariableCommand(
    model::ProjectModel &model, model::PouId pou, const QString &oldName, const QString &newName)
{
    auto *command = new QUndoCommand(tr("Rename variable %1 to %2").arg(oldName, newName));
    const model::Variable *variable = model.findVariable(pou, oldName);
    if (!variable)
        return command;
    model::Variable renamed = *variable;
    renamed.name = newName;
    new model::ChangeVariableCommand(model, pou, oldName, std::move(renamed), command);
    addVariableReferenceRenames(model, pou, {{oldName, newName}}, command);
    return command;
}

namespace {

// The names of the global variable lists that declare one of the renamed globals (CODESYS GVLs:
// code may write List.Variable).
QStringList listsDeclaring(const model::Instances &instances, const Renames &renames)
{
    QStringList names;
    for (const editors::GlobalListRef &list : editors::globalLists(instances)) {
        if (list.name.isEmpty())
            continue;
        for (const model::VarList &varList : editors::globalListDeclarations(instances, list).varLists) {
            for (const model::Variable &variable : varList.variables) {
                if (newNameOf(renames, variable.name) && !names.contains(list.name, Qt::CaseInsensitive))
                    names << list.name;
            }
        }
    }
    return names;
}

// `List.Old` becomes `List.New` for the lists given, whatever the POU declares itself.
BodyRewrite qualifiedGlobalRewrite(const QStringList &lists, const Renames &renames)
{
    BodyRewrite rewrite;
    rewrite.text = [lists, renames](const QString &text, TextDialect) {
        TokenText tokens(text);
        for (size_t i = 2; i < tokens.size(); ++i) {
            const QString *newName = tokens.is(i, interp::TokenKind::Identifier) ? newNameOf(renames, tokens.word(i)) : nullptr;
            if (newName && tokens.isOperator(i - 1, u".") && lists.contains(tokens.word(i - 2).toString(), Qt::CaseInsensitive))
                tokens.replace(i, *newName);
        }
        return tokens.result();
    };
    return rewrite;
}

} // namespace

void addGlobalReferenceRenames(model::ProjectModel &model, const Renames &renames, QUndoCommand *gesture)
{
    const QStringList lists = listsDeclaring(model.project().instances, renames);
    for (const model::Pou &pou : model.project().types.pous) {
        Renames seen;
        for (const model::VariableRename &rename : renames) {
            if (declaresLocally(pou, rename.oldName))
                continue;
            seen.push_back(rename);
            if (const model::Variable *external = findExternal(pou, rename.oldName)) {
                model::Variable renamed = *external;
                renamed.name = rename.newName;
                new model::ChangeVariableCommand(model, pou.id, external->name, std::move(renamed), gesture);
            }
        }
        std::vector<BodyRewrite> rewrites;
        if (!seen.empty())
            rewrites.push_back(variableRewrite(pou, seen));
        if (!lists.isEmpty())
            rewrites.push_back(qualifiedGlobalRewrite(lists, renames));
        if (!rewrites.empty())
            addPouRewrite(model, pou, composed(std::move(rewrites)), gesture);
    }
}

QUndoCommand *createRenameGlobalVariableCommand(
    model::ProjectModel &model, const QString &oldName, const QString &newName)
{
    auto *command = new QUndoCommand(tr("Rename global variable %1 to %2").arg(oldName, newName));
    auto instances = model::instancesWithGlobalRenamed(model.project().instances, oldName, newName);
    if (!instances)
        return command;
    new model::SetInstancesCommand(model, std::move(*instances), command);
    addGlobalReferenceRenames(model, {{oldName, newName}}, command);
    return command;
}

namespace {

// The member names of structured initial values, `(X := 1, Y := 2)`, where the value has the type.
bool renameValueMembers(model::Value &value, const model::DataType &type, const TypeScope &scope,
    const QString &typeName, const Renames &renames)
{
    bool changed = false;
    if (auto *structure = std::get_if<model::StructValue>(&value.kind)) {
        const bool ofType = scope.isType(&type, typeName);
        for (model::StructValueItem &item : structure->values) {
            if (const model::DataType *memberType = scope.memberType(&type, item.member))
                changed |= renameValueMembers(*item.value, *memberType, scope, typeName, renames);
            const QString *newName = ofType ? newNameOf(renames, item.member) : nullptr;
            if (newName) {
                item.member = *newName;
                changed = true;
            }
        }
    } else if (auto *array = std::get_if<model::ArrayValue>(&value.kind)) {
        if (const model::DataType *element = scope.elementType(&type)) {
            for (model::ArrayValueItem &item : array->values)
                changed |= renameValueMembers(*item.value, *element, scope, typeName, renames);
        }
    }
    return changed;
}

void renameInitialValueMembers(model::ProjectModel &model, const model::Pou &pou, const QString &typeName,
    const Renames &renames, QUndoCommand *gesture)
{
    if (!pou.pouInterface)
        return;
    const TypeScope scope(model.project(), pou);
    for (const model::VarList &list : pou.pouInterface->varLists) {
        for (const model::Variable &variable : list.variables) {
            model::Variable changed = variable;
            if (changed.initialValue
                && renameValueMembers(*changed.initialValue, changed.type, scope, typeName, renames))
                new model::ChangeVariableCommand(model, pou.id, variable.name, std::move(changed), gesture);
        }
    }
}

} // namespace

void addMemberReferenceRenames(
    model::ProjectModel &model, const QString &typeName, const Renames &renames, QUndoCommand *gesture)
{
    const model::Project &project = model.project();
    for (const model::Pou &pou : project.types.pous) {
        addPouRewrite(model, pou, memberRewrite(project, pou, typeName, renames), gesture);
        renameInitialValueMembers(model, pou, typeName, renames, gesture);
    }
}

QUndoCommand *createRenameMemberCommand(
    model::ProjectModel &model, const QString &typeName, const QString &oldName, const QString &newName)
{
    auto *command = new QUndoCommand(tr("Rename member %1 to %2").arg(oldName, newName));
    const model::DataTypeDecl *type = model.project().findDataType(typeName);
    const auto *structure = type ? std::get_if<model::StructType>(&type->baseType.kind) : nullptr;
    if (!structure)
        return command;
    model::DataTypeDecl changed = *type;
    bool found = false;
    for (model::Variable &member : std::get<model::StructType>(changed.baseType.kind).members) {
        if (sameName(member.name, oldName)) {
            member.name = newName;
            found = true;
        }
    }
    if (!found)
        return command;
    new model::ChangeDataTypeCommand(model, type->name, std::move(changed), command);
    addMemberReferenceRenames(model, type->name, {{oldName, newName}}, command);
    return command;
}

model::Project projectWithTypesRenamed(const model::Project &project, const Renames &renames)
{
    if (renames.empty())
        return project;
    // The bodies through the same rewrites as an interactive rename, on a model of its own.
    model::ProjectModel staging;
    staging.reset(project);
    {
        QUndoCommand rewrites;
        const BodyRewrite rewrite = pouNamesRewrite(renames);
        for (const model::Pou &pou : staging.project().types.pous)
            addPouRewrite(staging, pou, rewrite, &rewrites);
        rewrites.redo();
    }
    model::Project result = staging.project();
    for (model::Pou &pou : result.types.pous) {
        if (const QString *newName = newNameOf(renames, pou.name))
            pou.name = *newName;
        if (!pou.pouInterface)
            continue;
        if (pou.pouInterface->returnType)
            renameTypes(*pou.pouInterface->returnType, renames);
        renameTypes(pou.pouInterface->varLists, renames);
    }
    for (model::DataTypeDecl &type : result.types.dataTypes) {
        if (const QString *newName = newNameOf(renames, type.name))
            type.name = *newName;
        renameTypes(type.baseType, renames);
    }
    renameTypesInInstances(result.instances, renames);
    return result;
}

} // namespace iec::app
