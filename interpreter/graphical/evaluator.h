#pragma once

#include "interpreter/graphical/astbuild.h"
#include "interpreter/graphical/graphicallowering.h"
#include "interpreter/graphical/network.h"
#include "interpreter/graphical/typeguess.h"

#include <QSet>

#include <map>
#include <optional>
#include <vector>

// Turns the elements of a network into statements and expressions: each element is evaluated
// once, after the elements it reads (pull order), and its outputs are kept as expressions.
// Outputs read more than once become hidden variables, so every reader sees one value.
namespace iec::interp::graphical {

struct Signal {
    ast::Expr expr;
    std::optional<ast::TypeSpec> type; // when it can be told before type checking
    int size = 1;                      // a rough node count, to keep expressions shallow
};

class Evaluator
{
public:
    // `ladder`: several wires into one input are ORed (LD); otherwise that is an error (FBD).
    Evaluator(const Network &network, LoweringContext &context, bool ladder);

    // Where the statements go from now on; nullptr: none may be needed (pure conditions).
    void setSink(std::vector<ast::Stmt> *sink) { m_sink = sink; }
    // CFC: a function box's result is stored in a variable of its own, so the box is a statement
    // (named by its localId, a place for the debugger) rather than part of the one that reads it.
    void setElementPlaces(bool on) { m_elementPlaces = on; }
    // Label name (upper case) -> segment number, and the variable a jump sets.
    void setJumpTargets(std::map<QString, int> labels, QString jumpVariable);

    // Evaluates a root (coil, output, block, jump, return) and whatever it reads.
    void run(std::size_t node);
    // The value wired into `point`; `where` names it for diagnostics.
    std::optional<Signal> valueOf(const model::ConnectionPointIn &point, quint64 localId, const QString &where);

    // A hidden variable (name starts with "__"), unique in the POU.
    QString hiddenVariable(const QString &base, const ast::TypeSpec &type);
    // Declares the hidden variables in the POU.
    void declareHidden();

private:
    void ensure(std::size_t node);
    void evaluate(std::size_t node);
    void evaluateContact(std::size_t n, const model::Contact &contact);
    void evaluateCoil(std::size_t n, const model::Coil &coil);
    void evaluateOutVariable(std::size_t n, const model::OutVariable &out);
    void evaluateInOutVariable(std::size_t n, const model::InOutVariable &inOut);
    void evaluateBlock(std::size_t n, const model::Block &block);
    void evaluateExecuteBox(std::size_t n, const model::Block &block, const Signal &enable);
    void evaluateJump(std::size_t n, const model::Jump &jump);
    void evaluateReturn(std::size_t n, const model::Return &ret);

    std::optional<Signal> input(std::size_t n, const std::optional<model::ConnectionPointIn> &point, const QString &missing);
    std::optional<Signal> read(std::size_t consumer, const model::Connection &connection);
    std::optional<ast::Expr> variable(std::size_t n, const QString &text);
    Signal variableSignal(ast::Expr expr) const;
    std::optional<Signal> trigger(std::size_t n, const Signal &value, bool rising);
    Signal materialize(std::size_t n, const QString &pin, Signal signal);
    void setOutput(std::size_t n, const QString &key, Signal signal);
    // The variable that keeps an output of a stored box (Network::isStoredBox) between scans:
    // named when first read, declared when the box runs and its type is known.
    QString storedOutput(std::size_t n, const QString &key);
    QString uniqueHiddenName(const QString &base);
    void push(ast::Stmt statement);
    void store(const ast::Expr &target, const Signal &value, bool negated, model::EdgeModifier edge,
        model::StorageModifier storage, std::size_t n);
    // what: a QT_TRANSLATE_NOOP text in the context iec::interp::Compiler, translated only on failure.
    bool canEmit(std::size_t n, const char *what);
    void fail(std::size_t n, const QString &message, const QString &hint = {});

    std::optional<ast::TypeSpec> declaredType(const ast::Expr &expr) const;
    std::optional<ast::TypeSpec> resultType(const model::Block &block, const std::vector<Signal> &inputs,
        std::size_t n, const QString &key) const;

    SourceLocation at(std::size_t n) const { return elementLocation(m_network.node(n).localId); }

    enum class State { New, Busy, Done, Failed };
    const Network &m_network;
    LoweringContext &m_context;
    bool m_ladder;
    std::vector<ast::Stmt> *m_sink = nullptr;
    bool m_elementPlaces = false;
    std::vector<State> m_state;
    std::map<std::pair<std::size_t, QString>, Signal> m_outputs;
    std::map<QString, int> m_labels;
    QString m_jumpVariable;
    std::vector<ast::VarDecl> m_hidden;
    DeclaredTypes m_declared;
    // The output and in-out variables each output is wired to (for the type of a result).
    std::map<std::pair<std::size_t, QString>, std::vector<std::size_t>> m_writtenTo;
    QSet<QString> m_taken; // upper-case names of the POU's variables
    std::map<std::pair<std::size_t, QString>, QString> m_stored; // outputs of stored boxes
};

ast::TypeSpec namedType(const QString &name);

} // namespace iec::interp::graphical
