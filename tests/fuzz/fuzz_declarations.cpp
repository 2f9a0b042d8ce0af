// The declaration editor's text view: text -> interface -> text. Reading never crashes; text
// that reads without problems prints as text that reads back to the same interface.
#include "fuzzsupport.h"

#include "editors/declarations/declarationtext.h"

using namespace iec;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const editors::DeclarationTextResult first = editors::readDeclarationText(fuzzing::text(data, size));
    FUZZ_CHECK(first.declarations.has_value() == first.problems.empty(), QStringLiteral("declarations and problems at once"));
    for (const editors::DeclarationProblem &problem : first.problems)
        FUZZ_CHECK(problem.line >= 1 && problem.column >= 1 && !problem.message.isEmpty(), problem.message);
    if (!first.declarations)
        return 0;
    const QString printed = editors::declarationText(*first.declarations);
    const editors::DeclarationTextResult second = editors::readDeclarationText(printed);
    FUZZ_CHECK(second.declarations.has_value(), printed + QStringLiteral("\n--- ") + (second.problems.empty() ? QString() : second.problems.front().message));
    FUZZ_CHECK(*second.declarations == *first.declarations, printed);
    return 0;
}
