#include "editors/ld/ldpowerflow.h"

namespace iec::editors::ld {

namespace {

bool evaluate(const RungNode &node, bool in, PowerFlow &flow, const std::function<std::optional<bool>(quint64, bool)> &pass)
{
    switch (node.kind) {
    case RungNode::Kind::Element: {
        flow.in[node.localId] = in;
        const std::optional<bool> out = pass(node.localId, in);
        if (!out)
            return false;
        flow.out[node.localId] = *out;
        return *out;
    }
    case RungNode::Kind::Series: {
        bool power = in;
        for (const RungNode &child : node.children)
            power = evaluate(child, power, flow, pass);
        return power;
    }
    case RungNode::Kind::Parallel: {
        bool any = false;
        for (const RungNode &branch : node.children)
            any = evaluate(branch, in, flow, pass) || any;
        return any;
    }
    }
    return false;
}

bool isTrue(const QString &literal)
{
    return literal.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0 || literal == QLatin1String("1");
}

} // namespace

PowerFlow evaluateRung(const RungNode &rung, const std::function<std::optional<bool>(quint64, bool)> &pass)
{
    PowerFlow flow;
    evaluate(rung, true, flow, pass);
    return flow;
}

bool contactCloses(const model::Contact &contact, const QString &name, const OnlineValues &values)
{
    const bool now = isTrue(values.now.value(name));
    switch (contact.edge) {
    case model::EdgeModifier::Rising:
        return values.consecutive && now && !isTrue(values.before.value(name));
    case model::EdgeModifier::Falling:
        return values.consecutive && !now && isTrue(values.before.value(name));
    case model::EdgeModifier::None:
        break;
    }
    return now != contact.negated;
}

} // namespace iec::editors::ld
