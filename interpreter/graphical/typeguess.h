#pragma once

#include "interpreter/compiler/ast.h"

#include "model/elements_fbd.h"

#include <QHash>

#include <optional>
#include <vector>

// Types the LD/FBD lowering needs before the compiler's type checking: a block output read by
// several elements is kept in a hidden variable, which must be declared with a type.
namespace iec::interp::graphical {

struct Signal;

// The standard functions and operators (ADD, GT, SEL, INT_TO_REAL, ...): called with positional
// arguments, since vendors name their pins differently (IN1, In1, K, G).
bool isStandardFunction(const QString &name);

// The declared types of a POU's variables by upper-case name.
using DeclaredTypes = QHash<QString, ast::TypeSpec>;
DeclaredTypes declaredTypes(const ast::Pou &pou);

// The type of a declared variable, a typed literal (INT#5, T#1s, TRUE) or an address.
std::optional<ast::TypeSpec> literalOrDeclaredType(const ast::Expr &expr, const DeclaredTypes &declared);

// The result type of a function's standard rule (comparisons give BOOL, ADD its inputs' type, ...).
std::optional<ast::TypeSpec> byStandardRule(const model::Block &block, const std::vector<Signal> &inputs);

// The result type of a function block: from the vendor's addData, else by the rule of the
// standard function (comparisons give BOOL, ADD gives the type of its inputs, X_TO_Y gives Y).
std::optional<ast::TypeSpec> guessResultType(const model::Block &block, const std::vector<Signal> &inputs);

} // namespace iec::interp::graphical
