#include "model/project.h"

#include <algorithm>

namespace iec::model {

BodyLanguage Pou::language() const
{
    return bodies.empty() ? BodyLanguage::ST : bodies.front().language();
}

const Pou *Project::findPou(PouId id) const
{
    const auto it = std::ranges::find(types.pous, id, &Pou::id);
    return it == types.pous.end() ? nullptr : &*it;
}

const Pou *Project::findPou(const QString &name) const
{
    // IEC identifiers are case-insensitive.
    const auto it = std::ranges::find_if(
        types.pous, [&](const Pou &pou) { return pou.name.compare(name, Qt::CaseInsensitive) == 0; });
    return it == types.pous.end() ? nullptr : &*it;
}

const DataTypeDecl *Project::findDataType(const QString &name) const
{
    const auto it = std::ranges::find_if(
        types.dataTypes, [&](const DataTypeDecl &type) { return type.name.compare(name, Qt::CaseInsensitive) == 0; });
    return it == types.dataTypes.end() ? nullptr : &*it;
}

} // namespace iec::model
