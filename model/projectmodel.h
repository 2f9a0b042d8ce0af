#pragma once

#include "model/project.h"

#include <QObject>

namespace iec::model {

// Owns the project value and is the only thing that changes it. Every change bumps the revision
// and emits a coarse signal that carries ids, never pointers.
class ProjectModel : public QObject
{
    Q_OBJECT

public:
    explicit ProjectModel(QObject *parent = nullptr);

    [[nodiscard]] const Project &project() const { return m_project; }
    [[nodiscard]] quint64 revision() const { return m_revision; }

    void reset(Project project);

    // Adds the POU; an invalid id in `pou` gets a fresh one. Returns the id it was stored under.
    PouId addPou(Pou pou);
    bool removePou(PouId id);
    bool renamePou(PouId id, const QString &newName);

Q_SIGNALS:
    void projectReset();
    void pouAdded(iec::model::PouId id);
    void pouRemoved(iec::model::PouId id);
    void pouRenamed(iec::model::PouId id);

private:
    Pou *findMutablePou(PouId id);
    PouId allocatePouId();
    void touch() { ++m_revision; }

    Project m_project;
    quint64 m_revision = 0;
    quint32 m_nextPouId = 1;
};

} // namespace iec::model
