// The compiler: IEC text -> parser -> front end (textual SFC lowered) -> bytecode. Compiling never
// crashes and every diagnostic has a message; what compiles runs three cycles with a small
// instruction budget, with the JIT and without it, with the same results.
#include "fuzzsupport.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/projectsource.h"

using namespace iec::interp;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    Diagnostics diagnostics;
    frontend::ProjectUnit unit;
    unit.unit = parseUnit(fuzzing::text(data, size), diagnostics);
    unit.parseErrors = diagnostics.hasErrors();
    const auto module = frontend::compileUnit(unit, diagnostics);
    for (const Diagnostic &d : diagnostics.all())
        FUZZ_CHECK(!d.message.isEmpty() && d.location.line >= 0 && d.location.column >= 0, d.toString());
    FUZZ_CHECK(!module == diagnostics.hasErrors(), QStringLiteral("a module with errors, or none without"));
    if (module)
        fuzzing::runBothWays(module);
    return 0;
}
