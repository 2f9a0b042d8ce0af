// What the online mode, the watch window and `iecstudio-cli run --set/--watch` take from the
// user: a variable name and a literal (the first line is the name, the rest the literal), and
// durations such as T#1s or PT0.01S. Writing never crashes; a value that was written reads back
// as a literal that writes the same value again.
#include "fuzzsupport.h"

#include "interpreter/frontend/duration.h"
#include "interpreter/runtime/runtime.h"

using namespace iec::interp;

namespace {

Runtime &runtime()
{
    static Runtime instance = [] {
        Diagnostics diagnostics;
        const auto module = compileText(QStringLiteral(
            "TYPE Color : (Red, Green, Blue); Pt : STRUCT x : INT; y : LREAL; END_STRUCT; Pct : INT(0..100); END_TYPE\n"
            "PROGRAM Main\nVAR b : BOOL; si : SINT; i : INT; di : DINT; li : LINT; us : USINT; ui : UINT; ud : UDINT; "
            "ul : ULINT; bt : BYTE; w : WORD; dw : DWORD; lw : LWORD; r : REAL; lr : LREAL; t : TIME; lt : LTIME; "
            "dat : DATE; tday : TOD; dtm : DT; s : STRING[12]; ws : WSTRING[12]; c : CHAR; wc : WCHAR; col : Color; "
            "p : Pt; pct : Pct; a : ARRAY[1..3, 0..1] OF INT; ton1 : TON; END_VAR\n"
            "i := i;\nEND_PROGRAM\n"),
            diagnostics);
        if (!module)
            fuzzing::fail(__FILE__, __LINE__, "module", diagnostics.all().empty() ? QString() : diagnostics.all().front().toString());
        return Runtime(module);
    }();
    return instance;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString text = fuzzing::text(data, size);
    frontend::parseDuration(text);
    const qsizetype newline = text.indexOf(QLatin1Char('\n'));
    const QString name = newline < 0 ? text : text.left(newline);
    const QString literal = newline < 0 ? QString() : text.mid(newline + 1);
    Runtime &r = runtime();
    const std::optional<VariableRef> ref = r.find(name);
    if (!ref)
        return 0;
    if (r.write(name, literal))
        return 0; // refused, with a reason
    const QString read = r.read(*ref);
    const auto refused = r.write(name, read);
    FUZZ_CHECK(!refused, name + QStringLiteral(" := ") + literal + QStringLiteral(" reads as ") + read + QStringLiteral(", refused: ") + refused.value_or(QString()));
    FUZZ_CHECK(r.read(*ref) == read, name + QStringLiteral(": ") + read + QStringLiteral(" then ") + r.read(*ref));
    return 0;
}
