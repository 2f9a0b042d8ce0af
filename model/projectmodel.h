#pragma once

#include "model/ids.h"
#include "model/project.h"

#include <QList>
#include <QObject>

#include <optional>

namespace iec::model {

// Owns the project value and is the only thing that changes it. Every change bumps the revision
// and emits a coarse signal that carries ids, never pointers. Functions return whether they
// changed something; a call that changes nothing emits nothing and keeps the revision.
//
// Addressing: POUs by PouId (fixed while the project is open), actions, transitions, data types
// and variables by name within their owner (IEC names are unique there), graphical elements by
// (BodyRef, localId). `index` arguments put a value back where an undo found it (-1: at the end).
class ProjectModel : public QObject
{
    Q_OBJECT

public:
    explicit ProjectModel(QObject *parent = nullptr);

    [[nodiscard]] const Project &project() const { return m_project; }
    [[nodiscard]] quint64 revision() const { return m_revision; }

    // Replaces the whole project; POUs without an id get fresh ones, given ids are kept.
    void reset(Project project);

    // ---- POUs
    // Adds the POU; an invalid or taken id gets a fresh one. Returns the id it was stored under.
    PouId addPou(Pou pou, int index = -1);
    bool removePou(PouId id);
    bool renamePou(PouId id, const QString &newName);
    // Copies a POU under a new name and id; the copy is an ordinary POU (not in vendor addData).
    PouId duplicatePou(PouId id, const QString &newName);
    [[nodiscard]] int pouIndex(PouId id) const;

    // ---- actions and transitions of a POU (Part::Action or Part::Transition)
    bool addPouPart(PouId pou, BodyRef::Part part, PouPart value, int index = -1);
    [[nodiscard]] const PouPart *findPouPart(PouId pou, BodyRef::Part part, const QString &name) const;
    bool removePouPart(PouId pou, BodyRef::Part part, const QString &name);
    bool renamePouPart(PouId pou, BodyRef::Part part, const QString &name, const QString &newName);
    [[nodiscard]] int pouPartIndex(PouId pou, BodyRef::Part part, const QString &name) const;

    // ---- data types
    bool addDataType(DataTypeDecl type, int index = -1);
    bool removeDataType(const QString &name);
    bool renameDataType(const QString &name, const QString &newName);
    bool changeDataType(const QString &name, const DataTypeDecl &type); // may rename too
    [[nodiscard]] int dataTypeIndex(const QString &name) const;

    // ---- configurations, resources, tasks and program instances
    // Replaces them as a whole (they are few and edited together: a rename of a program changes
    // the pouInstance typeNames of every task that runs it).
    bool setInstances(const Instances &instances);

    // ---- the project's own addData (where CODESYS keeps INTERFACEs). Emits projectAddDataChanged.
    bool setProjectAddData(const AddData &addData);

    // ---- declarations of a POU
    // Adds to the first var list of that kind (a new list when there is none) at `index`.
    bool addVariable(PouId pou, VarListKind kind, Variable variable, int index = -1);
    bool removeVariable(PouId pou, const QString &name);
    bool changeVariable(PouId pou, const QString &name, const Variable &variable); // may rename
    // Replaces the whole interface (the declaration editor's "apply").
    bool setInterface(PouId pou, const std::optional<Interface> &declarations);
    // Replaces the POU's addData (where CODESYS keeps methods and properties). Emits
    // pouAddDataChanged.
    bool setPouAddData(PouId pou, const AddData &addData);
    [[nodiscard]] const Variable *findVariable(PouId pou, const QString &name) const;

    // ---- bodies
    [[nodiscard]] const Body *body(const BodyRef &ref) const;
    bool setBodyText(const BodyRef &ref, const QString &text); // ST and IL bodies
    // Replaces the body's addData (another tool's diagram kept there, such as a CODESYS CFC, is
    // edited this way). Emits bodyAddDataChanged.
    bool setBodyAddData(const BodyRef &ref, const AddData &addData);
    // Inserts at `index` (-1: the end). A localId of 0 or one already used gets a fresh one.
    // Returns the localId the element got, 0 when the body does not exist or is textual.
    quint64 insertElement(const BodyRef &ref, Element element, int index = -1);
    // Removes the element and every connection that starts at it.
    bool removeElement(const BodyRef &ref, quint64 localId);
    bool moveElement(const BodyRef &ref, quint64 localId, Position position);
    // Replaces the element with the same localId (its properties, pins and connections).
    bool changeElement(const BodyRef &ref, const Element &element);
    // Brings a graphical body to exactly `target` (its elements in that order) in one step, in
    // time linear in the number of elements: what a structured edit of a whole body (an SFC
    // command, an LD network edit, a paste) produces. Emits at most one elementsRemoved, one
    // elementsInserted and one elementsChanged (same localId, different value), each with every
    // localId concerned, in that order. `target` is taken as it is (its wires too); its localIds
    // must be distinct (false and no change otherwise).
    bool replaceElements(const BodyRef &ref, std::vector<Element> target);
    // The same, giving the elements replaced back in `elements` (an undo command keeps them
    // without copying a large body). Unchanged when it returns false.
    bool swapElements(const BodyRef &ref, std::vector<Element> &elements);
    // Adds a connection to input point `pin` of `target` (pins in inputPoints() order).
    bool connect(const BodyRef &ref, quint64 target, int pin, const Connection &connection);
    // Removes the connection from `source` (and its formal parameter) on that pin.
    bool disconnect(const BodyRef &ref, quint64 target, int pin, quint64 source,
        const std::optional<QString> &formalParameter = {});
    [[nodiscard]] const Element *element(const BodyRef &ref, quint64 localId) const;
    [[nodiscard]] int elementIndex(const BodyRef &ref, quint64 localId) const;
    [[nodiscard]] quint64 nextLocalId(const BodyRef &ref) const;

Q_SIGNALS:
    void projectReset();
    void pouAdded(iec::model::PouId id);
    void pouRemoved(iec::model::PouId id);
    void pouRenamed(iec::model::PouId id);
    void pouPartsChanged(iec::model::PouId id); // actions or transitions added, removed, renamed
    void dataTypesChanged();
    void instancesChanged();
    void projectAddDataChanged();
    void variablesChanged(iec::model::PouId id);
    void pouAddDataChanged(iec::model::PouId id);
    void bodyTextChanged(const iec::model::BodyRef &ref);
    void bodyAddDataChanged(const iec::model::BodyRef &ref);
    void elementsInserted(const iec::model::BodyRef &ref, const QList<quint64> &localIds);
    void elementsRemoved(const iec::model::BodyRef &ref, const QList<quint64> &localIds);
    void elementsChanged(const iec::model::BodyRef &ref, const QList<quint64> &localIds);
    void connectionsChanged(const iec::model::BodyRef &ref, quint64 target);

private:
    Pou *findMutablePou(PouId id);
    Body *findMutableBody(const BodyRef &ref);
    Element *findMutableElement(const BodyRef &ref, quint64 localId);
    Interface *findMutableInterface(PouId id);
    PouId allocatePouId();
    void touch() { ++m_revision; }

    Project m_project;
    quint64 m_revision = 0;
    quint32 m_nextPouId = 1;
};

} // namespace iec::model
