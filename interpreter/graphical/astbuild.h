#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"
#include "model/element.h"

#include <QString>

#include <optional>
#include <vector>

// Small builders for the compiler's AST, used by the LD/FBD lowering. Every node carries the
// location of the graphical element it came from, so the compiler's messages point at it.
namespace iec::interp::graphical {

// The location of a graphical element: no line, its localId (64-bit: CODESYS writes ids around
// 1e10; only ids above 2^63 stay unlocated).
SourceLocation elementLocation(quint64 localId);
// What the user calls the element's kind in messages ("selection divergence"), translated.
QString elementKindName(const model::Element &element);

ast::Expr nameExpr(const QString &name, SourceLocation at);
ast::Expr boolLiteral(bool value, SourceLocation at);
ast::Expr intLiteral(int value, SourceLocation at);
ast::Expr notExpr(ast::Expr operand);
ast::Expr binaryExpr(const QString &op, ast::Expr left, ast::Expr right);
ast::Expr memberExpr(ast::Expr base, const QString &member);
ast::Expr callExpr(const QString &name, std::vector<ast::CallArg> args, SourceLocation at);

ast::Stmt assignStmt(ast::Expr target, ast::Expr value);
ast::Stmt callStmt(ast::Expr call);
ast::Stmt ifStmt(ast::Expr condition, std::vector<ast::Stmt> body);
ast::Stmt simpleStmt(ast::StmtKind kind, SourceLocation at); // RETURN, EXIT, CONTINUE

bool isBoolLiteral(const ast::Expr &expr, bool value);
// A name, literal, address or member/bit of one: cheap to read twice, no calls.
bool isSimple(const ast::Expr &expr);

// Sets the location of `expr` and everything inside it.
void relocate(ast::Expr &expr, SourceLocation at);
// Sets the location of every statement, branch and expression in `statements`.
void relocate(std::vector<ast::Stmt> &statements, SourceLocation at);
// Sets SourceLocation::place of every statement and branch in `statements` (the debugger's place
// for them; diagnostics keep their locations).
void setPlace(std::vector<ast::Stmt> &statements, qint64 place);

// Parses the text of a variable, contact, coil or pin ("Motor", "Tank.Level", "%QX0.1", "a + 1",
// "T#5s") as one ST expression. Problems go to `diagnostics` under `owner`, located at `at`.
std::optional<ast::Expr> parseExpression(const QString &text, const QString &owner, SourceLocation at,
    Diagnostics &diagnostics);

} // namespace iec::interp::graphical
