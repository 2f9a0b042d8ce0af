#include "app/referencerename.h"

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

} // namespace

namespace {

// ---- types of names, for `x.Member` where x's type is known from the declarations

class TypeScope
{
public:
    TypeScope(const model::Project &project, const model::Pou &pou)
        : m_project(project)
        , m_pou(pou)
    { }

    // The declared type of variable `name` of the POU, else of a global; nullptr when unknown.
    [[nodiscard]] const model::DataType *variableType(QStringView name) const
    {
        if (m_pou.pouInterface) {
            if (const model::DataType *type = typeIn(m_pou.pouInterface->varLists, name))
                return type;
        }
        for (const model::Configuration &configuration : m_project.instances.configurations) {
            if (const model::DataType *type = typeIn(configuration.globalVars, name))
                return type;
            for (const model::Resource &resource : configuration.resources) {
                if (const model::DataType *type = typeIn(resource.globalVars, name))
                    return type;
            }
        }
        return nullptr;
    }

    [[nodiscard]] bool isPou(QStringView name) const { return m_project.findPou(name.toString()) != nullptr; }

    // Whether `type` is `typeName` itself or an alias of it.
    [[nodiscard]] bool isType(const model::DataType *type, const QString &typeName) const
    {
        for (int depth = 0; type && depth < kAliasDepth; ++depth) {
            const auto *derived = std::get_if<model::DerivedType>(&type->kind);
            if (!derived)
                return false;
            if (sameName(derived->name, typeName))
                return true;
            const model::DataTypeDecl *declared = m_project.findDataType(derived->name);
            type = declared ? &declared->baseType : nullptr;
        }
        return false;
    }

    // The element type of an array type (through aliases).
    [[nodiscard]] const model::DataType *elementType(const model::DataType *type) const
    {
        type = resolved(type);
        const auto *array = type ? std::get_if<model::ArrayType>(&type->kind) : nullptr;
        return array ? &*array->baseType : nullptr;
    }

    // The type of member `member` of a struct type or of a function block's instance.
    [[nodiscard]] const model::DataType *memberType(const model::DataType *type, QStringView member) const
    {
        for (int depth = 0; type && depth < kAliasDepth; ++depth) {
            if (const auto *structure = std::get_if<model::StructType>(&type->kind)) {
                const auto it = std::ranges::find_if(
                    structure->members, [&](const model::Variable &v) { return sameName(v.name, member); });
                return it == structure->members.end() ? nullptr : &it->type;
            }
            const auto *derived = std::get_if<model::DerivedType>(&type->kind);
            if (!derived)
                return nullptr;
            if (const model::Pou *block = m_project.findPou(derived->name))
                return block->pouInterface ? typeIn(block->pouInterface->varLists, member) : nullptr;
            const model::DataTypeDecl *declared = m_project.findDataType(derived->name);
            type = declared ? &declared->baseType : nullptr;
        }
        return nullptr;
    }

private:
    static constexpr int kAliasDepth = 16; // TYPE A : B; B : A; must not loop

    static const model::DataType *typeIn(const std::vector<model::VarList> &lists, QStringView name)
    {
        for (const model::VarList &list : lists) {
            for (const model::Variable &variable : list.variables) {
                if (sameName(variable.name, name))
                    return &variable.type;
            }
        }
        return nullptr;
    }

    const model::DataType *resolved(const model::DataType *type) const
    {
        for (int depth = 0; type && depth < kAliasDepth; ++depth) {
            const auto *derived = std::get_if<model::DerivedType>(&type->kind);
            if (!derived)
                return type;
            const model::DataTypeDecl *declared = m_project.findDataType(derived->name);
            type = declared ? &declared->baseType : nullptr;
        }
        return nullptr;
    }

    const model::Project &m_project;
    const model::Pou &m_pou;
};

// Renames members of `typeName` in text: after a '.' that follows an expression of that type
// (x.M, a[i].M, x.Inner.M), and formal parameters of calls of it (fb(M := 1), Fn(M := 1)).
QString renameMembers(const QString &text, const TypeScope &scope, const QString &typeName, const Renames &renames)
{
    TokenText tokens(text);
    struct Bracket {
        bool call = false;
        bool callsType = false; // a call of an instance of typeName, or of the function itself
        const model::DataType *element = nullptr; // '[': the type after the closing ']'
    };
    std::vector<Bracket> open;
    const model::DataType *current = nullptr; // the type of the expression just read
    QStringView currentPou; // a bare POU name just read (a function about to be called)
    for (size_t i = 0; i < tokens.size(); ++i) {
        const QStringView word = tokens.word(i);
        if (tokens.is(i, interp::TokenKind::Identifier)) {
            const bool inCall = !open.empty() && open.back().call;
            if (inCall && tokens.isAssignmentAfter(i)) {
                if (const QString *newName = open.back().callsType ? newNameOf(renames, word) : nullptr)
                    tokens.replace(i, *newName);
                current = nullptr;
                currentPou = {};
                continue;
            }
            current = scope.variableType(word);
            currentPou = !current && scope.isPou(word) ? word : QStringView();
            continue;
        }
        if (tokens.isOperator(i, u".") && tokens.is(i + 1, interp::TokenKind::Identifier)) {
            const QStringView member = tokens.word(i + 1);
            if (scope.isType(current, typeName)) {
                if (const QString *newName = newNameOf(renames, member))
                    tokens.replace(i + 1, *newName);
            }
            current = scope.memberType(current, member);
            currentPou = {};
            ++i;
            continue;
        }
        if (tokens.isOperator(i, u"[")) {
            open.push_back({.element = scope.elementType(current)});
            current = nullptr;
        } else if (tokens.isOperator(i, u"]")) {
            current = !open.empty() && !open.back().call ? open.back().element : nullptr;
            if (!open.empty())
                open.pop_back();
        } else if (tokens.isOperator(i, u"(")) {
            const bool callsType = current ? scope.isType(current, typeName) : sameName(currentPou, typeName);
            open.push_back({.call = true, .callsType = callsType});
            current = nullptr;
        } else {
            if (tokens.isOperator(i, u")") && !open.empty())
                open.pop_back();
            current = nullptr;
        }
        currentPou = {};
    }
    return tokens.result();
}

// ---- bodies: one rewrite applied to text, expressions and elements, as commands

using TextRewrite = std::function<QString(const QString &, TextDialect)>;
using ElementRewrite = std::function<bool(model::Element &, const std::vector<model::Element> &siblings)>;

struct BodyRewrite {
    TextRewrite text;
    ElementRewrite element;
    // Whether `text` also applies to the expressions of graphical elements (variables, contacts,
    // coils, inline SFC conditions and actions); names of actions and transitions are not there.
    bool inGraphics = true;
};

TextDialect dialectOf(const model::Body &body)
{
    return body.language() == model::BodyLanguage::IL ? TextDialect::IL : TextDialect::ST;
}

bool rewriteBodyValue(model::Body &body, const BodyRewrite &rewrite);

bool rewriteText(QString &text, const BodyRewrite &rewrite)
{
    if (!rewrite.text || !rewrite.inGraphics)
        return false;
    const QString renamed = rewrite.text(text, TextDialect::ST);
    if (renamed == text)
        return false;
    text = renamed;
    return true;
}

bool rewriteText(std::optional<QString> &text, const BodyRewrite &rewrite)
{
    return text && rewriteText(*text, rewrite);
}

bool rewriteInline(std::optional<model::Box<model::Body>> &body, const BodyRewrite &rewrite)
{
    return body && rewrite.inGraphics && rewriteBodyValue(**body, rewrite);
}

bool rewriteElement(model::Element &element, const std::vector<model::Element> &siblings, const BodyRewrite &rewrite)
{
    bool changed = false;
    if (auto *in = std::get_if<model::InVariable>(&element))
        changed |= rewriteText(in->expression, rewrite);
    else if (auto *out = std::get_if<model::OutVariable>(&element))
        changed |= rewriteText(out->expression, rewrite);
    else if (auto *inOut = std::get_if<model::InOutVariable>(&element))
        changed |= rewriteText(inOut->expression, rewrite);
    else if (auto *contact = std::get_if<model::Contact>(&element))
        changed |= rewriteText(contact->variable, rewrite);
    else if (auto *coil = std::get_if<model::Coil>(&element))
        changed |= rewriteText(coil->variable, rewrite);
    else if (auto *macro = std::get_if<model::MacroStep>(&element))
        changed |= rewriteInline(macro->body, rewrite);
    if (auto *block = std::get_if<model::ActionBlock>(&element)) {
        for (model::ActionBlockAction &action : block->actions) {
            changed |= rewriteText(action.indicator, rewrite);
            changed |= rewriteInline(action.inlineBody, rewrite);
        }
    }
    if (auto *transition = std::get_if<model::Transition>(&element); transition && transition->condition) {
        if (auto *inlined = std::get_if<model::InlineCondition>(&transition->condition->kind); inlined && rewrite.inGraphics)
            changed |= rewriteBodyValue(*inlined->body, rewrite);
    }
    for (model::ConnectionPointIn *point : model::inputPoints(element))
        changed |= rewriteText(point->expression, rewrite);
    if (rewrite.element)
        changed |= rewrite.element(element, siblings);
    return changed;
}

bool rewriteBodyValue(model::Body &body, const BodyRewrite &rewrite)
{
    if (std::vector<model::Element> *elements = body.elements()) {
        const std::vector<model::Element> siblings = *elements;
        bool changed = false;
        for (model::Element &element : *elements)
            changed |= rewriteElement(element, siblings, rewrite);
        return changed;
    }
    if (!rewrite.text)
        return false;
    const QString text = body.text();
    const QString renamed = rewrite.text(text, dialectOf(body));
    if (renamed == text)
        return false;
    body.setText(renamed);
    return true;
}

// One command per changed element or text body, under `parent`.
void addBodyRewrite(model::ProjectModel &model, const BodyRef &ref, const model::Body &body,
    const BodyRewrite &rewrite, QUndoCommand *parent)
{
    if (const std::vector<model::Element> *elements = body.elements()) {
        for (const model::Element &element : *elements) {
            model::Element changed = element;
            if (rewriteElement(changed, *elements, rewrite))
                new model::ChangeElementCommand(model, ref, std::move(changed), parent);
        }
        return;
    }
    if (!rewrite.text)
        return;
    const QString text = body.text();
    if (const QString renamed = rewrite.text(text, dialectOf(body)); renamed != text)
        new model::SetBodyTextCommand(model, ref, renamed, parent);
}

// The POU's body and the bodies of its actions and transitions; `skip` is left alone.
void addPouRewrite(model::ProjectModel &model, const model::Pou &pou, const BodyRewrite &rewrite,
    QUndoCommand *parent, const std::optional<BodyRef> &skip = {})
{
    const auto visit = [&](const BodyRef &ref, const model::Body &body) {
        if (!(skip && skip->part == ref.part && sameName(skip->name, ref.name)))
            addBodyRewrite(model, ref, body, rewrite, parent);
    };
    if (const model::Body *body = pou.body())
        visit({pou.id, BodyRef::Part::Pou, {}}, *body);
    for (const model::PouPart &action : pou.actions)
        visit({pou.id, BodyRef::Part::Action, action.name}, action.body);
    for (const model::PouPart &transition : pou.transitions)
        visit({pou.id, BodyRef::Part::Transition, transition.name}, transition.body);
}

// Several rewrites of the same bodies as one (one command per body, applied in order).
BodyRewrite composed(std::vector<BodyRewrite> rewrites)
{
    BodyRewrite result;
    result.inGraphics = std::ranges::any_of(rewrites, &BodyRewrite::inGraphics);
    result.text = [rewrites](const QString &text, TextDialect dialect) {
        QString out = text;
        for (const BodyRewrite &rewrite : rewrites) {
            if (rewrite.text)
                out = rewrite.text(out, dialect);
        }
        return out;
    };
    result.element = [rewrites](model::Element &element, const std::vector<model::Element> &siblings) {
        bool changed = false;
        for (const BodyRewrite &rewrite : rewrites) {
            if (rewrite.element)
                changed |= rewrite.element(element, siblings);
        }
        return changed;
    };
    return result;
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
