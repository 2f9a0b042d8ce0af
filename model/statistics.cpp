#include "model/statistics.h"

namespace iec::model {

namespace {

void countElements(const Body &body, ProjectStatistics &stats)
{
    if (const std::vector<Element> *elements = body.elements()) {
        stats.elements += int(elements->size());
        for (const Element &element : *elements)
            ++stats.elementsByKind[QString::fromLatin1(elementTagName(element))];
    }
}

int countVariables(const std::vector<VarList> &lists)
{
    int count = 0;
    for (const VarList &list : lists)
        count += int(list.variables.size());
    return count;
}

} // namespace

QString pouKindName(PouKind kind)
{
    switch (kind) {
    case PouKind::Program:
        return QStringLiteral("program");
    case PouKind::FunctionBlock:
        return QStringLiteral("functionBlock");
    case PouKind::Function:
        return QStringLiteral("function");
    }
    return {};
}

QString bodyLanguageName(BodyLanguage language)
{
    switch (language) {
    case BodyLanguage::ST:
        return QStringLiteral("ST");
    case BodyLanguage::IL:
        return QStringLiteral("IL");
    case BodyLanguage::LD:
        return QStringLiteral("LD");
    case BodyLanguage::FBD:
        return QStringLiteral("FBD");
    case BodyLanguage::SFC:
        return QStringLiteral("SFC");
    }
    return {};
}

ProjectStatistics statistics(const Project &project)
{
    ProjectStatistics stats;
    for (PouKind kind : {PouKind::Program, PouKind::FunctionBlock, PouKind::Function})
        stats.pousByKind[pouKindName(kind)] = 0;
    for (BodyLanguage language :
        {BodyLanguage::ST, BodyLanguage::IL, BodyLanguage::LD, BodyLanguage::FBD, BodyLanguage::SFC})
        stats.pousByLanguage[bodyLanguageName(language)] = 0;
    stats.pousByLanguage[QStringLiteral("none")] = 0;

    for (const Pou &pou : project.types.pous) {
        ++stats.pous;
        ++stats.pousByKind[pouKindName(pou.kind)];
        ++stats.pousByLanguage[pou.bodies.empty() ? QStringLiteral("none") : bodyLanguageName(pou.language())];
        if (pou.pouInterface)
            stats.variables += countVariables(pou.pouInterface->varLists);
        stats.actions += int(pou.actions.size());
        stats.transitions += int(pou.transitions.size());
        for (const Body &body : pou.bodies)
            countElements(body, stats);
        for (const PouAction &action : pou.actions)
            countElements(action.body, stats);
        for (const PouTransition &transition : pou.transitions)
            countElements(transition.body, stats);
    }
    stats.dataTypes = int(project.types.dataTypes.size());
    for (const Configuration &configuration : project.instances.configurations) {
        stats.variables += countVariables(configuration.globalVars);
        for (const Resource &resource : configuration.resources)
            stats.variables += countVariables(resource.globalVars);
    }
    return stats;
}

} // namespace iec::model
