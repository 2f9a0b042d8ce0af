#include "editors/cfc/cfcstorage.h"

#include "editors/common/editorlanguage.h"
#include "model/plcopen/fragment.h"

#include <QCoreApplication>
#include <QHash>

#include <cmath>
#include <map>

namespace iec::editors::cfc {

using namespace model;

namespace {

bool isAnonymousConnector(const Element &element)
{
    const auto *connector = std::get_if<Connector>(&element);
    return connector && connector->name.trimmed().isEmpty();
}

// Drawing units from CODESYS's grid and back. A pin on grid row y is drawn at y * grid, in the
// middle of a row: an element's top is half a row above its first pin's row.
Position fromGrid(const Position &grid)
{
    return {grid.x * kCodesysGrid, grid.y * kCodesysGrid - kCodesysGrid / 2};
}

Position toGrid(const Position &drawn)
{
    return {std::round(drawn.x / kCodesysGrid), std::round((drawn.y + kCodesysGrid / 2) / kCodesysGrid)};
}

void forEachPoint(Element &element, const std::function<void(std::optional<Position> &)> &visit)
{
    std::visit([&](auto &e) {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, Block>) {
            for (auto *pins : {&e.inputVariables, &e.inOutVariables, &e.outputVariables}) {
                for (BlockVariable &pin : *pins) {
                    if (pin.connectionPointIn)
                        visit(pin.connectionPointIn->relPosition);
                    if (pin.connectionPointOut)
                        visit(pin.connectionPointOut->relPosition);
                }
            }
        } else {
            if constexpr (requires { e.connectionPointIn; })
                if (e.connectionPointIn)
                    visit(e.connectionPointIn->relPosition);
            if constexpr (requires { e.connectionPointOut; })
                if (e.connectionPointOut)
                    visit(e.connectionPointOut->relPosition);
        }
    }, element);
}

// Where a connection through anonymous connectors comes from in the end (a chain is followed,
// a cycle of connectors stops it).
Connection resolved(Connection connection, const QHash<quint64, const Connector *> &anonymous)
{
    for (int guard = 0; guard < 64; ++guard) {
        const auto it = anonymous.find(connection.refLocalId);
        if (it == anonymous.end())
            break;
        const Connector &connector = **it;
        if (!connector.connectionPointIn || connector.connectionPointIn->connections.empty())
            break;
        const Connection &through = connector.connectionPointIn->connections.front();
        connection.refLocalId = through.refLocalId;
        connection.formalParameter = through.formalParameter;
    }
    return connection;
}

// A connection's formalParameter names a box's output; CODESYS also writes the variable's name
// for a variable's only output, which the editor does not keep.
void dropVariableOutputNames(std::vector<Element> &elements)
{
    QHash<quint64, bool> isBlock;
    for (const Element &e : elements)
        isBlock.insert(header(e).localId, std::holds_alternative<Block>(e));
    for (Element &e : elements)
        for (ConnectionPointIn *point : inputPoints(e))
            for (Connection &c : point->connections)
                if (!isBlock.value(c.refLocalId))
                    c.formalParameter.reset();
}

QString outputNameOf(const Element &source, const std::optional<QString> &formalParameter)
{
    if (formalParameter)
        return *formalParameter;
    if (const auto *in = std::get_if<InVariable>(&source))
        return in->expression;
    if (const auto *inOut = std::get_if<InOutVariable>(&source))
        return inOut->expression;
    return {};
}

} // namespace

int codesysCfcEntry(const Body &body)
{
    for (std::size_t i = 0; i < body.addData.size(); ++i)
        if (body.addData[i].name.endsWith(QLatin1String(kCodesysCfcAddDataSuffix), Qt::CaseInsensitive))
            return int(i);
    return -1;
}

std::optional<CfcStorage> cfcStorageOf(const Body &body)
{
    if (body.language() == BodyLanguage::ST && body.text().trimmed().isEmpty() && codesysCfcEntry(body) >= 0)
        return CfcStorage::Codesys;
    if (body.language() == BodyLanguage::FBD) {
        for (const AddDataEntry &entry : body.addData)
            if (entry.name == QLatin1String(kIecStudioCfcAddDataName))
                return CfcStorage::Elements;
        if (codesysCfcEntry(body) >= 0)
            return CfcStorage::Elements;
    }
    return std::nullopt;
}

CodesysCfcRead readCodesysCfc(const QString &content)
{
    CodesysCfcRead result;
    const plcopen::FragmentReadResult read = plcopen::readElementsUnder(content.toUtf8());
    if (!read.ok()) {
        result.error = read.error;
        return result;
    }
    QHash<quint64, const Connector *> anonymous;
    for (const Element &e : read.elements)
        if (isAnonymousConnector(e))
            anonymous.insert(header(e).localId, &std::get<Connector>(e));
    for (const Element &e : read.elements) {
        if (isAnonymousConnector(e))
            continue;
        Element shown = e;
        ElementHeader &h = header(shown);
        h.position = fromGrid(h.position);
        // Sizes are on the grid too (a comment's frame).
        if (h.width)
            *h.width *= kCodesysGrid;
        if (h.height)
            *h.height *= kCodesysGrid;
        if (h.executionOrderId)
            *h.executionOrderId += 1;
        forEachPoint(shown, [](std::optional<Position> &rel) { rel.reset(); });
        for (ConnectionPointIn *point : inputPoints(shown))
            for (Connection &c : point->connections)
                c = resolved(c, anonymous);
        result.elements.push_back(std::move(shown));
    }
    dropVariableOutputNames(result.elements);
    return result;
}

QString writeCodesysCfc(const std::vector<Element> &elements)
{
    quint64 nextId = 0;
    for (const Element &e : elements)
        nextId = std::max(nextId, header(e).localId + 1);
    // One anonymous connector per output that has readers, as CODESYS routes every wire.
    std::map<std::pair<quint64, QString>, quint64> connectorOf;
    std::map<quint64, std::vector<Element>> connectorsAfter;
    QHash<quint64, const Element *> byId;
    for (const Element &e : elements)
        byId.insert(header(e).localId, &e);
    std::vector<Element> written;
    written.reserve(elements.size() * 2);
    std::vector<Element> copies = elements;
    for (Element &e : copies) {
        for (ConnectionPointIn *point : inputPoints(e)) {
            for (Connection &c : point->connections) {
                const Element *source = byId.value(c.refLocalId);
                if (!source)
                    continue;
                const QString output = outputNameOf(*source, c.formalParameter);
                auto [it, fresh] = connectorOf.try_emplace({c.refLocalId, output}, nextId);
                if (fresh) {
                    Connector connector;
                    connector.localId = nextId++;
                    ConnectionPointIn in;
                    Connection through;
                    through.refLocalId = c.refLocalId;
                    through.formalParameter = output;
                    in.connections.push_back(through);
                    connector.connectionPointIn = in;
                    connectorsAfter[c.refLocalId].push_back(connector);
                }
                Connection viaConnector;
                viaConnector.refLocalId = it->second;
                c = viaConnector;
            }
        }
    }
    for (Element &e : copies) {
        ElementHeader &h = header(e);
        const quint64 id = h.localId;
        h.position = toGrid(h.position);
        if (h.width)
            h.width = std::round(*h.width / kCodesysGrid);
        if (h.height)
            h.height = std::round(*h.height / kCodesysGrid);
        if (h.executionOrderId)
            *h.executionOrderId = *h.executionOrderId > 0 ? *h.executionOrderId - 1 : 0;
        if (auto *block = std::get_if<Block>(&e)) {
            int row = 0;
            for (auto *pins : {&block->inputVariables, &block->inOutVariables}) {
                for (BlockVariable &pin : *pins)
                    if (pin.connectionPointIn)
                        pin.connectionPointIn->relPosition = Position {0, double(row++)};
            }
            row = 0;
            for (BlockVariable &pin : block->outputVariables)
                if (pin.connectionPointOut)
                    pin.connectionPointOut->relPosition = Position {0, double(row++)};
        } else {
            forEachPoint(e, [](std::optional<Position> &rel) { rel = Position {0, 0}; });
        }
        written.push_back(std::move(e));
        if (const auto it = connectorsAfter.find(id); it != connectorsAfter.end())
            for (Element &connector : it->second)
                written.push_back(std::move(connector));
    }
    return QString::fromUtf8(plcopen::writeElementsUnder("CFC", written));
}

} // namespace iec::editors::cfc
