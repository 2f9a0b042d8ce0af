#include "model/project.h"

#include <algorithm>

namespace iec::model {

const Pou *Project::findPou(PouId id) const
{
    const auto it = std::ranges::find(pous, id, &Pou::id);
    return it == pous.end() ? nullptr : &*it;
}

const Pou *Project::findPou(const QString &name) const
{
    // IEC identifiers are case-insensitive.
    const auto it = std::ranges::find_if(pous, [&](const Pou &pou) {
        return pou.name.compare(name, Qt::CaseInsensitive) == 0;
    });
    return it == pous.end() ? nullptr : &*it;
}

} // namespace iec::model
