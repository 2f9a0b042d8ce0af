#pragma once

#include "editors/ld/ldnetwork.h"

#include <QHash>
#include <QString>

#include <functional>
#include <unordered_map>

// Power flow of a rung for the online view, as CODESYS shows it: from the left rail through
// contacts that are closed, through coils and boxes, in series and parallel. Pure: the values come
// from the caller (the running program's snapshot).
namespace iec::editors::ld {

struct PowerFlow {
    std::unordered_map<quint64, bool> in;  // power at an element's rung input
    std::unordered_map<quint64, bool> out; // power it passes on (absent: it passes none)
};

// `pass(id, powerIn)` says what an element passes on; nullopt for outputs that end the rung.
PowerFlow evaluateRung(const RungNode &rung, const std::function<std::optional<bool>(quint64, bool)> &pass);

// The values the overlay reads, by the name the runtime knows ("Main.Start"), as IEC literals.
struct OnlineValues {
    QHash<QString, QString> now;
    QHash<QString, QString> before; // the previous snapshot's, for edges
    bool consecutive = false;       // `before` is from the cycle right before (single cycle)
};

// Whether a contact conducts with these values: its variable TRUE (FALSE when negated); a P/N
// contact only in the cycle its variable rose/fell, which the view can tell only when stepping
// one cycle at a time.
bool contactCloses(const model::Contact &contact, const QString &name, const OnlineValues &values);

} // namespace iec::editors::ld
