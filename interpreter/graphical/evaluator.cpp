#include "interpreter/graphical/evaluator.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/graphical/astbuild.h"
#include "interpreter/graphical/typeguess.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace iec::interp::graphical {

namespace {

constexpr int kMaxExpressionSize = 48; // larger power-flow expressions go through a variable

bool isEnable(const QString &pin)
{
    return pin.trimmed().compare(QLatin1String("EN"), Qt::CaseInsensitive) == 0;
}

bool isEnableOut(const QString &pin)
{
    return pin.trimmed().compare(QLatin1String("ENO"), Qt::CaseInsensitive) == 0;
}

bool connected(const std::optional<model::ConnectionPointIn> &point)
{
    return point && (!point->connections.empty() || (point->expression && !point->expression->trimmed().isEmpty()));
}

Signal combine(const QString &op, Signal left, Signal right)
{
    const bool isAnd = op == QLatin1String("AND");
    // TRUE is the left rail: x AND TRUE is x; x OR TRUE is TRUE.
    if (isBoolLiteral(left.expr, isAnd))
        return right;
    if (isBoolLiteral(right.expr, isAnd))
        return left;
    if (isBoolLiteral(left.expr, !isAnd))
        return left;
    if (isBoolLiteral(right.expr, !isAnd))
        return right;
    Signal out;
    out.size = left.size + right.size + 1;
    out.type = namedType(QStringLiteral("BOOL"));
    out.expr = binaryExpr(op, std::move(left.expr), std::move(right.expr));
    return out;
}

// The ST text of a CODESYS EXECUTE box, kept in its addData.
std::optional<QString> executeCode(const model::Block &block)
{
    for (const model::AddDataEntry &entry : block.addData) {
        if (!entry.name.endsWith(QLatin1String("/stcode"), Qt::CaseInsensitive))
            continue;
        static const QRegularExpression code(QStringLiteral("<STCode[^>]*>(.*)</STCode>"),
            QRegularExpression::DotMatchesEverythingOption);
        const auto match = code.match(entry.content);
        if (!match.hasMatch())
            return QString();
        QString text = match.captured(1);
        text.replace(QLatin1String("&lt;"), QLatin1String("<"));
        text.replace(QLatin1String("&gt;"), QLatin1String(">"));
        text.replace(QLatin1String("&quot;"), QLatin1String("\""));
        text.replace(QLatin1String("&apos;"), QLatin1String("'"));
        text.replace(QLatin1String("&amp;"), QLatin1String("&"));
        return text;
    }
    return std::nullopt;
}

} // namespace

ast::TypeSpec namedType(const QString &name)
{
    ast::TypeSpec type;
    type.kind = ast::TypeSpec::Kind::Named;
    type.name = name;
    return type;
}

Evaluator::Evaluator(const Network &network, LoweringContext &context, bool ladder)
    : m_network(network)
    , m_context(context)
    , m_ladder(ladder)
    , m_state(network.nodes().size(), State::New)
{
    for (const ast::VarSection &section : context.pou.sections) {
        for (const ast::VarDecl &var : section.vars)
            m_taken.insert(var.name.toUpper());
    }
    m_taken.insert(context.pou.name.toUpper());
    m_declared = declaredTypes(context.pou);
    for (std::size_t i = 0; i < network.nodes().size(); ++i) {
        const Node &node = network.node(i);
        if (node.kind != NodeKind::OutVariable && node.kind != NodeKind::InOutVariable)
            continue;
        for (const model::ConnectionPointIn *point : model::inputPoints(*node.element)) {
            for (const model::Connection &c : point->connections) {
                if (const auto source = network.indexOf(c.refLocalId))
                    m_writtenTo[{*source, network.outputKey(*source, c.formalParameter)}].push_back(i);
            }
        }
    }
}

void Evaluator::setJumpTargets(std::map<QString, int> labels, QString jumpVariable)
{
    m_labels = std::move(labels);
    m_jumpVariable = std::move(jumpVariable);
}

QString Evaluator::uniqueHiddenName(const QString &base)
{
    QString name = QStringLiteral("__") + base;
    for (int n = 2; m_taken.contains(name.toUpper()); ++n)
        name = QStringLiteral("__%1_%2").arg(base).arg(n);
    m_taken.insert(name.toUpper());
    return name;
}

QString Evaluator::storedOutput(std::size_t n, const QString &key)
{
    auto [it, fresh] = m_stored.try_emplace({n, key});
    if (fresh)
        it->second = uniqueHiddenName(QStringLiteral("loop%1%2").arg(m_network.node(n).localId).arg(key.isEmpty() ? QString() : QLatin1Char('_') + key));
    return it->second;
}

QString Evaluator::hiddenVariable(const QString &base, const ast::TypeSpec &type)
{
    const QString name = uniqueHiddenName(base);
    ast::VarDecl var;
    var.name = name;
    var.type = type;
    m_hidden.push_back(std::move(var));
    return name;
}

void Evaluator::declareHidden()
{
    if (m_hidden.empty())
        return;
    ast::VarSection section;
    section.kind = ast::VarKind::Local;
    section.vars = std::move(m_hidden);
    m_hidden.clear();
    m_context.pou.sections.push_back(std::move(section));
}

void Evaluator::fail(std::size_t n, const QString &message, const QString &hint)
{
    m_context.diagnostics.error(m_context.owner, at(n), message, hint);
    m_state[n] = State::Failed;
}

bool Evaluator::canEmit(std::size_t n, const char *what)
{
    if (m_sink)
        return true;
    fail(n, QCoreApplication::translate("iec::interp::Compiler", "%1 cannot be used in a condition wired into a chart.")
                .arg(QCoreApplication::translate("iec::interp::Compiler", what)),
        QCoreApplication::translate("iec::interp::Compiler", "write the condition as a named transition instead"));
    return false;
}

void Evaluator::push(ast::Stmt statement)
{
    if (m_sink)
        m_sink->push_back(std::move(statement));
}

void Evaluator::run(std::size_t node)
{
    ensure(node);
}

// Evaluates `node` after everything it reads, without recursion (rungs can be long).
void Evaluator::ensure(std::size_t node)
{
    if (m_state[node] != State::New)
        return;
    std::vector<std::pair<std::size_t, std::size_t>> stack {{node, 0}};
    m_state[node] = State::Busy;
    while (!stack.empty()) {
        auto &[current, next] = stack.back();
        const std::vector<std::size_t> &sources = m_network.node(current).sources;
        if (next < sources.size()) {
            const std::size_t source = sources[next++];
            if (m_state[source] == State::New && !m_network.isFeedback(current, source)) {
                m_state[source] = State::Busy;
                stack.emplace_back(source, 0);
            }
            continue;
        }
        const std::size_t done = current;
        stack.pop_back();
        evaluate(done);
        if (m_state[done] == State::Busy)
            m_state[done] = State::Done;
    }
}

std::optional<Signal> Evaluator::read(std::size_t consumer, const model::Connection &connection)
{
    const auto source = m_network.indexOf(connection.refLocalId);
    if (!source) {
        fail(consumer, QCoreApplication::translate("iec::interp::Compiler", "A wire comes from element %1, which is not in this diagram.").arg(connection.refLocalId));
        return std::nullopt;
    }
    const Node &from = m_network.node(*source);
    if (m_network.isFeedback(consumer, *source) && m_network.isInstanceBlock(*source)) {
        // The loop is broken here: the instance still holds the output of the previous scan.
        const auto &block = std::get<model::Block>(*from.element);
        const QString pin = m_network.outputKey(*source, connection.formalParameter);
        Signal signal = variableSignal(memberExpr(nameExpr(block.instanceName->trimmed(), at(*source)), pin));
        for (const model::BlockVariable &output : block.outputVariables) {
            if (output.negated && output.formalParameter.trimmed().compare(pin, Qt::CaseInsensitive) == 0)
                signal.expr = notExpr(std::move(signal.expr));
        }
        return signal;
    }
    if (m_network.isFeedback(consumer, *source) && m_network.isStoredBox(*source)) {
        // The loop is broken here: the box runs later in the order; its output from the scan
        // before is kept in a variable.
        const QString key = m_network.outputKey(*source, connection.formalParameter);
        return variableSignal(nameExpr(storedOutput(*source, key), at(*source)));
    }
    if (m_network.isFeedback(consumer, *source)) {
        // The loop is broken here: the variable still holds its value from before.
        const auto &inOut = std::get<model::InOutVariable>(*from.element);
        auto expr = variable(*source, inOut.expression);
        if (!expr)
            return std::nullopt;
        Signal signal = variableSignal(std::move(*expr));
        if (inOut.negatedOut)
            signal.expr = notExpr(std::move(signal.expr));
        return signal;
    }
    if (from.kind == NodeKind::Foreign || from.kind == NodeKind::Ignored || from.kind == NodeKind::Unsupported
        || from.kind == NodeKind::RightRail) {
        fail(consumer, QCoreApplication::translate("iec::interp::Compiler", "A wire comes from an element that gives no value (%1).")
                           .arg(elementKindName(*from.element)));
        return std::nullopt;
    }
    ensure(*source);
    if (m_state[*source] == State::Failed) {
        m_state[consumer] = State::Failed; // already reported at the source
        return std::nullopt;
    }
    const QString key = m_network.outputKey(*source, connection.formalParameter);
    const auto found = m_outputs.find({*source, key});
    if (found == m_outputs.end()) {
        if (from.kind == NodeKind::Block) {
            fail(consumer, QCoreApplication::translate("iec::interp::Compiler", "A wire comes from the output '%1', which %2 does not have.")
                               .arg(connection.formalParameter.value_or(QString()), std::get<model::Block>(*from.element).typeName));
        } else {
            fail(consumer, QCoreApplication::translate("iec::interp::Compiler", "A wire comes from a %1, which gives no value.")
                               .arg(elementKindName(*from.element)));
        }
        return std::nullopt;
    }
    return found->second;
}

std::optional<Signal> Evaluator::input(std::size_t n, const std::optional<model::ConnectionPointIn> &point,
    const QString &missing)
{
    if (!connected(point)) {
        fail(n, missing, QCoreApplication::translate("iec::interp::Compiler", "draw a wire to it"));
        return std::nullopt;
    }
    if (point->connections.empty()) {
        auto expr = variable(n, *point->expression);
        if (!expr)
            return std::nullopt;
        return variableSignal(std::move(*expr));
    }
    std::optional<Signal> result;
    bool powerOnly = true;
    for (const model::Connection &connection : point->connections) {
        const auto source = m_network.indexOf(connection.refLocalId);
        const NodeKind kind = source ? m_network.node(*source).kind : NodeKind::Ignored;
        powerOnly = powerOnly && (kind == NodeKind::LeftRail || kind == NodeKind::Contact || kind == NodeKind::Coil);
    }
    if (point->connections.size() > 1 && !m_ladder && !powerOnly) {
        fail(n, QCoreApplication::translate("iec::interp::Compiler", "%1 wires end at one input; an input takes exactly one.").arg(point->connections.size()),
            QCoreApplication::translate("iec::interp::Compiler", "combine them with an OR block"));
        return std::nullopt;
    }
    for (const model::Connection &connection : point->connections) {
        auto value = read(n, connection);
        if (!value)
            return std::nullopt;
        result = result ? combine(QStringLiteral("OR"), std::move(*result), std::move(*value)) : std::move(*value);
    }
    return result;
}

std::optional<Signal> Evaluator::valueOf(const model::ConnectionPointIn &point, quint64 localId, const QString &where)
{
    const auto node = m_network.indexOf(localId);
    if (!node) {
        m_context.diagnostics.error(m_context.owner, elementLocation(localId),
            QCoreApplication::translate("iec::interp::Compiler", "%1 is not connected.").arg(where));
        return std::nullopt;
    }
    const bool ladder = m_ladder;
    m_ladder = true; // contacts in parallel in front of a transition are ORed
    auto value = input(*node, point, QCoreApplication::translate("iec::interp::Compiler", "%1 is not connected.").arg(where));
    m_ladder = ladder;
    return value;
}

std::optional<ast::Expr> Evaluator::variable(std::size_t n, const QString &text)
{
    auto expr = parseExpression(text, m_context.owner, at(n), m_context.diagnostics);
    if (!expr)
        m_state[n] = State::Failed;
    return expr;
}

Signal Evaluator::variableSignal(ast::Expr expr) const
{
    Signal signal;
    signal.type = literalOrDeclaredType(expr, m_declared);
    signal.expr = std::move(expr);
    return signal;
}

std::optional<Signal> Evaluator::trigger(std::size_t n, const Signal &value, bool rising)
{
    if (!canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "An edge detection")))
        return std::nullopt;
    const quint64 id = m_network.node(n).localId;
    const QString name = hiddenVariable(QStringLiteral("%1trig%2").arg(rising ? QLatin1Char('r') : QLatin1Char('f')).arg(id),
        namedType(rising ? QStringLiteral("R_TRIG") : QStringLiteral("F_TRIG")));
    ast::CallArg clk;
    clk.name = QStringLiteral("CLK");
    clk.value = value.expr;
    push(callStmt(callExpr(name, {clk}, at(n))));
    Signal out;
    out.expr = memberExpr(nameExpr(name, at(n)), QStringLiteral("Q"));
    out.type = namedType(QStringLiteral("BOOL"));
    return out;
}

Signal Evaluator::materialize(std::size_t n, const QString &pin, Signal signal)
{
    if (!m_sink || !signal.type || isSimple(signal.expr))
        return signal;
    const QString base = QStringLiteral("v%1%2").arg(m_network.node(n).localId).arg(pin.isEmpty() ? QString() : QLatin1Char('_') + pin);
    const QString name = hiddenVariable(base, *signal.type);
    push(assignStmt(nameExpr(name, at(n)), std::move(signal.expr)));
    signal.expr = nameExpr(name, at(n));
    signal.size = 1;
    return signal;
}

void Evaluator::setOutput(std::size_t n, const QString &key, Signal signal)
{
    if (m_network.isStoredBox(n) && m_sink) {
        // A loop reads this output from the scan before: it lives in a variable of its own,
        // written when the box runs; everyone reads that variable.
        if (!signal.type) {
            fail(n, QCoreApplication::translate("iec::interp::Compiler", "The type of the value this loop carries cannot be told."),
                QCoreApplication::translate("iec::interp::Compiler", "wire the loop through a variable of the type you mean"));
            return;
        }
        const QString name = storedOutput(n, key);
        ast::VarDecl var;
        var.name = name;
        var.type = *signal.type;
        m_hidden.push_back(std::move(var));
        push(assignStmt(nameExpr(name, at(n)), std::move(signal.expr)));
        signal.expr = nameExpr(name, at(n));
        signal.size = 1;
        m_outputs[{n, key}] = std::move(signal);
        return;
    }
    const bool shared = m_network.readers(n, key) > 1;
    if (shared || signal.size > kMaxExpressionSize)
        signal = materialize(n, key, std::move(signal));
    m_outputs[{n, key}] = std::move(signal);
}

// target := value, with the modifiers of a coil or an output variable.
void Evaluator::store(const ast::Expr &target, const Signal &value, bool negated, model::EdgeModifier edge,
    model::StorageModifier storage, std::size_t n)
{
    Signal v = value;
    if (edge != model::EdgeModifier::None) {
        auto edged = trigger(n, v, edge == model::EdgeModifier::Rising);
        if (!edged)
            return;
        v = std::move(*edged);
    }
    if (storage != model::StorageModifier::None) {
        const bool set = storage == model::StorageModifier::Set;
        ast::Stmt write = assignStmt(target, boolLiteral(set, at(n)));
        if (isBoolLiteral(v.expr, true))
            push(std::move(write));
        else if (!isBoolLiteral(v.expr, false))
            push(ifStmt(std::move(v.expr), {std::move(write)}));
        return;
    }
    push(assignStmt(target, negated ? notExpr(std::move(v.expr)) : std::move(v.expr)));
}

void Evaluator::evaluate(std::size_t n)
{
    if (m_state[n] == State::Failed)
        return;
    const Node &node = m_network.node(n);
    const model::Element &element = *node.element;
    switch (node.kind) {
    case NodeKind::LeftRail: {
        Signal power;
        power.expr = boolLiteral(true, at(n));
        power.type = namedType(QStringLiteral("BOOL"));
        m_outputs[{n, QString()}] = power;
        break;
    }
    case NodeKind::Contact:
        evaluateContact(n, std::get<model::Contact>(element));
        break;
    case NodeKind::Coil:
        evaluateCoil(n, std::get<model::Coil>(element));
        break;
    case NodeKind::InVariable: {
        const auto &in = std::get<model::InVariable>(element);
        auto expr = variable(n, in.expression);
        if (!expr)
            return;
        Signal value = variableSignal(std::move(*expr));
        if (in.edge != model::EdgeModifier::None) {
            auto edged = trigger(n, value, in.edge == model::EdgeModifier::Rising);
            if (!edged)
                return;
            value = std::move(*edged);
        }
        if (in.negated)
            value.expr = notExpr(std::move(value.expr));
        setOutput(n, QString(), std::move(value));
        break;
    }
    case NodeKind::OutVariable:
        evaluateOutVariable(n, std::get<model::OutVariable>(element));
        break;
    case NodeKind::InOutVariable:
        evaluateInOutVariable(n, std::get<model::InOutVariable>(element));
        break;
    case NodeKind::Block:
        evaluateBlock(n, std::get<model::Block>(element));
        break;
    case NodeKind::Connector: {
        const auto &connector = std::get<model::Connector>(element);
        auto value = input(n, connector.connectionPointIn,
            QCoreApplication::translate("iec::interp::Compiler", "Nothing is wired to the connector '%1'.").arg(connector.name));
        if (value)
            setOutput(n, QString(), std::move(*value));
        break;
    }
    case NodeKind::Continuation: {
        const auto connector = m_network.connectorOf(n);
        const auto found = connector ? m_outputs.find({*connector, QString()}) : m_outputs.end();
        if (found == m_outputs.end()) {
            m_state[n] = State::Failed; // reported at the connector or by the network
            return;
        }
        m_outputs[{n, QString()}] = found->second;
        break;
    }
    case NodeKind::Jump:
        evaluateJump(n, std::get<model::Jump>(element));
        break;
    case NodeKind::Return:
        evaluateReturn(n, std::get<model::Return>(element));
        break;
    case NodeKind::Label:
    case NodeKind::RightRail:
    case NodeKind::Ignored:
    case NodeKind::Foreign:
    case NodeKind::Unsupported:
        break;
    }
}

void Evaluator::evaluateContact(std::size_t n, const model::Contact &contact)
{
    auto power = input(n, contact.connectionPointIn,
        QCoreApplication::translate("iec::interp::Compiler", "The contact '%1' has no wire on its left.").arg(contact.variable));
    if (!power)
        return;
    auto expr = variable(n, contact.variable);
    if (!expr)
        return;
    Signal value = variableSignal(std::move(*expr));
    if (contact.edge != model::EdgeModifier::None) {
        auto edged = trigger(n, value, contact.edge == model::EdgeModifier::Rising);
        if (!edged)
            return;
        value = std::move(*edged);
    } else if (contact.negated) {
        value.expr = notExpr(std::move(value.expr));
    }
    setOutput(n, QString(), combine(QStringLiteral("AND"), std::move(*power), std::move(value)));
}

void Evaluator::evaluateCoil(std::size_t n, const model::Coil &coil)
{
    auto power = input(n, coil.connectionPointIn,
        QCoreApplication::translate("iec::interp::Compiler", "The coil '%1' has no wire on its left.").arg(coil.variable));
    if (!power)
        return;
    auto target = variable(n, coil.variable);
    if (!target)
        return;
    if (m_network.readers(n, QString()) > 0)
        *power = materialize(n, QStringLiteral("p"), std::move(*power));
    if (!canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "A coil")))
        return;
    store(*target, *power, coil.negated, coil.edge, coil.storage, n);
    m_outputs[{n, QString()}] = std::move(*power);
}

void Evaluator::evaluateOutVariable(std::size_t n, const model::OutVariable &out)
{
    auto value = input(n, out.connectionPointIn, QCoreApplication::translate("iec::interp::Compiler", "Nothing is wired to the output '%1'.").arg(out.expression));
    if (!value)
        return;
    auto target = variable(n, out.expression);
    if (!target || !canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "An output variable")))
        return;
    store(*target, *value, out.negated, out.edge, out.storage, n);
}

void Evaluator::evaluateInOutVariable(std::size_t n, const model::InOutVariable &inOut)
{
    auto target = variable(n, inOut.expression);
    if (!target)
        return;
    if (connected(inOut.connectionPointIn)) {
        auto value = input(n, inOut.connectionPointIn, QString());
        if (!value || !canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "A variable that is written")))
            return;
        store(*target, *value, inOut.negatedIn, inOut.edgeIn, inOut.storageIn, n);
    }
    Signal out = variableSignal(*target);
    if (inOut.edgeOut != model::EdgeModifier::None) {
        auto edged = trigger(n, out, inOut.edgeOut == model::EdgeModifier::Rising);
        if (!edged)
            return;
        out = std::move(*edged);
    }
    if (inOut.negatedOut)
        out.expr = notExpr(std::move(out.expr));
    setOutput(n, QString(), std::move(out));
}

void Evaluator::evaluateBlock(std::size_t n, const model::Block &block)
{
    const QString type = block.typeName.trimmed();
    const bool isInstance = block.instanceName && !block.instanceName->trimmed().isEmpty();
    const bool standard = !isInstance && isStandardFunction(type);
    Signal enable;
    enable.expr = boolLiteral(true, at(n));
    enable.type = namedType(QStringLiteral("BOOL"));
    std::vector<ast::CallArg> args;
    std::vector<Signal> inputs;
    for (const model::BlockVariable &pin : block.inputVariables) {
        if (isEnable(pin.formalParameter)) {
            if (connected(pin.connectionPointIn)) {
                auto value = input(n, pin.connectionPointIn, QString());
                if (!value)
                    return;
                enable = std::move(*value);
            }
            continue;
        }
        if (!connected(pin.connectionPointIn)) {
            if (isInstance)
                continue; // an open input of a function block keeps its value
            fail(n, QCoreApplication::translate("iec::interp::Compiler", "The input %1 of %2 is not connected.").arg(pin.formalParameter, type),
                QCoreApplication::translate("iec::interp::Compiler", "draw a wire to it or write a constant"));
            return;
        }
        auto value = input(n, pin.connectionPointIn, QString());
        if (!value)
            return;
        if (pin.edge != model::EdgeModifier::None) {
            auto edged = trigger(n, *value, pin.edge == model::EdgeModifier::Rising);
            if (!edged)
                return;
            value = std::move(*edged);
        }
        if (pin.negated)
            value->expr = notExpr(std::move(value->expr));
        ast::CallArg arg;
        if (!standard)
            arg.name = pin.formalParameter.trimmed();
        arg.value = value->expr;
        args.push_back(std::move(arg));
        inputs.push_back(std::move(*value));
    }
    for (const model::BlockVariable &pin : block.inOutVariables) {
        if (!connected(pin.connectionPointIn))
            continue;
        auto value = input(n, pin.connectionPointIn, QString());
        if (!value)
            return;
        ast::CallArg arg;
        arg.name = pin.formalParameter.trimmed();
        arg.value = value->expr;
        args.push_back(std::move(arg));
        m_outputs[{n, pin.formalParameter.trimmed().toUpper()}] = *value;
    }
    if (type.compare(QLatin1String("EXECUTE"), Qt::CaseInsensitive) == 0 && !isInstance) {
        evaluateExecuteBox(n, block, enable);
        return;
    }
    const bool gated = !isBoolLiteral(enable.expr, true);
    if (gated && (isInstance || !block.outputVariables.empty()))
        enable = materialize(n, QStringLiteral("EN"), std::move(enable)); // read by the call and by ENO
    for (const model::BlockVariable &pin : block.outputVariables) {
        if (isEnableOut(pin.formalParameter))
            m_outputs[{n, QStringLiteral("ENO")}] = enable;
    }
    if (isInstance) {
        if (!canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "A function block")))
            return;
        const QString instance = block.instanceName->trimmed();
        ast::Stmt call = callStmt(callExpr(instance, std::move(args), at(n)));
        push(gated ? ifStmt(enable.expr, {std::move(call)}) : std::move(call));
        for (const model::BlockVariable &pin : block.outputVariables) {
            if (isEnableOut(pin.formalParameter))
                continue;
            Signal out;
            out.expr = memberExpr(nameExpr(instance, at(n)), pin.formalParameter.trimmed());
            if (pin.negated)
                out.expr = notExpr(std::move(out.expr));
            m_outputs[{n, pin.formalParameter.trimmed().toUpper()}] = std::move(out);
        }
        return;
    }
    // A function: its first output is the result.
    QString resultKey;
    const model::BlockVariable *resultPin = nullptr;
    for (const model::BlockVariable &pin : block.outputVariables) {
        if (isEnableOut(pin.formalParameter))
            continue;
        if (!resultPin) {
            resultPin = &pin;
            resultKey = pin.formalParameter.trimmed().toUpper();
        } else if (m_network.readers(n, pin.formalParameter.trimmed().toUpper()) > 0) {
            fail(n, QCoreApplication::translate("iec::interp::Compiler", "Only the result of the function %1 can be wired; its output %2 cannot yet.")
                        .arg(type, pin.formalParameter),
                QCoreApplication::translate("iec::interp::Compiler", "call %1 from ST to use its other outputs").arg(type));
            return;
        }
    }
    Signal result;
    result.expr = callExpr(type, std::move(args), at(n));
    result.type = resultType(block, inputs, n, resultKey);
    for (const Signal &in : inputs)
        result.size += in.size;
    if (m_network.readers(n, resultKey) == 0 && !standard) {
        // Nobody reads the result: call the function for what it does (VAR_IN_OUT, globals).
        if (!canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "A function call")))
            return;
        ast::Stmt call = callStmt(std::move(result.expr));
        push(gated ? ifStmt(enable.expr, {std::move(call)}) : std::move(call));
        return;
    }
    if (gated) {
        if (!canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "A function with EN")))
            return;
        if (!result.type) {
            fail(n, QCoreApplication::translate("iec::interp::Compiler", "The result type of %1 cannot be told here, so it cannot run under EN.").arg(type),
                QCoreApplication::translate("iec::interp::Compiler", "wire its output to a variable, or leave EN open"));
            return;
        }
        const QString name = hiddenVariable(QStringLiteral("v%1_%2").arg(m_network.node(n).localId).arg(resultKey), *result.type);
        push(ifStmt(enable.expr, {assignStmt(nameExpr(name, at(n)), std::move(result.expr))}));
        result.expr = nameExpr(name, at(n));
        result.size = 1;
    }
    if (m_elementPlaces)
        result = materialize(n, resultKey, std::move(result));
    if (resultPin && resultPin->negated)
        result.expr = notExpr(std::move(result.expr));
    if (resultPin)
        setOutput(n, resultKey, std::move(result));
}

void Evaluator::evaluateExecuteBox(std::size_t n, const model::Block &block, const Signal &enable)
{
    const auto code = executeCode(block);
    if (!code) {
        fail(n, QCoreApplication::translate("iec::interp::Compiler", "This EXECUTE box holds no ST code."));
        return;
    }
    Diagnostics local;
    std::vector<ast::Stmt> statements = parseStBody(*code, m_context.owner, local);
    if (local.hasErrors()) {
        fail(n, QCoreApplication::translate("iec::interp::Compiler", "The ST code of this EXECUTE box does not parse: %1").arg(local.all().front().message));
        return;
    }
    if (!canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "An EXECUTE box")))
        return;
    relocate(statements, at(n));
    if (isBoolLiteral(enable.expr, true)) {
        for (ast::Stmt &s : statements)
            push(std::move(s));
    } else {
        push(ifStmt(enable.expr, std::move(statements)));
    }
    m_outputs[{n, QStringLiteral("ENO")}] = enable;
}

void Evaluator::evaluateJump(std::size_t n, const model::Jump &jump)
{
    auto condition = input(n, jump.connectionPointIn,
        QCoreApplication::translate("iec::interp::Compiler", "The jump to '%1' has no condition wired to it.").arg(jump.label));
    if (!condition)
        return;
    const auto target = m_labels.find(jump.label.trimmed().toUpper());
    if (target == m_labels.end()) {
        fail(n, QCoreApplication::translate("iec::interp::Compiler", "There is no label '%1' to jump to.").arg(jump.label),
            QCoreApplication::translate("iec::interp::Compiler", "add a label with that name, or correct the jump"));
        return;
    }
    if (!canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "A jump")))
        return;
    std::vector<ast::Stmt> go;
    go.push_back(assignStmt(nameExpr(m_jumpVariable, at(n)), intLiteral(target->second, at(n))));
    go.push_back(simpleStmt(ast::StmtKind::Continue, at(n)));
    if (isBoolLiteral(condition->expr, true)) {
        for (ast::Stmt &s : go)
            push(std::move(s));
    } else {
        push(ifStmt(std::move(condition->expr), std::move(go)));
    }
}

void Evaluator::evaluateReturn(std::size_t n, const model::Return &ret)
{
    auto condition = input(n, ret.connectionPointIn, QCoreApplication::translate("iec::interp::Compiler", "The return has no condition wired to it."));
    if (!condition || !canEmit(n, QT_TRANSLATE_NOOP("iec::interp::Compiler", "A return")))
        return;
    ast::Stmt leave = simpleStmt(ast::StmtKind::Return, at(n));
    if (isBoolLiteral(condition->expr, true))
        push(std::move(leave));
    else
        push(ifStmt(std::move(condition->expr), {std::move(leave)}));
}

std::optional<ast::TypeSpec> Evaluator::resultType(const model::Block &block, const std::vector<Signal> &inputs,
    std::size_t n, const QString &key) const
{
    if (auto type = guessResultType(block, inputs))
        return type;
    // The variable the result is written to tells its type.
    const auto written = m_writtenTo.find({n, key});
    if (written == m_writtenTo.end())
        return std::nullopt;
    for (const std::size_t reader : written->second) {
        const model::Element &element = *m_network.node(reader).element;
        const auto *out = std::get_if<model::OutVariable>(&element);
        const QString &target = out ? out->expression : std::get<model::InOutVariable>(element).expression;
        Diagnostics ignored;
        if (auto expr = parseExpression(target, QString(), {}, ignored)) {
            if (auto type = literalOrDeclaredType(*expr, m_declared))
                return type;
        }
    }
    return std::nullopt;
}

} // namespace iec::interp::graphical
