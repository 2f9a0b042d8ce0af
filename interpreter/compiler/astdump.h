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

} // namespace iec::interp::ast
