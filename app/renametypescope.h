#pragma once

#include "app/textrename.h"
#include "model/project.h"

#include <QString>

// The declared types of names as a rename sees them: `x.Member` is a member of the struct or
// block x is declared as (locals of the POU first, then globals; aliases followed).
namespace iec::app {

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
    static bool sameName(QStringView a, QStringView b) { return a.compare(b, Qt::CaseInsensitive) == 0; }

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
[[nodiscard]] QString renameMembers(
    const QString &text, const TypeScope &scope, const QString &typeName, const Renames &renames);

} // namespace iec::app
