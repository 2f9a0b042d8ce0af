#include "app/projectsymbols.h"

#include "editors/datatypes/typetext.h"
#include "model/projectmodel.h"

#include <utility>

namespace iec::app {

using editors::CompletionItem;

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

void appendLists(std::vector<VisibleVariable> &out, const std::vector<model::VarList> &lists, bool global)
{
    for (const model::VarList &list : lists) {
        for (const model::Variable &variable : list.variables)
            out.push_back({&variable, list.kind, global});
    }
}

// A data type as far as members are concerned: user aliases followed to what they name (a
// bounded walk, so a cycle in a broken project ends).
const model::DataType *resolved(const model::Project &project, const model::DataType *type)
{
    for (int depth = 0; type && depth < 16; ++depth) {
        const auto *derived = std::get_if<model::DerivedType>(&type->kind);
        if (!derived)
            return type;
        const model::DataTypeDecl *decl = project.findDataType(derived->name);
        if (!decl)
            return type; // a POU (function block) or a standard FB: the name is the answer
        type = &decl->baseType;
    }
    return type;
}

// The variables a dotted access reaches inside a value of `type`: struct members, or a function
// block's inputs, outputs and in-outs (a program's whole interface).
std::vector<const model::Variable *> membersOf(const model::Project &project, const model::DataType *type)
{
    std::vector<const model::Variable *> members;
    type = resolved(project, type);
    if (!type)
        return members;
    if (const auto *structType = std::get_if<model::StructType>(&type->kind)) {
        for (const model::Variable &member : structType->members)
            members.push_back(&member);
    } else if (const auto *derived = std::get_if<model::DerivedType>(&type->kind)) {
        const model::Pou *pou = project.findPou(derived->name);
        if (!pou || !pou->pouInterface || pou->kind == model::PouKind::Function)
            return members;
        for (const model::VarList &list : pou->pouInterface->varLists) {
            const bool visible = pou->kind == model::PouKind::Program || list.kind == model::VarListKind::Input
                || list.kind == model::VarListKind::Output || list.kind == model::VarListKind::InOut;
            if (!visible)
                continue;
            for (const model::Variable &member : list.variables)
                members.push_back(&member);
        }
    }
    return members;
}

// Steps into the element type once per "[...]" after a name.
const model::DataType *indexed(const model::Project &project, const model::DataType *type, int indexCount)
{
    for (int i = 0; i < indexCount && type; ++i) {
        type = resolved(project, type);
        const auto *array = type ? std::get_if<model::ArrayType>(&type->kind) : nullptr;
        type = array ? &*array->baseType : nullptr;
    }
    return type;
}

struct PathSegment {
    QString name;
    int indexCount = 0;
};

std::vector<PathSegment> segmentsOf(const QString &path)
{
    std::vector<PathSegment> segments;
    int depth = 0;
    PathSegment current;
    for (const QChar c : path) {
        if (c == QLatin1Char('[')) {
            if (depth++ == 0)
                ++current.indexCount;
        } else if (c == QLatin1Char(']')) {
            depth = std::max(0, depth - 1);
        } else if (depth == 0 && c == QLatin1Char('.')) {
            segments.push_back(std::exchange(current, {}));
        } else if (depth == 0 && !c.isSpace()) {
            current.name += c;
        }
    }
    segments.push_back(current);
    return segments;
}

// The type a path ends at; a program's name alone stands for the program (its variables are
// members, as Main.Counter reads in CODESYS).
const model::DataType *typeOfPath(
    const model::Project &project, model::PouId pou, const QString &path, model::DataType &programType)
{
    const std::vector<PathSegment> segments = segmentsOf(path);
    if (segments.empty() || segments.front().name.isEmpty())
        return nullptr;
    const model::DataType *type = nullptr;
    if (const auto found = findVisibleVariable(project, pou, segments.front().name)) {
        type = &found->variable->type;
    } else if (const model::Pou *program = project.findPou(segments.front().name);
               program && program->kind == model::PouKind::Program) {
        programType.kind = model::DerivedType {.name = program->name};
        type = &programType;
    }
    type = indexed(project, type, segments.front().indexCount);
    for (size_t i = 1; i < segments.size() && type; ++i) {
        const model::DataType *next = nullptr;
        for (const model::Variable *member : membersOf(project, type)) {
            if (sameName(member->name, segments[i].name))
                next = &member->type;
        }
        type = indexed(project, next, segments[i].indexCount);
    }
    return type;
}

QString pouSignature(const model::Pou &pou)
{
    QStringList parameters;
    if (pou.pouInterface) {
        for (const model::VarList &list : pou.pouInterface->varLists) {
            if (list.kind != model::VarListKind::Input && list.kind != model::VarListKind::InOut)
                continue;
            for (const model::Variable &variable : list.variables)
                parameters.append(variable.name + QStringLiteral(" : ") + editors::typeText(variable.type));
        }
    }
    QString signature = pou.name + QLatin1Char('(') + parameters.join(QStringLiteral(", ")) + QLatin1Char(')');
    if (pou.kind == model::PouKind::Function && pou.pouInterface && pou.pouInterface->returnType)
        signature += QStringLiteral(" : ") + editors::typeText(*pou.pouInterface->returnType);
    return signature;
}

} // namespace

std::vector<VisibleVariable> visibleVariables(const model::Project &project, model::PouId pou)
{
    std::vector<VisibleVariable> result;
    if (const model::Pou *own = project.findPou(pou); own && own->pouInterface)
        appendLists(result, own->pouInterface->varLists, false);
    for (const model::Configuration &configuration : project.instances.configurations) {
        appendLists(result, configuration.globalVars, true);
        for (const model::Resource &resource : configuration.resources)
            appendLists(result, resource.globalVars, true);
    }
    return result;
}

std::optional<VisibleVariable> findVisibleVariable(const model::Project &project, model::PouId pou, const QString &name)
{
    // The POU's own declarations come first, so they hide globals of the same name.
    for (const VisibleVariable &visible : visibleVariables(project, pou)) {
        if (sameName(visible.variable->name, name))
            return visible;
    }
    return std::nullopt;
}

QString typeNameOfPath(const model::Project &project, model::PouId pou, const QString &path)
{
    model::DataType programType;
    const model::DataType *type = typeOfPath(project, pou, path, programType);
    return type ? editors::typeText(*type) : QString();
}

ModelCompletionProvider::ModelCompletionProvider(const model::ProjectModel &model, model::PouId pou)
    : m_model(model)
    , m_pou(pou)
{
}

QList<CompletionItem> ModelCompletionProvider::variables() const
{
    QList<CompletionItem> items;
    for (const VisibleVariable &visible : visibleVariables(m_model.project(), m_pou)) {
        items.append({.text = visible.variable->name,
            .kind = CompletionItem::Kind::Variable,
            .detail = editors::typeText(visible.variable->type),
            .category = visible.global ? tr("Global variables") : tr("Local variables")});
    }
    return items;
}

QList<CompletionItem> ModelCompletionProvider::members(const QString &path) const
{
    QList<CompletionItem> items;
    const model::Project &project = m_model.project();
    model::DataType programType;
    for (const model::Variable *member : membersOf(project, typeOfPath(project, m_pou, path, programType))) {
        items.append({.text = member->name,
            .kind = CompletionItem::Kind::Member,
            .detail = editors::typeText(member->type),
            .category = {}});
    }
    return items;
}

QList<CompletionItem> ModelCompletionProvider::pous() const
{
    QList<CompletionItem> items;
    for (const model::Pou &pou : m_model.project().types.pous) {
        if (pou.id == m_pou)
            continue; // a POU does not call itself
        CompletionItem item {.text = pou.name, .kind = CompletionItem::Kind::Program, .detail = pouSignature(pou)};
        switch (pou.kind) {
        case model::PouKind::Program:
            item.category = tr("Programs");
            break;
        case model::PouKind::FunctionBlock:
            item.kind = CompletionItem::Kind::FunctionBlock;
            item.category = tr("Function blocks");
            break;
        case model::PouKind::Function:
            item.kind = CompletionItem::Kind::Function;
            item.category = tr("Functions");
            break;
        }
        items.append(item);
    }
    return items;
}

QString ModelCompletionProvider::typeOf(const QString &path) const
{
    return typeNameOfPath(m_model.project(), m_pou, path);
}

} // namespace iec::app
