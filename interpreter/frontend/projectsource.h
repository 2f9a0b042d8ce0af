#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/compiler/diagnostics.h"

#include "model/project.h"

#include <memory>

// The bridge from the project model to the compiler: builds the compiler's input (ast.h) from a
// model::Project.
//
// - Declarations (data types, POU interfaces, configurations) are printed as IEC text
//   (iecprinter.h) and parsed by the one parser, so the model and .st files can never disagree
//   on what a declaration means. Their diagnostics carry the line in that printed text, which is
//   what `iecstudio-cli convert FILE OUT.st` shows and the declaration editor will show.
// - ST and IL bodies are parsed with parseStBody / parseIlBody, so their diagnostics carry
//   (POU, line, column) counted in the body text as the editor shows it.
// - LD and FBD bodies are lowered to statements (graphical/graphicallowering.h), SFC charts to
//   statements and hidden variables (sfc/sfclowering.h); their diagnostics carry (POU, localId).
namespace iec::interp::frontend {

struct ProjectUnit {
    ast::CompilationUnit unit;
    bool parseErrors = false; // some text did not parse: the unit is not worth type checking
};

// Every diagnostic goes to `diagnostics`; lowering errors of graphical bodies count as parse errors.
ProjectUnit buildUnit(const model::Project &project, Diagnostics &diagnostics);

// Compiles a unit unless it had parse errors (like compileText: one typo gives one message, not
// a cascade of type errors). Returns nullptr when there are errors, all of them in `diagnostics`.
std::shared_ptr<const Module> compileUnit(
    const ProjectUnit &unit, Diagnostics &diagnostics, const CompileOptions &options = {});

// Sets the configurations aside so that CompileOptions::program runs alone as one cyclic task
// (`iecstudio-cli run --program P`): their global variables stay, as globals of the unit, so
// VAR_EXTERNAL declarations still find them; their tasks and program instances go.
void dropConfigurations(ast::CompilationUnit &unit);

// buildUnit + compileUnit.
std::shared_ptr<const Module> compileProject(
    const model::Project &project, Diagnostics &diagnostics, const CompileOptions &options = {});

} // namespace iec::interp::frontend
