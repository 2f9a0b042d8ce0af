#include "app/projectcommands.h"

#include "app/namerules.h"
#include "app/referencerename.h"
#include "editors/common/editorregistry.h"
#include "editors/standardeditors.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/frontend/codesysmembers.h"
#include "model/plcopen/codesysoop.h"
#include "model/projectmodel.h"
#include "model/undo/instancecommands.h"
#include "model/undo/partcommands.h"
#include "model/undo/poucommands.h"

#include <QUndoStack>

namespace iec::app {

using model::BodyRef;

namespace {

model::DataType dataTypeNamed(const QString &name)
{
    const QString upper = name.toUpper();
    if (upper == u"STRING" || upper == u"WSTRING")
        return {model::StringType {.wide = upper == u"WSTRING"}};
    if (interp::isTypeName(name))
        return {model::ElementaryType {upper}};
    return {model::DerivedType {.name = name}};
}

// Says why an operation was refused; returns false so `return fail(...)` reads as the refusal.
bool fail(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return false;
}

} // namespace

model::Body startingBody(editors::EditorLanguage language)
{
    editors::registerStandardEditors();
    const editors::EditorFactory *factory = editors::EditorRegistry::instance().find(language);
    return factory && factory->newBody ? factory->newBody() : model::Body::withLanguage(editors::storedLanguage(language));
}

model::Pou makePou(const NewPou &pou)
{
    model::Pou value;
    value.name = pou.name;
    value.kind = pou.kind;
    value.pouInterface = model::Interface {};
    if (pou.kind == model::PouKind::Function)
        value.pouInterface->returnType = dataTypeNamed(pou.returnType.trimmed());
    value.bodies.push_back(startingBody(pou.language));
    return value;
}

ProjectCommands::ProjectCommands(model::ProjectModel &model, QUndoStack &projectStack)
    : m_model(model)
    , m_stack(projectStack)
{ }

std::optional<model::PouId> ProjectCommands::addPou(const NewPou &pou, QString *error)
{
    if (const auto problem = NameRules::pouNameError(m_model.project(), pou.name)) {
        fail(error, *problem);
        return std::nullopt;
    }
    if (pou.kind == model::PouKind::Function && !NameRules::isIdentifier(pou.returnType.trimmed())
        && !interp::isTypeName(pou.returnType.trimmed())) {
        fail(error, tr("A function needs a return type."));
        return std::nullopt;
    }
    auto *command = new model::AddPouCommand(m_model, makePou(pou));
    m_stack.push(command);
    return command->pouId();
}

std::optional<BodyRef> ProjectCommands::addPouPart(model::PouId pou, const NewPouPart &part, QString *error)
{
    if (!m_model.project().findPou(pou)) {
        fail(error, tr("The POU does not exist any more."));
        return std::nullopt;
    }
    if (const auto problem = NameRules::partNameError(m_model.project(), pou, part.name)) {
        fail(error, *problem);
        return std::nullopt;
    }
    model::PouPart value;
    value.name = part.name;
    value.body = startingBody(part.language);
    m_stack.push(new model::AddPouPartCommand(m_model, pou, part.part, std::move(value)));
    return BodyRef {pou, part.part, part.name};
}

bool ProjectCommands::rename(const BodyRef &item, const QString &newName, QString *error)
{
    flushPendingEdits();
    const QString oldName = nameOf(item);
    if (oldName.isEmpty())
        return fail(error, tr("The item does not exist any more."));
    if (newName == oldName)
        return true;
    if (item.part == BodyRef::Part::Pou) {
        if (const auto problem = NameRules::pouNameError(m_model.project(), newName, item.pou))
            return fail(error, *problem);
        m_stack.push(createRenamePouCommand(m_model, item.pou, newName));
        return true;
    }
    if (const auto problem = NameRules::partNameError(m_model.project(), item.pou, newName, oldName))
        return fail(error, *problem);
    m_stack.push(createRenamePouPartCommand(m_model, item.pou, item.part, oldName, newName));
    return true;
}

bool ProjectCommands::addMember(model::PouId pou, const QString &name, bool property, QString *error)
{
    const model::Pou *found = m_model.project().findPou(pou);
    if (!found || found->kind != model::PouKind::FunctionBlock)
        return fail(error, tr("Methods and properties belong to function blocks."));
    if (const auto problem = NameRules::memberNameError(m_model.project(), pou, name))
        return fail(error, *problem);
    const QString text = property
        ? QStringLiteral("PROPERTY %1 : INT\nGET\n%1 := 0;\nEND_GET\nSET\nEND_SET\nEND_PROPERTY\n").arg(name)
        : QStringLiteral("METHOD %1 : BOOL\nVAR_INPUT\nEND_VAR\n%1 := TRUE;\nEND_METHOD\n").arg(name);
    const interp::frontend::CodesysMemberText read = interp::frontend::readCodesysMemberText(text, found->name);
    if (!read.definition)
        return fail(error, tr("The name \"%1\" cannot start a method.").arg(name));
    m_stack.push(new model::SetPouAddDataCommand(m_model, pou,
        model::plcopen::addDataWithMember(found->addData, {}, *read.definition),
        property ? tr("Add Property %1").arg(name) : tr("Add Method %1").arg(name)));
    return true;
}

bool ProjectCommands::removeMember(model::PouId pou, const QString &name)
{
    flushPendingEdits();
    const model::Pou *found = m_model.project().findPou(pou);
    if (!found)
        return false;
    const model::AddData without = model::plcopen::addDataWithoutMember(found->addData, name);
    if (without == found->addData)
        return false;
    m_stack.push(new model::SetPouAddDataCommand(m_model, pou, without, tr("Delete %1").arg(name)));
    return true;
}

bool ProjectCommands::addInterface(const QString &name, QString *error)
{
    flushPendingEdits();
    const model::Project &project = m_model.project();
    if (const auto problem = NameRules::interfaceNameError(project, name))
        return fail(error, *problem);
    const model::plcopen::CodesysInterfaceDefinition empty {name, {}, {}};
    m_stack.push(new model::SetProjectAddDataCommand(m_model, model::plcopen::addDataWithInterface(project.addData, {}, empty),
        tr("Add Interface %1").arg(name)));
    return true;
}

bool ProjectCommands::removeInterface(const QString &name)
{
    flushPendingEdits();
    const model::AddData without = model::plcopen::addDataWithoutInterface(m_model.project().addData, name);
    if (without == m_model.project().addData)
        return false;
    m_stack.push(new model::SetProjectAddDataCommand(m_model, without, tr("Delete %1").arg(name)));
    return true;
}

bool ProjectCommands::remove(const BodyRef &item)
{
    flushPendingEdits();
    const QString name = nameOf(item);
    if (name.isEmpty())
        return false;
    if (item.part == BodyRef::Part::Pou)
        m_stack.push(new model::RemovePouCommand(m_model, item.pou));
    else
        m_stack.push(new model::RemovePouPartCommand(m_model, item.pou, item.part, name));
    return true;
}

std::optional<BodyRef> ProjectCommands::duplicate(const BodyRef &item)
{
    flushPendingEdits();
    const QString name = nameOf(item);
    if (name.isEmpty())
        return std::nullopt;
    if (item.part == BodyRef::Part::Pou) {
        const QString copyName = NameRules::uniquePouName(m_model.project(), name);
        auto *command = new model::DuplicatePouCommand(m_model, item.pou, copyName);
        m_stack.push(command);
        return BodyRef {command->copyId(), BodyRef::Part::Pou, {}};
    }
    const QString copyName = NameRules::uniquePartName(m_model.project(), item.pou, name);
    m_stack.push(model::AddPouPartCommand::duplicate(m_model, item.pou, item.part, name, copyName));
    return BodyRef {item.pou, item.part, copyName};
}

void ProjectCommands::flushPendingEdits() const
{
    if (m_flushPendingEdits)
        m_flushPendingEdits();
}

QString ProjectCommands::nameOf(const BodyRef &item) const
{
    if (item.part == BodyRef::Part::Pou) {
        const model::Pou *pou = m_model.project().findPou(item.pou);
        return pou ? pou->name : QString();
    }
    const model::PouPart *part = m_model.findPouPart(item.pou, item.part, item.name);
    return part ? part->name : QString();
}

} // namespace iec::app
