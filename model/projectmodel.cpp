#include "model/projectmodel.h"

#include <QSet>

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace iec::model {

namespace {

// IEC identifiers are case-insensitive, but a rename that only changes case is a change.
bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

template<class T> void insertAt(std::vector<T> &values, T value, int index)
{
    const auto position = index < 0 || std::size_t(index) > values.size() ? values.end() : values.begin() + index;
    values.insert(position, std::move(value));
}

template<class T> int indexByName(const std::vector<T> &values, const QString &name)
{
    const auto it = std::ranges::find_if(values, [&](const T &value) { return sameName(value.name, name); });
    return it == values.end() ? -1 : int(it - values.begin());
}

template<class T> T *findByName(std::vector<T> &values, const QString &name)
{
    const int index = indexByName(values, name);
    return index < 0 ? nullptr : &values[std::size_t(index)];
}

// A POU's actions and transitions have the same shape; these give uniform access.
template<class F> auto withParts(Pou &pou, BodyRef::Part part, F &&f)
{
    return part == BodyRef::Part::Action ? f(pou.actions) : f(pou.transitions);
}

template<class F> auto withParts(const Pou &pou, BodyRef::Part part, F &&f)
{
    return part == BodyRef::Part::Action ? f(pou.actions) : f(pou.transitions);
}

int elementIndexIn(const std::vector<Element> &elements, quint64 localId)
{
    const auto it = std::ranges::find_if(elements, [&](const Element &e) { return header(e).localId == localId; });
    return it == elements.end() ? -1 : int(it - elements.begin());
}

bool isValidPart(BodyRef::Part part)
{
    return part == BodyRef::Part::Action || part == BodyRef::Part::Transition;
}

} // namespace

ProjectModel::ProjectModel(QObject *parent)
    : QObject(parent)
{ }

void ProjectModel::reset(Project project)
{
    m_project = std::move(project);
    m_nextPouId = 1;
    for (const Pou &pou : m_project.types.pous)
        m_nextPouId = std::max(m_nextPouId, pou.id.value + 1);
    for (Pou &pou : m_project.types.pous) {
        if (!pou.id.isValid())
            pou.id = allocatePouId();
    }
    touch();
    Q_EMIT projectReset();
}

// ---- POUs ---------------------------------------------------------------------------------

PouId ProjectModel::addPou(Pou pou, int index)
{
    if (!pou.id.isValid() || m_project.findPou(pou.id))
        pou.id = allocatePouId();
    else
        m_nextPouId = std::max(m_nextPouId, pou.id.value + 1);
    const PouId id = pou.id;
    insertAt(m_project.types.pous, std::move(pou), index);
    touch();
    Q_EMIT pouAdded(id);
    return id;
}

bool ProjectModel::removePou(PouId id)
{
    const auto removed = std::erase_if(m_project.types.pous, [id](const Pou &pou) { return pou.id == id; });
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

PouId ProjectModel::duplicatePou(PouId id, const QString &newName)
{
    const Pou *original = m_project.findPou(id);
    if (!original)
        return {};
    Pou copy = *original;
    copy.id = {};
    copy.name = newName;
    copy.globalId.reset(); // xsd:ID values must stay unique in the file
    copy.addDataSlot = 0;
    return addPou(std::move(copy), pouIndex(id) + 1);
}

int ProjectModel::pouIndex(PouId id) const
{
    const auto it = std::ranges::find(m_project.types.pous, id, &Pou::id);
    return it == m_project.types.pous.end() ? -1 : int(it - m_project.types.pous.begin());
}

// ---- actions and transitions --------------------------------------------------------------

bool ProjectModel::addPouPart(PouId id, BodyRef::Part part, PouPart value, int index)
{
    Pou *pou = findMutablePou(id);
    if (!pou || !isValidPart(part) || pouPartIndex(id, part, value.name) >= 0)
        return false;
    withParts(*pou, part, [&](auto &parts) { insertAt(parts, std::move(value), index); });
    touch();
    Q_EMIT pouPartsChanged(id);
    return true;
}

bool ProjectModel::removePouPart(PouId id, BodyRef::Part part, const QString &name)
{
    Pou *pou = findMutablePou(id);
    const int index = pouPartIndex(id, part, name);
    if (!pou || index < 0)
        return false;
    withParts(*pou, part, [&](auto &parts) { parts.erase(parts.begin() + index); });
    touch();
    Q_EMIT pouPartsChanged(id);
    return true;
}

bool ProjectModel::renamePouPart(PouId id, BodyRef::Part part, const QString &name, const QString &newName)
{
    Pou *pou = findMutablePou(id);
    const int index = pouPartIndex(id, part, name);
    if (!pou || index < 0 || name == newName)
        return false;
    withParts(*pou, part, [&](auto &parts) { parts[std::size_t(index)].name = newName; });
    touch();
    Q_EMIT pouPartsChanged(id);
    return true;
}

const PouPart *ProjectModel::findPouPart(PouId id, BodyRef::Part part, const QString &name) const
{
    const Pou *pou = m_project.findPou(id);
    const int index = pouPartIndex(id, part, name);
    if (!pou || index < 0)
        return nullptr;
    return withParts(*pou, part, [&](const auto &parts) { return &parts[std::size_t(index)]; });
}

int ProjectModel::pouPartIndex(PouId id, BodyRef::Part part, const QString &name) const
{
    const Pou *pou = m_project.findPou(id);
    if (!pou || !isValidPart(part))
        return -1;
    return withParts(*pou, part, [&](const auto &parts) { return indexByName(parts, name); });
}

// ---- data types ---------------------------------------------------------------------------

bool ProjectModel::addDataType(DataTypeDecl type, int index)
{
    if (dataTypeIndex(type.name) >= 0)
        return false;
    insertAt(m_project.types.dataTypes, std::move(type), index);
    touch();
    Q_EMIT dataTypesChanged();
    return true;
}

bool ProjectModel::removeDataType(const QString &name)
{
    const int index = dataTypeIndex(name);
    if (index < 0)
        return false;
    m_project.types.dataTypes.erase(m_project.types.dataTypes.begin() + index);
    touch();
    Q_EMIT dataTypesChanged();
    return true;
}

bool ProjectModel::renameDataType(const QString &name, const QString &newName)
{
    const int index = dataTypeIndex(name);
    if (index < 0)
        return false;
    DataTypeDecl type = m_project.types.dataTypes[std::size_t(index)];
    type.name = newName;
    return changeDataType(name, type);
}

bool ProjectModel::changeDataType(const QString &name, const DataTypeDecl &type)
{
    DataTypeDecl *existing = findByName(m_project.types.dataTypes, name);
    if (!existing || *existing == type)
        return false;
    *existing = type;
    touch();
    Q_EMIT dataTypesChanged();
    return true;
}

int ProjectModel::dataTypeIndex(const QString &name) const
{
    return indexByName(m_project.types.dataTypes, name);
}

// ---- instances ----------------------------------------------------------------------------

bool ProjectModel::setInstances(const Instances &instances)
{
    if (m_project.instances == instances)
        return false;
    m_project.instances = instances;
    touch();
    Q_EMIT instancesChanged();
    return true;
}

bool ProjectModel::setProjectAddData(const AddData &addData)
{
    if (m_project.addData == addData)
        return false;
    m_project.addData = addData;
    touch();
    Q_EMIT projectAddDataChanged();
    return true;
}

// ---- declarations -------------------------------------------------------------------------

bool ProjectModel::addVariable(PouId id, VarListKind kind, Variable variable, int index)
{
    Pou *pou = findMutablePou(id);
    if (!pou || findVariable(id, variable.name))
        return false;
    if (!pou->pouInterface)
        pou->pouInterface.emplace();
    std::vector<VarList> &lists = pou->pouInterface->varLists;
    auto list = std::ranges::find(lists, kind, &VarList::kind);
    if (list == lists.end())
        list = lists.insert(lists.end(), VarList {.kind = kind});
    insertAt(list->variables, std::move(variable), index);
    touch();
    Q_EMIT variablesChanged(id);
    return true;
}

bool ProjectModel::removeVariable(PouId id, const QString &name)
{
    Interface *declarations = findMutableInterface(id);
    if (!declarations)
        return false;
    for (VarList &list : declarations->varLists) {
        const int index = indexByName(list.variables, name);
        if (index >= 0) {
            list.variables.erase(list.variables.begin() + index);
            touch();
            Q_EMIT variablesChanged(id);
            return true;
        }
    }
    return false;
}

bool ProjectModel::changeVariable(PouId id, const QString &name, const Variable &variable)
{
    Variable *existing = const_cast<Variable *>(findVariable(id, name));
    if (!existing || *existing == variable)
        return false;
    *existing = variable;
    touch();
    Q_EMIT variablesChanged(id);
    return true;
}

bool ProjectModel::setInterface(PouId id, const std::optional<Interface> &declarations)
{
    Pou *pou = findMutablePou(id);
    if (!pou || pou->pouInterface == declarations)
        return false;
    pou->pouInterface = declarations;
    touch();
    Q_EMIT variablesChanged(id);
    return true;
}

const Variable *ProjectModel::findVariable(PouId id, const QString &name) const
{
    const Pou *pou = m_project.findPou(id);
    if (!pou || !pou->pouInterface)
        return nullptr;
    for (const VarList &list : pou->pouInterface->varLists) {
        const int index = indexByName(list.variables, name);
        if (index >= 0)
            return &list.variables[std::size_t(index)];
    }
    return nullptr;
}

// ---- bodies -------------------------------------------------------------------------------

const Body *ProjectModel::body(const BodyRef &ref) const
{
    return const_cast<ProjectModel *>(this)->findMutableBody(ref);
}

bool ProjectModel::setBodyText(const BodyRef &ref, const QString &text)
{
    Body *body = findMutableBody(ref);
    if (!body || body->isGraphical() || body->text() == text)
        return false;
    body->setText(text);
    touch();
    Q_EMIT bodyTextChanged(ref);
    return true;
}

bool ProjectModel::setPouAddData(PouId id, const AddData &addData)
{
    Pou *pou = findMutablePou(id);
    if (!pou || pou->addData == addData)
        return false;
    pou->addData = addData;
    touch();
    Q_EMIT pouAddDataChanged(id);
    return true;
}

bool ProjectModel::setBodyAddData(const BodyRef &ref, const AddData &addData)
{
    Body *body = findMutableBody(ref);
    if (!body || body->addData == addData)
        return false;
    body->addData = addData;
    touch();
    Q_EMIT bodyAddDataChanged(ref);
    return true;
}

quint64 ProjectModel::insertElement(const BodyRef &ref, Element element, int index)
{
    Body *body = findMutableBody(ref);
    if (!body || !body->isGraphical())
        return 0;
    std::vector<Element> &elements = *body->elements();
    ElementHeader &head = header(element);
    if (head.localId == 0 || elementIndexIn(elements, head.localId) >= 0)
        head.localId = nextLocalId(ref);
    const quint64 localId = head.localId;
    insertAt(elements, std::move(element), index);
    touch();
    Q_EMIT elementsInserted(ref, {localId});
    return localId;
}

bool ProjectModel::removeElement(const BodyRef &ref, quint64 localId)
{
    Body *body = findMutableBody(ref);
    const int index = body && body->isGraphical() ? elementIndexIn(*body->elements(), localId) : -1;
    if (index < 0)
        return false;
    std::vector<Element> &elements = *body->elements();
    elements.erase(elements.begin() + index);
    // No wire may start at an element that is gone.
    QList<quint64> rewired;
    for (Element &element : elements) {
        bool changed = false;
        for (ConnectionPointIn *point : inputPoints(element))
            changed
                |= std::erase_if(point->connections, [&](const Connection &c) { return c.refLocalId == localId; }) > 0;
        if (changed)
            rewired.push_back(header(element).localId);
    }
    touch();
    Q_EMIT elementsRemoved(ref, {localId});
    for (quint64 target : rewired)
        Q_EMIT connectionsChanged(ref, target);
    return true;
}

bool ProjectModel::moveElement(const BodyRef &ref, quint64 localId, Position position)
{
    Element *element = findMutableElement(ref, localId);
    if (!element || header(*element).position == position)
        return false;
    header(*element).position = position;
    touch();
    Q_EMIT elementsChanged(ref, {localId});
    return true;
}

bool ProjectModel::changeElement(const BodyRef &ref, const Element &element)
{
    Element *existing = findMutableElement(ref, header(element).localId);
    if (!existing || *existing == element)
        return false;
    *existing = element;
    touch();
    Q_EMIT elementsChanged(ref, {header(element).localId});
    return true;
}

bool ProjectModel::replaceElements(const BodyRef &ref, std::vector<Element> target)
{
    return swapElements(ref, target);
}

namespace {

struct ElementDiff {
    QList<quint64> inserted;
    QList<quint64> removed;
    QList<quint64> changed;
};

bool hasDuplicateIds(const std::vector<Element> &elements)
{
    std::vector<quint64> ids;
    ids.reserve(elements.size());
    for (const Element &element : elements)
        ids.push_back(header(element).localId);
    std::ranges::sort(ids);
    return std::ranges::adjacent_find(ids) != ids.end();
}

// What replacing `before` with `after` inserts, removes and changes, by localId; nullopt when
// `after` holds two elements with one localId. An edit of a large body (an LD body of 10,000
// elements) touches a few elements somewhere in the middle: the common head and tail (the same
// ids in the same places) are compared in place, and only the window between them is hashed.
std::optional<ElementDiff> diffElements(const std::vector<Element> &before, const std::vector<Element> &after)
{
    if (hasDuplicateIds(after))
        return std::nullopt;
    const auto idAt = [](const std::vector<Element> &list, std::size_t i) { return header(list[i]).localId; };
    std::size_t head = 0;
    while (head < before.size() && head < after.size() && idAt(before, head) == idAt(after, head))
        ++head;
    std::size_t tail = 0;
    while (tail < before.size() - head && tail < after.size() - head
        && idAt(before, before.size() - 1 - tail) == idAt(after, after.size() - 1 - tail))
        ++tail;
    const std::size_t beforeEnd = before.size() - tail;
    const std::size_t afterEnd = after.size() - tail;

    ElementDiff diff;
    for (std::size_t i = 0; i < head; ++i)
        if (!(before[i] == after[i]))
            diff.changed.append(idAt(after, i));
    QHash<quint64, const Element *> window;
    window.reserve(qsizetype(beforeEnd - head));
    for (std::size_t i = head; i < beforeEnd; ++i)
        window.insert(idAt(before, i), &before[i]);
    QSet<quint64> kept;
    for (std::size_t i = head; i < afterEnd; ++i) {
        const quint64 localId = idAt(after, i);
        kept.insert(localId);
        const auto it = window.constFind(localId);
        if (it == window.cend())
            diff.inserted.append(localId);
        else if (!(*it.value() == after[i]))
            diff.changed.append(localId);
    }
    for (std::size_t i = 0; i < tail; ++i)
        if (!(before[beforeEnd + i] == after[afterEnd + i]))
            diff.changed.append(idAt(after, afterEnd + i));
    for (std::size_t i = head; i < beforeEnd; ++i)
        if (!kept.contains(idAt(before, i)))
            diff.removed.append(idAt(before, i));
    // Survivors that changed places count as changed (the order is the file's, and FBD's
    // evaluation order where no executionOrderId says otherwise). Head and tail kept theirs.
    std::vector<quint64> survivorsBefore;
    std::vector<quint64> survivorsAfter;
    for (std::size_t i = head; i < beforeEnd; ++i)
        if (kept.contains(idAt(before, i)))
            survivorsBefore.push_back(idAt(before, i));
    for (std::size_t i = head; i < afterEnd; ++i)
        if (window.contains(idAt(after, i)))
            survivorsAfter.push_back(idAt(after, i));
    if (survivorsBefore != survivorsAfter) {
        const QSet<quint64> alreadyChanged(diff.changed.begin(), diff.changed.end());
        for (std::size_t i = 0; i < survivorsAfter.size(); ++i) {
            if (survivorsAfter[i] != survivorsBefore[i] && !alreadyChanged.contains(survivorsAfter[i]))
                diff.changed.append(survivorsAfter[i]);
        }
    }
    return diff;
}

} // namespace

bool ProjectModel::swapElements(const BodyRef &ref, std::vector<Element> &target)
{
    Body *body = findMutableBody(ref);
    if (!body || !body->isGraphical())
        return false;
    std::vector<Element> &elements = *body->elements();
    const std::optional<ElementDiff> diff = diffElements(elements, target);
    if (!diff || (diff->inserted.isEmpty() && diff->removed.isEmpty() && diff->changed.isEmpty()))
        return false;
    std::swap(elements, target);
    touch();
    if (!diff->removed.isEmpty())
        Q_EMIT elementsRemoved(ref, diff->removed);
    if (!diff->inserted.isEmpty())
        Q_EMIT elementsInserted(ref, diff->inserted);
    if (!diff->changed.isEmpty())
        Q_EMIT elementsChanged(ref, diff->changed);
    return true;
}

bool ProjectModel::connect(const BodyRef &ref, quint64 target, int pin, const Connection &connection)
{
    Element *element = findMutableElement(ref, target);
    if (!element || !findMutableElement(ref, connection.refLocalId))
        return false;
    const std::vector<ConnectionPointIn *> pins = inputPoints(*element);
    if (pin < 0 || std::size_t(pin) >= pins.size())
        return false;
    pins[std::size_t(pin)]->connections.push_back(connection);
    touch();
    Q_EMIT connectionsChanged(ref, target);
    return true;
}

bool ProjectModel::disconnect(
    const BodyRef &ref, quint64 target, int pin, quint64 source, const std::optional<QString> &formalParameter)
{
    Element *element = findMutableElement(ref, target);
    if (!element)
        return false;
    const std::vector<ConnectionPointIn *> pins = inputPoints(*element);
    if (pin < 0 || std::size_t(pin) >= pins.size())
        return false;
    std::vector<Connection> &connections = pins[std::size_t(pin)]->connections;
    const auto it = std::ranges::find_if(connections,
        [&](const Connection &c) { return c.refLocalId == source && c.formalParameter == formalParameter; });
    if (it == connections.end())
        return false;
    connections.erase(it);
    touch();
    Q_EMIT connectionsChanged(ref, target);
    return true;
}

const Element *ProjectModel::element(const BodyRef &ref, quint64 localId) const
{
    return const_cast<ProjectModel *>(this)->findMutableElement(ref, localId);
}

int ProjectModel::elementIndex(const BodyRef &ref, quint64 localId) const
{
    const Body *b = body(ref);
    return b && b->isGraphical() ? elementIndexIn(*b->elements(), localId) : -1;
}

quint64 ProjectModel::nextLocalId(const BodyRef &ref) const
{
    const Body *b = body(ref);
    quint64 highest = 0;
    if (b && b->isGraphical()) {
        for (const Element &element : *b->elements())
            highest = std::max(highest, header(element).localId);
    }
    return highest + 1;
}

// ---- lookups ------------------------------------------------------------------------------

Pou *ProjectModel::findMutablePou(PouId id)
{
    return const_cast<Pou *>(m_project.findPou(id));
}

Body *ProjectModel::findMutableBody(const BodyRef &ref)
{
    Pou *pou = findMutablePou(ref.pou);
    if (!pou)
        return nullptr;
    if (ref.part == BodyRef::Part::Pou)
        return pou->bodies.empty() ? nullptr : &pou->bodies.front();
    return withParts(*pou, ref.part, [&](auto &parts) -> Body * {
        auto *part = findByName(parts, ref.name);
        return part ? &part->body : nullptr;
    });
}

Element *ProjectModel::findMutableElement(const BodyRef &ref, quint64 localId)
{
    Body *body = findMutableBody(ref);
    const int index = body && body->isGraphical() ? elementIndexIn(*body->elements(), localId) : -1;
    return index < 0 ? nullptr : &(*body->elements())[std::size_t(index)];
}

Interface *ProjectModel::findMutableInterface(PouId id)
{
    Pou *pou = findMutablePou(id);
    return pou && pou->pouInterface ? &*pou->pouInterface : nullptr;
}

PouId ProjectModel::allocatePouId()
{
    return PouId {m_nextPouId++};
}

} // namespace iec::model
