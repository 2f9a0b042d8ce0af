#pragma once

#include <QString>

#include <cstdint>

namespace iec::interp {

// Values printed in IEC 61131-3 literal syntax, as `iecstudio-cli run --watch` and the watch
// pane show them: TRUE, 42, 1.5, T#1s500ms, 'text'.

QString formatBool(bool value);
QString formatInteger(std::int64_t value);
QString formatUnsigned(std::uint64_t value);
// Shortest text that reads back to the same double; always has a '.' or an exponent so it
// stays a REAL literal (1.0, not 1).
QString formatReal(double value);
// A REAL: the shortest text that reads back to the same float (0.1, not 0.10000000149011612).
QString formatReal(float value);
// TIME and LTIME: nanoseconds as T#1h2m3s4ms5us6ns with zero parts left out; T#0s for zero.
QString formatDuration(std::int64_t nanoseconds);
// DATE: D#2024-01-31; TIME_OF_DAY: TOD#12:30:00(.5); DATE_AND_TIME: DT#2024-01-31-12:30:00.
// Arguments are nanoseconds since 1970-01-01 (DATE, DT) or since midnight (TOD).
QString formatDate(std::int64_t nanoseconds);
QString formatTimeOfDay(std::int64_t nanoseconds);
QString formatDateAndTime(std::int64_t nanoseconds);
// STRING: single quotes, with $ escapes for quotes, $ and control characters.
QString formatString(const QString &value);
// WSTRING: the same in double quotes.
QString formatWString(const QString &value);

} // namespace iec::interp
