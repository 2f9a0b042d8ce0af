#include "editors/cfc/cfcgeometry.h"

#include "editors/common/elementpool.h"
#include "editors/common/textmetrics.h"
#include "editors/common/wirerouting.h"

#include <algorithm>

namespace iec::editors::cfc {

using namespace model;

namespace {

constexpr double kTitleRow = kCfcRow; // the type name above the first pin (BoxItem's title row)

int boxRows(const Block &block)
{
    const std::size_t inputs = block.inputVariables.size() + block.inOutVariables.size();
    return int(std::max({inputs, block.outputVariables.size(), std::size_t(1)}));
}

QSizeF commentSize(const Comment &comment)
{
    const QStringList lines = comment.content.text.split(QLatin1Char('\n'));
    double width = 0;
    for (const QString &line : lines)
        width = std::max(width, textWidth(line));
    return {roundUp(std::max(80.0, width + 16), 10), roundUp(lines.size() * 15.0 + 10, 10)};
}

QSizeF contentSize(const Element &e)
{
    if (const auto *block = std::get_if<Block>(&e))
        return {boxWidth(*block), kTitleRow + boxRows(*block) * kCfcRow};
    if (const auto *label = std::get_if<Label>(&e))
        return {roundUp(textWidth(label->label) + 24, 10), kCfcRow};
    if (const auto *connector = std::get_if<Connector>(&e))
        return {roundUp(textWidth(connector->name) + 30, 10), kCfcRow};
    if (const auto *continuation = std::get_if<Continuation>(&e))
        return {roundUp(textWidth(continuation->name) + 30, 10), kCfcRow};
    if (const auto *comment = std::get_if<Comment>(&e))
        return commentSize(*comment);
    if (const auto *vendor = std::get_if<VendorElement>(&e)) {
        // Another tool's element (a CODESYS selector, say): its text in a box with its pins.
        const std::size_t inputs = vendor->inputVariables ? vendor->inputVariables->size() : 0;
        const std::size_t outputs = vendor->outputVariables ? vendor->outputVariables->size() : 0;
        const std::size_t rows = std::max({inputs, outputs, std::size_t(1)});
        return {roundUp(std::max(60.0, textWidth(vendor->alternativeText.text.simplified()) + 16), 10), double(rows) * kCfcRow};
    }
    return sinkOrVariableSize(e);
}

} // namespace

QRectF cfcRect(const Element &element)
{
    const ElementHeader &h = header(element);
    QSizeF size = contentSize(element);
    // A comment is as large as it was drawn; everything else as its content needs.
    if (std::holds_alternative<Comment>(element) && h.width && h.height && *h.width > 0 && *h.height > 0)
        size = QSizeF(*h.width, *h.height);
    return {QPointF(h.position.x, h.position.y), size};
}

void writeCfcSizes(std::vector<Element> &elements, const std::vector<Element> &before)
{
    QHash<quint64, const Element *> old;
    old.reserve(qsizetype(before.size()));
    for (const Element &e : before)
        old.insert(header(e).localId, &e);
    for (Element &e : elements) {
        ElementHeader &h = header(e);
        const Element *was = old.value(h.localId);
        if (was && h.width && h.height && *was == e)
            continue;
        const QSizeF size = cfcRect(e).size();
        h.width = size.width();
        h.height = size.height();
    }
}

std::optional<QPointF> cfcInputPin(const Element &element, int pin)
{
    const QRectF rect = cfcRect(element);
    if (const auto *block = std::get_if<Block>(&element)) {
        int index = 0;
        int row = 0;
        for (const auto *pins : {&block->inputVariables, &block->inOutVariables}) {
            for (const BlockVariable &variable : *pins) {
                if (variable.connectionPointIn && index++ == pin)
                    return QPointF(rect.left(), rect.top() + kTitleRow + row * kCfcRow + kCfcRow / 2);
                ++row;
            }
        }
        return std::nullopt;
    }
    if (const auto *vendor = std::get_if<VendorElement>(&element)) {
        int index = 0;
        int row = 0;
        for (const auto *pins : {&vendor->inputVariables, &vendor->inOutVariables}) {
            for (const BlockVariable &variable : pins->value_or(std::vector<BlockVariable> {})) {
                if (variable.connectionPointIn && index++ == pin)
                    return QPointF(rect.left(), rect.top() + row * kCfcRow + kCfcRow / 2);
                ++row;
            }
        }
        return std::nullopt;
    }
    if (pin != 0 || inputPoints(element).empty())
        return std::nullopt;
    return QPointF(rect.left(), rect.top() + kCfcRow / 2);
}

std::optional<QPointF> cfcOutputPin(const Element &element, const std::optional<QString> &formalParameter)
{
    const QRectF rect = cfcRect(element);
    const int index = outputPinIndex(element, formalParameter);
    if (index < 0)
        return std::nullopt;
    if (std::holds_alternative<Block>(element))
        return QPointF(rect.right(), rect.top() + kTitleRow + index * kCfcRow + kCfcRow / 2);
    if (const auto *vendor = std::get_if<VendorElement>(&element)) {
        const std::vector<BlockVariable> outputs = vendor->outputVariables.value_or(std::vector<BlockVariable> {});
        int row = 0;
        for (std::size_t i = 0; i < outputs.size(); ++i)
            if (!formalParameter || outputs[i].formalParameter.compare(*formalParameter, Qt::CaseInsensitive) == 0) {
                row = int(i);
                break;
            }
        return outputs.empty() ? std::nullopt : std::optional(QPointF(rect.right(), rect.top() + row * kCfcRow + kCfcRow / 2));
    }
    const bool hasOutput = std::visit([](const auto &e) {
        if constexpr (requires { e.connectionPointOut; })
            return true;
        else
            return false;
    }, element);
    if (!hasOutput)
        return std::nullopt;
    return QPointF(rect.right(), rect.top() + kCfcRow / 2);
}

CfcFrames cfcFrames(const std::vector<Element> &elements)
{
    CfcFrames frames;
    frames.reserve(qsizetype(elements.size()));
    for (const Element &e : elements)
        if (!std::holds_alternative<Comment>(e)) // wires may cross comments
            frames.insert(header(e).localId, cfcRect(e));
    return frames;
}

CfcWire routeCfcWire(QPointF from, QPointF to, const CfcFrames &frames)
{
    CfcWire wire;
    // The frames near the pins first (a wire rarely needs a long detour, and a 500-box chart has
    // to route while a box is dragged), then a wider window before giving up.
    for (const double margin : {120.0, 600.0}) {
        const QRectF window = QRectF(from, to).normalized().adjusted(-margin, -margin, margin, margin);
        RouteRequest request;
        request.from = from;
        request.to = to;
        request.clearance = kWireClearance;
        for (const QRectF &frame : frames)
            if (frame.intersects(window))
                request.obstacles << frame;
        if (auto route = tryRouteOrthogonal(request)) {
            wire.points = *std::move(route);
            return wire;
        }
    }
    wire.points = {from, to};
    wire.broken = true;
    return wire;
}

std::vector<CfcWire> routeCfcWires(const std::vector<Element> &elements, const CfcFrames &frames)
{
    QHash<quint64, const Element *> byId;
    for (const Element &e : elements)
        byId.insert(header(e).localId, &e);
    std::vector<CfcWire> wires;
    for (const Element &target : elements) {
        const auto points = inputPoints(target);
        for (std::size_t pin = 0; pin < points.size(); ++pin) {
            for (const Connection &c : points[pin]->connections) {
                const Element *source = byId.value(c.refLocalId);
                const auto from = source ? cfcOutputPin(*source, c.formalParameter) : std::nullopt;
                const auto to = cfcInputPin(target, int(pin));
                if (!from || !to)
                    continue;
                CfcWire wire = routeCfcWire(*from, *to, frames);
                wire.source = c.refLocalId;
                wire.formalParameter = c.formalParameter;
                wire.target = header(target).localId;
                wire.pin = int(pin);
                wires.push_back(std::move(wire));
            }
        }
    }
    return wires;
}

} // namespace iec::editors::cfc
