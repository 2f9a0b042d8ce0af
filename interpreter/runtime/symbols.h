#pragma once

#include "interpreter/vm/bytecode.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace iec::interp {

// Where a name points in the memory image or the process image.
struct VariableRef {
    const Type *type = nullptr;
    std::uint32_t offset = 0; // in the memory image, or the byte in the process image
    int bit = -1;             // a bit of the word at offset (w.3, %QX0.1)
    char imageArea = 0;       // 'I', 'Q', 'M' for %-addresses (process image); 0 for variables
};

// Resolves Main.Counter, Main.Timer1.ET, Main.Values[3], Main.Word.5, GlobalVar, %QX0.1. The first
// part is a global or a program instance, or the program's POU name when exactly one instance
// runs it (PROGRAM Fast WITH T : Counter: both Fast.n and Counter.n).
std::optional<VariableRef> resolveSymbol(const Module &module, const QString &name);

// The value at `ref` in IEC literal syntax: TRUE, 42, 1.5, T#1s500ms, 'text', [1, 2], (a := 1).
QString formatValue(const VariableRef &ref, const std::uint8_t *memory, const std::uint8_t *image);

// Writes a literal (TRUE, 42, -1.5, T#2s, 'abc', 16#FF, INT#5 ...) to an elementary or string
// variable. Returns an explanation when the text does not fit the type.
std::optional<QString> writeLiteral(const VariableRef &ref, const QString &text, std::uint8_t *memory, std::uint8_t *image);

} // namespace iec::interp
