#pragma once

#include <QMetaType>
#include <QString>
#include <QtGlobal>

#include <compare>
#include <functional>

namespace iec::model {

// Identifies a POU while the project is open. It survives renames, so undo commands and views
// can refer to a POU by id (DESIGN.md: ids, not pointers, across layers).
struct PouId {
    quint32 value = 0;

    [[nodiscard]] constexpr bool isValid() const { return value != 0; }
    constexpr auto operator<=>(const PouId &) const = default;
};

// Names one body: the POU's own body, or the body of one of its actions or transitions.
struct BodyRef {
    enum class Part { Pou, Action, Transition };

    PouId pou;
    Part part = Part::Pou;
    QString name; // the action or transition; empty for Part::Pou

    bool operator==(const BodyRef &) const = default;
};

} // namespace iec::model

Q_DECLARE_METATYPE(iec::model::PouId)
Q_DECLARE_METATYPE(iec::model::BodyRef)

template<> struct std::hash<iec::model::PouId> {
    std::size_t operator()(iec::model::PouId id) const noexcept { return std::hash<quint32> {}(id.value); }
};
