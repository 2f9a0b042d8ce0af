#pragma once

// Builds SFC charts as model values, element by element, with chosen localIds, for tests of the
// chart's structure diagnostics:
//   chart({step(1, "Init", {}, true), transition(2, 1), step(3, "S1", 2), transition(4, 3), jump(5, 4, "Init")})
// The second argument of an element is the localId of the element before it.

#include "model/pou.h"

#include <optional>
#include <vector>

namespace iec::testing::sfcchart {

inline model::ConnectionPointIn from(quint64 source)
{
    model::ConnectionPointIn in;
    in.connections.push_back({source, {}, {}, {}, {}, {}});
    return in;
}

inline model::Element step(quint64 id, const QString &name, std::optional<quint64> before = {}, bool initial = false)
{
    model::Step s;
    s.localId = id;
    s.name = name;
    s.initialStep = initial;
    s.connectionPointIn = before ? from(*before) : model::ConnectionPointIn {};
    s.connectionPointOut = model::ConnectionPointOut {};
    return s;
}

inline model::Element transition(quint64 id, std::optional<quint64> before, const QString &condition = QStringLiteral("TRUE"))
{
    model::Transition t;
    t.localId = id;
    if (before)
        t.connectionPointIn = from(*before);
    model::ConnectionPointIn wire;
    wire.expression = condition;
    t.condition = model::Condition {false, wire};
    return t;
}

inline model::Element jump(quint64 id, quint64 before, const QString &target)
{
    model::JumpStep j;
    j.localId = id;
    j.targetName = target;
    j.connectionPointIn = from(before);
    return j;
}

template<typename Kind> inline model::Element split(quint64 id, quint64 before)
{
    Kind k;
    k.localId = id;
    k.connectionPointIn = from(before);
    return k;
}

template<typename Kind> inline model::Element join(quint64 id, std::vector<quint64> before)
{
    Kind k;
    k.localId = id;
    for (quint64 b : before)
        k.connectionPointIns.push_back(from(b));
    return k;
}

inline model::Pou chart(std::vector<model::Element> elements)
{
    model::Pou pou;
    pou.name = QStringLiteral("Main");
    model::Body body = model::Body::withLanguage(model::BodyLanguage::SFC);
    *body.elements() = std::move(elements);
    pou.bodies.push_back(std::move(body));
    return pou;
}


// An action block below step `stepId`; each action is {qualifier, action name, duration}.
struct BlockAction {
    QString qualifier;
    QString name;
    QString duration;
};
inline model::Element actionBlock(quint64 id, quint64 stepId, const std::vector<BlockAction> &actions)
{
    model::ActionBlock block;
    block.localId = id;
    block.connectionPointIn = from(stepId);
    for (const BlockAction &a : actions) {
        model::ActionBlockAction action;
        action.qualifier = a.qualifier;
        action.reference = model::Reference {a.name};
        if (!a.duration.isEmpty())
            action.duration = a.duration;
        block.actions.push_back(action);
    }
    return block;
}

// Init(1) -T(2)-> S1(3) -T(4)-> jump(5) to Init: a correct chart to break in each row.
inline std::vector<model::Element> loop()
{
    return {step(1, QStringLiteral("Init"), {}, true), transition(2, 1), step(3, QStringLiteral("S1"), 2), transition(4, 3),
        jump(5, 4, QStringLiteral("Init"))};
}

} // namespace iec::testing::sfcchart
