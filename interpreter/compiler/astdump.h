#pragma once

#include "interpreter/compiler/ast.h"

#include <QString>

namespace iec::interp::ast {

// Compact one-line text of AST parts, as S-expressions with IEC spelling. Tests compare against
// it, and it is handy when debugging the parser.
QString dump(const Expr &expr);
QString dump(const Stmt &stmt);
QString dump(const std::vector<Stmt> &statements);
QString dump(const IlInstruction &instruction);
QString dump(const TypeSpec &type);
QString dump(const Initializer &init);
QString dump(const VarSection &section);
QString dump(const SfcChart &chart);

// IEC text of an expression, with parentheses only where the operators' precedence needs them
// (a + b + c, a * (b + c)); parsing it gives the same expression again.
QString sourceText(const Expr &expr);

} // namespace iec::interp::ast
