// Instruction List as the IDE holds it: the text of an IL body in a project (the POU's
// declarations fixed, below), compiled through the front end and run like fuzz_compile.
#include "fuzzsupport.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"

using namespace iec;

namespace {

const model::Project &base()
{
    static const model::Project project = [] {
        interp::frontend::TextReadResult read = interp::frontend::readIecText(QStringLiteral(
            "TYPE Pt : STRUCT x : INT; y : REAL; END_STRUCT; END_TYPE\n"
            "FUNCTION_BLOCK Counter\nVAR_INPUT up : BOOL; END_VAR\nVAR_OUTPUT n : INT; END_VAR\nIF up THEN n := n + 1; END_IF;\nEND_FUNCTION_BLOCK\n"
            "PROGRAM Main\nVAR a, b, c : BOOL; i, j, k : INT; d : DINT; r : REAL; w : WORD; s : STRING[16]; t : TON; "
            "ct : CTU; tr : R_TRIG; cn : Counter; arr : ARRAY[0..3] OF INT; p : Pt; tm : TIME; END_VAR\n"
            "LD a\nST b\nEND_PROGRAM\n"),
            QStringLiteral("il"));
        return read.project;
    }();
    return project;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString text = fuzzing::text(data, size);
    interp::Diagnostics parsing;
    interp::parseIlBody(text, QStringLiteral("Main"), parsing);
    model::Project project = base();
    model::Pou &main = project.types.pous.back();
    main.bodies.front() = model::Body::withLanguage(model::BodyLanguage::IL);
    main.bodies.front().setText(text);
    interp::Diagnostics diagnostics;
    const auto module = interp::frontend::compileProject(project, diagnostics);
    FUZZ_CHECK(!module == diagnostics.hasErrors(), QStringLiteral("a module with errors, or none without"));
    if (module)
        fuzzing::runBothWays(module);
    return 0;
}
