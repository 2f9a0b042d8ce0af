#include "app/namerules.h"

#include "editors/globals/globallists.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/frontend/codesysmembers.h"
#include "model/project.h"

#include <QRegularExpression>

#include <algorithm>
#include <functional>

namespace iec::app {

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

bool isPouOrTypeName(const model::Project &project, const QString &name, model::PouId except)
{
    const bool pouClash = std::ranges::any_of(
        project.types.pous, [&](const model::Pou &pou) { return pou.id != except && sameName(pou.name, name); });
    return pouClash || project.findDataType(name) != nullptr;
}

bool isInterfaceName(const model::Project &project, const QString &name, const QString &except = {})
{
    return !sameName(name, except)
        && std::ranges::any_of(interp::frontend::codesysInterfaceNames(project), [&](const QString &n) { return sameName(n, name); });
}

bool isPartName(const model::Project &project, model::PouId id, const QString &name, const QString &except)
{
    const model::Pou *pou = project.findPou(id);
    if (!pou)
        return false;
    const auto clashes = [&](const model::PouPart &part) {
        return sameName(part.name, name) && !(except.size() && sameName(part.name, except));
    };
    return std::ranges::any_of(pou->actions, clashes) || std::ranges::any_of(pou->transitions, clashes);
}

bool isGlobalListName(const model::Project &project, const QString &name, const QString &exceptKey)
{
    return std::ranges::any_of(editors::globalLists(project.instances), [&](const editors::GlobalListRef &list) {
        return list.key() != exceptKey && sameName(list.name, name);
    });
}

} // namespace

QString NameRules::firstFree(const QString &base, const std::function<bool(const QString &)> &taken)
{
    if (!taken(base))
        return base;
    // A trailing '_' is not allowed in IEC names, so the number joins without a second one.
    const QString stem = base.endsWith(QLatin1Char('_')) ? base : base + QLatin1Char('_');
    for (int number = 1;; ++number) {
        const QString candidate = stem + QString::number(number);
        if (!taken(candidate))
            return candidate;
    }
}

bool NameRules::isIdentifier(const QString &name)
{
    return !identifierError(name).has_value();
}

std::optional<QString> NameRules::identifierError(const QString &name)
{
    if (name.isEmpty())
        return tr("Enter a name.");
    if (!interp::hasIdentifierShape(name))
        return tr("\"%1\" is not an IEC identifier: use letters, digits and single underscores, starting with a "
                  "letter or an underscore and not ending with an underscore.")
            .arg(name);
    if (interp::isKeyword(name) || interp::isTypeName(name))
        return tr("\"%1\" is a reserved word of IEC 61131-3.").arg(name);
    return std::nullopt;
}

std::optional<QString> NameRules::pouNameError(const model::Project &project, const QString &name, model::PouId renamed)
{
    if (auto error = identifierError(name))
        return error;
    if (isPouOrTypeName(project, name, renamed))
        return tr("A POU or data type named \"%1\" exists already.").arg(name);
    if (isInterfaceName(project, name))
        return tr("An interface named \"%1\" exists already.").arg(name);
    return std::nullopt;
}

std::optional<QString> NameRules::interfaceNameError(const model::Project &project, const QString &name, const QString &renamed)
{
    if (auto error = identifierError(name))
        return error;
    if (isPouOrTypeName(project, name, {}))
        return tr("A POU or data type named \"%1\" exists already.").arg(name);
    if (isInterfaceName(project, name, renamed))
        return tr("An interface named \"%1\" exists already.").arg(name);
    return std::nullopt;
}

std::optional<QString> NameRules::partNameError(
    const model::Project &project, model::PouId pou, const QString &name, const QString &renamed)
{
    if (auto error = identifierError(name))
        return error;
    if (isPartName(project, pou, name, renamed))
        return tr("This POU has an action or transition named \"%1\" already.").arg(name);
    return std::nullopt;
}

std::optional<QString> NameRules::memberNameError(const model::Project &project, model::PouId pou, const QString &name)
{
    if (auto error = identifierError(name))
        return error;
    const model::Pou *found = project.findPou(pou);
    if (found && std::ranges::any_of(interp::frontend::codesysMembers(*found), [&](const interp::frontend::CodesysMemberSummary &m) {
            return m.name.compare(name, Qt::CaseInsensitive) == 0;
        }))
        return tr("This function block has a method or property named \"%1\" already.").arg(name);
    return std::nullopt;
}

std::optional<QString> NameRules::globalListNameError(
    const model::Project &project, const QString &name, const QString &renamedKey)
{
    if (auto error = identifierError(name))
        return error;
    if (isGlobalListName(project, name, renamedKey))
        return tr("A global variable list named \"%1\" exists already.").arg(name);
    if (isPouOrTypeName(project, name, {}))
        return tr("A POU or data type named \"%1\" exists already.").arg(name);
    return std::nullopt;
}

QString NameRules::uniqueGlobalListName(const model::Project &project, const QString &base)
{
    return firstFree(base, [&](const QString &name) {
        return isGlobalListName(project, name, {}) || isPouOrTypeName(project, name, {});
    });
}

QString NameRules::uniquePouName(const model::Project &project, const QString &base)
{
    return firstFree(base, [&](const QString &name) { return isPouOrTypeName(project, name, {}) || isInterfaceName(project, name); });
}

QString NameRules::uniquePartName(const model::Project &project, model::PouId pou, const QString &base)
{
    return firstFree(base, [&](const QString &name) { return isPartName(project, pou, name, {}); });
}

} // namespace iec::app
