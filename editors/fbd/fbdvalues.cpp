#include "editors/fbd/fbdvalues.h"

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <optional>

namespace iec::editors::fbd {

using namespace model;

namespace {

std::optional<bool> asBool(const QString &literal)
{
    const QString t = literal.trimmed();
    if (t.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0 || t == QLatin1String("1"))
        return true;
    if (t.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0 || t == QLatin1String("0"))
        return false;
    return std::nullopt;
}

bool isBoolLiteral(const QString &literal)
{
    const QString t = literal.trimmed();
    return t.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0 || t.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0;
}

// A number, with a type prefix ("INT#5") or not; nullopt for anything else (times, strings).
std::optional<double> asNumber(const QString &literal)
{
    QString t = literal.trimmed();
    if (const qsizetype hash = t.indexOf(QLatin1Char('#')); hash > 0 && t.left(hash).front().isLetter()) {
        const QString type = t.left(hash).toUpper();
        if (type.startsWith(QLatin1String("T")) || type.startsWith(QLatin1String("D")) || type.contains(QLatin1String("STRING")))
            return std::nullopt;
        t = t.mid(hash + 1);
    }
    t.remove(QLatin1Char('_'));
    bool ok = false;
    const double value = t.toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

bool isIntegerLiteral(const QString &literal)
{
    const QString t = literal.trimmed();
    return !t.contains(QLatin1Char('.')) && !t.contains(QLatin1Char('e'), Qt::CaseInsensitive) && asNumber(t).has_value();
}

QString boolText(bool value)
{
    return value ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
}

QString numberText(double value, bool integer)
{
    if (integer)
        return QString::number(qint64(value));
    QString text = QString::number(value, 'g', 12);
    if (!text.contains(QLatin1Char('.')) && !text.contains(QLatin1Char('e')))
        text += QStringLiteral(".0");
    return text;
}

QString negate(const QString &literal)
{
    const auto b = asBool(literal);
    return b && isBoolLiteral(literal) ? boolText(!*b) : literal;
}

} // namespace

QString evaluateFunction(const QString &typeName, const QStringList &inputs)
{
    const QString type = typeName.trimmed().toUpper();
    if (inputs.isEmpty() || std::ranges::any_of(inputs, [](const QString &v) { return v.isEmpty(); }))
        return {};
    const bool logical = std::ranges::all_of(inputs, isBoolLiteral);
    if (logical && (type == QLatin1String("AND") || type == QLatin1String("OR") || type == QLatin1String("XOR"))) {
        bool result = *asBool(inputs.front());
        for (qsizetype i = 1; i < inputs.size(); ++i) {
            const bool v = *asBool(inputs[i]);
            result = type == QLatin1String("AND") ? (result && v) : type == QLatin1String("OR") ? (result || v) : (result != v);
        }
        return boolText(result);
    }
    if (logical && type == QLatin1String("NOT") && inputs.size() == 1)
        return boolText(!*asBool(inputs.front()));
    if ((type == QLatin1String("MOVE")) && inputs.size() == 1)
        return inputs.front();
    if (type == QLatin1String("SEL") && inputs.size() == 3) {
        const auto g = asBool(inputs[0]);
        return g ? inputs[*g ? 2 : 1] : QString();
    }
    std::vector<double> numbers;
    for (const QString &v : inputs) {
        const auto n = asNumber(v);
        if (!n || isBoolLiteral(v))
            return {};
        numbers.push_back(*n);
    }
    const bool integer = std::ranges::all_of(inputs, isIntegerLiteral);
    const auto compareAll = [&](auto op) {
        for (std::size_t i = 1; i < numbers.size(); ++i)
            if (!op(numbers[i - 1], numbers[i]))
                return boolText(false);
        return boolText(true);
    };
    if (type == QLatin1String("GT"))
        return compareAll([](double a, double b) { return a > b; });
    if (type == QLatin1String("GE"))
        return compareAll([](double a, double b) { return a >= b; });
    if (type == QLatin1String("LT"))
        return compareAll([](double a, double b) { return a < b; });
    if (type == QLatin1String("LE"))
        return compareAll([](double a, double b) { return a <= b; });
    if (type == QLatin1String("EQ"))
        return compareAll([](double a, double b) { return a == b; });
    if (type == QLatin1String("NE") && numbers.size() == 2)
        return boolText(numbers[0] != numbers[1]);
    if (type == QLatin1String("ADD") || type == QLatin1String("MUL")) {
        double result = type == QLatin1String("ADD") ? 0 : 1;
        for (double n : numbers)
            result = type == QLatin1String("ADD") ? result + n : result * n;
        return numberText(result, integer);
    }
    if (type == QLatin1String("SUB") && numbers.size() == 2)
        return numberText(numbers[0] - numbers[1], integer);
    if (type == QLatin1String("DIV") && numbers.size() == 2 && numbers[1] != 0)
        return numberText(integer ? std::trunc(numbers[0] / numbers[1]) : numbers[0] / numbers[1], integer);
    if (type == QLatin1String("MAX"))
        return numberText(*std::ranges::max_element(numbers), integer);
    if (type == QLatin1String("MIN"))
        return numberText(*std::ranges::min_element(numbers), integer);
    if (type == QLatin1String("LIMIT") && numbers.size() == 3)
        return numberText(std::clamp(numbers[1], numbers[0], std::max(numbers[0], numbers[2])), integer);
    return {};
}

std::map<std::pair<quint64, int>, QString> networkValues(const FbdDocument &document, const FbdNetwork &network,
    const std::function<QString(quint64, const QString &)> &valueOf, const std::function<QString(quint64, const QString &)> &instancePin)
{
    std::map<std::pair<quint64, int>, QString> values;
    // Nodes in data-flow order: a node once every node feeding it has its value (no recursion;
    // a loop in a freehand network simply stays unknown).
    std::vector<quint64> pending;
    for (quint64 id : network.members)
        if (const Element *e = document.element(id); e && isNode(*e))
            pending.push_back(id);
    std::vector<bool> done(pending.size(), false);
    bool progress = true;
    while (progress) {
        progress = false;
        for (std::size_t i = 0; i < pending.size(); ++i) {
            if (done[i])
                continue;
            const quint64 id = pending[i];
            const Element &e = *document.element(id);
            QStringList inputs;
            bool ready = true;
            for (int pin = 0; pin < inputCount(e) && ready; ++pin) {
                const auto source = sourceOf(document, id, pin);
                if (source && isNode(*document.element(source->element)) && !values.contains({source->element, source->pin})) {
                    // Not computed yet, or never: wait while others make progress.
                    const auto at = std::ranges::find(pending, source->element);
                    if (at != pending.end() && !done[std::size_t(at - pending.begin())]) {
                        ready = false;
                        break;
                    }
                }
                QString value = source ? values[{source->element, source->pin}] : QString();
                if (const auto *block = std::get_if<Block>(&e); block && pin < int(block->inputVariables.size())
                    && block->inputVariables[std::size_t(pin)].negated)
                    value = negate(value);
                inputs << value;
            }
            if (!ready)
                continue;
            done[i] = true;
            progress = true;
            if (const auto *in = std::get_if<InVariable>(&e)) {
                const QString v = valueOf(id, in->expression);
                values[{id, 0}] = in->negated ? negate(v) : v;
            } else if (const auto *inOut = std::get_if<InOutVariable>(&e)) {
                const QString v = valueOf(id, inOut->expression);
                values[{id, 0}] = inOut->negatedOut ? negate(v) : v;
            } else if (const auto *block = std::get_if<Block>(&e)) {
                for (int out = 0; out < int(block->outputVariables.size()); ++out) {
                    const BlockVariable &pin = block->outputVariables[std::size_t(out)];
                    QString v;
                    if (block->instanceName) {
                        v = instancePin(id, pin.formalParameter);
                    } else if (pin.formalParameter.compare(QLatin1String("ENO"), Qt::CaseInsensitive) == 0) {
                        v = inputs.isEmpty() ? QString() : inputs.front();
                    } else {
                        QStringList data = inputs;
                        if (!block->inputVariables.empty() && block->inputVariables.front().formalParameter.compare(QLatin1String("EN"), Qt::CaseInsensitive) == 0)
                            data.removeFirst();
                        v = evaluateFunction(block->typeName, data);
                    }
                    values[{id, out}] = pin.negated ? negate(v) : v;
                }
            }
        }
    }
    std::erase_if(values, [](const auto &entry) { return entry.second.isEmpty(); });
    return values;
}

} // namespace iec::editors::fbd
