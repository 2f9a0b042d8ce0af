#pragma once

#include "interpreter/vm/bytecode.h"

#include <QString>

#include <array>
#include <cstdint>
#include <optional>

// A breakpoint's condition: a Boolean expression over the program's variables ("i = 5",
// "Level > 2.5 AND NOT Alarm", "Timer1.ET >= T#1s"), read where the program is halted.
namespace iec::interp {

struct ConditionScope {
    const Module &module;
    const std::uint8_t *memory = nullptr;
    std::array<const std::uint8_t *, 3> images{}; // I, Q, M
    QString instance; // names are looked up in this instance first (Main, Main.Counter1), then globally
};

struct ConditionResult {
    std::optional<bool> value; // nullopt: it could not be evaluated, see error
    QString error;             // a sentence a student understands
};

ConditionResult evaluateCondition(const QString &text, const ConditionScope &scope);

// Whether the text is an expression at all (for the breakpoint dialog): empty when it is.
QString conditionSyntaxError(const QString &text);

} // namespace iec::interp
