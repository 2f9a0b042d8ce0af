#include "interpreter/compiler/ast.h"

namespace iec::interp::ast {

namespace {

// Everything of an expression but its operands and arguments. A field added to Expr must be
// copied here: the size check below fails until it is.
void copyNode(const Expr &from, Expr &to)
{
    to.kind = from.kind;
    to.location = from.location;
    to.text = from.text;
    to.literal = from.literal;
}
struct ExprFieldsAsCopied {
    ExprKind kind;
    SourceLocation location;
    QString text;
    TokenKind literal;
    std::vector<Expr> operands;
    std::vector<CallArg> callArgs;
};
static_assert(sizeof(Expr) == sizeof(ExprFieldsAsCopied), "copyNode (ast.cpp) must copy every field of Expr");
struct CallArgFieldsAsCopied {
    QString name;
    bool isOutput;
    bool negatedOutput;
    Expr value;
};
static_assert(sizeof(CallArg) == sizeof(CallArgFieldsAsCopied), "Expr's copy (ast.cpp) must copy every field of CallArg");

// Moves the operands and argument values of `e` to the end of `into`; `e` keeps none.
void detachChildren(Expr &e, std::vector<Expr> &into)
{
    for (Expr &operand : e.operands)
        into.push_back(std::move(operand));
    e.operands.clear();
    for (CallArg &arg : e.callArgs)
        into.push_back(std::move(arg.value));
    e.callArgs.clear();
}

} // namespace

Expr::Expr(const Expr &other)
{
    std::vector<std::pair<const Expr *, Expr *>> pending {{&other, this}};
    while (!pending.empty()) {
        const auto [from, to] = pending.back();
        pending.pop_back();
        copyNode(*from, *to);
        // Sized once, so the addresses taken below stay valid.
        to->operands.resize(from->operands.size());
        for (size_t i = 0; i < from->operands.size(); ++i)
            pending.emplace_back(&from->operands[i], &to->operands[i]);
        to->callArgs.resize(from->callArgs.size());
        for (size_t i = 0; i < from->callArgs.size(); ++i) {
            const CallArg &arg = from->callArgs[i];
            CallArg &copy = to->callArgs[i];
            copy.name = arg.name;
            copy.isOutput = arg.isOutput;
            copy.negatedOutput = arg.negatedOutput;
            pending.emplace_back(&arg.value, &copy.value);
        }
    }
}

Expr &Expr::operator=(const Expr &other)
{
    if (this != &other)
        *this = Expr(other);
    return *this;
}

Expr::~Expr()
{
    if (operands.empty() && callArgs.empty())
        return;
    std::vector<Expr> pending;
    detachChildren(*this, pending);
    while (!pending.empty()) {
        Expr last = std::move(pending.back());
        pending.pop_back();
        detachChildren(last, pending); // `last` is left without children and ends at once
    }
}

} // namespace iec::interp::ast
