#pragma once

#include <QStringView>

#include <cstdint>
#include <optional>

namespace iec::interp::frontend {

// A duration as users and files write it, in nanoseconds: the IEC literal (T#10ms, TIME#1s500ms),
// its body alone (10ms, 1.5s) or XML Schema / ISO 8601 (PT0.01S, P1DT2H), as PLCopen task
// intervals and `iecstudio-cli run --cycle-time` accept them. Nullopt when it is none of these.
std::optional<std::int64_t> parseDuration(QStringView text);

} // namespace iec::interp::frontend
