#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"

#include <QStringView>

namespace iec::interp {

// The IEC 61131-3 textual format: TYPE, PROGRAM, FUNCTION_BLOCK, FUNCTION, VAR_GLOBAL and
// CONFIGURATION, with ST, IL or textual SFC bodies. Errors go to `diagnostics`; parsing always
// goes on, so the unit holds everything that could be understood.
ast::CompilationUnit parseUnit(QStringView text, Diagnostics &diagnostics);

// Bodies given apart from their declarations (as the project model stores them). Locations are
// counted from `firstLine` so they match the editor the text came from.
std::vector<ast::Stmt> parseStBody(QStringView text, const QString &pou, Diagnostics &diagnostics, int firstLine = 1);
std::vector<ast::IlInstruction> parseIlBody(QStringView text, const QString &pou, Diagnostics &diagnostics,
                                            int firstLine = 1);
// How tightly a binary operator binds (its canonical spelling, as in ast::Expr::text: "OR" 1 ...
// "**" 8); 0 for none.
int binaryPrecedence(QStringView op);

// Declarations only: the VAR ... END_VAR sections of a POU's interface.
std::vector<ast::VarSection> parseDeclarations(QStringView text, const QString &pou, Diagnostics &diagnostics,
                                               int firstLine = 1);

} // namespace iec::interp
