#include "model/projectmodel.h"

#include <algorithm>

namespace iec::model {

ProjectModel::ProjectModel(QObject *parent)
    : QObject(parent)
{
}

void ProjectModel::reset(Project project)
{
    m_project = std::move(project);
    m_nextPouId = 1;
    for (const Pou &pou : m_project.pous)
        m_nextPouId = std::max(m_nextPouId, pou.id.value + 1);
    for (Pou &pou : m_project.pous) {
        if (!pou.id.isValid())
            pou.id = allocatePouId();
    }
    touch();
    Q_EMIT projectReset();
}

PouId ProjectModel::addPou(Pou pou)
{
    if (!pou.id.isValid() || m_project.findPou(pou.id))
        pou.id = allocatePouId();
    else
        m_nextPouId = std::max(m_nextPouId, pou.id.value + 1);
    const PouId id = pou.id;
    m_project.pous.push_back(std::move(pou));
    touch();
    Q_EMIT pouAdded(id);
    return id;
}

bool ProjectModel::removePou(PouId id)
{
    const auto removed = std::erase_if(m_project.pous, [id](const Pou &pou) { return pou.id == id; });
    if (removed == 0)
        return false;
    touch();
    Q_EMIT pouRemoved(id);
    return true;
}

bool ProjectModel::renamePou(PouId id, const QString &newName)
{
    Pou *pou = findMutablePou(id);
    if (!pou || pou->name == newName)
        return false;
    pou->name = newName;
    touch();
    Q_EMIT pouRenamed(id);
    return true;
}

Pou *ProjectModel::findMutablePou(PouId id)
{
    return const_cast<Pou *>(m_project.findPou(id));
}

PouId ProjectModel::allocatePouId()
{
    return PouId{m_nextPouId++};
}

} // namespace iec::model
