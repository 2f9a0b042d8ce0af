#include "interpreter/graphical/graphicallowering.h"

#include "interpreter/graphical/astbuild.h"
#include "interpreter/graphical/evaluator.h"
#include "interpreter/graphical/network.h"

#include "model/plcopen/reader.h"

#include <QCoreApplication>

#include <map>

namespace iec::interp::graphical {

namespace {

// Elements that have no meaning in an LD or FBD network.
bool reportForeignElements(const Network &network, LoweringContext &context)
{
    bool ok = true;
    for (const Node &node : network.nodes()) {
        if (node.kind != NodeKind::Foreign && node.kind != NodeKind::Unsupported)
            continue;
        QString message;
        if (const auto *vendor = std::get_if<model::VendorElement>(node.element)) {
            message = QCoreApplication::translate("iec::interp::Compiler", "The vendor element '%1' cannot run in this version.")
                          .arg(vendor->alternativeText.text.trimmed());
        } else if (std::holds_alternative<model::Error>(*node.element)) {
            message = QCoreApplication::translate("iec::interp::Compiler", "This element could not be read from the file, so it cannot run.");
        } else {
            message = QCoreApplication::translate("iec::interp::Compiler", "A %1 belongs in an SFC chart, not in an LD or FBD network.")
                          .arg(elementKindName(*node.element));
        }
        context.diagnostics.error(context.owner, elementLocation(node.localId), message);
        ok = false;
    }
    return ok;
}

// Segment numbers of the labels (segment 0 runs from the start), upper-case names.
std::map<QString, int> labelSegments(const Network &network, const std::vector<std::size_t> &roots,
    LoweringContext &context)
{
    std::map<QString, int> labels;
    int segment = 0;
    for (const std::size_t root : roots) {
        const auto *label = std::get_if<model::Label>(network.node(root).element);
        if (!label)
            continue;
        ++segment;
        if (!labels.try_emplace(label->label.trimmed().toUpper(), segment).second) {
            context.diagnostics.error(context.owner, elementLocation(network.node(root).localId),
                QCoreApplication::translate("iec::interp::Compiler", "Two labels are called '%1'.").arg(label->label), QCoreApplication::translate("iec::interp::Compiler", "rename one of them"));
        }
    }
    return labels;
}

// pc := 0; WHILE TRUE DO IF pc <= 0 THEN (segment 0) END_IF; ... EXIT; END_WHILE
// A jump sets pc to its label's segment and continues the loop, which skips the segments before.
std::vector<ast::Stmt> segmentLoop(std::vector<std::vector<ast::Stmt>> segments, const QString &pc)
{
    const SourceLocation nowhere;
    std::vector<ast::Stmt> loopBody;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (segments[i].empty())
            continue;
        ast::Expr due = binaryExpr(QStringLiteral("<="), nameExpr(pc, nowhere), intLiteral(int(i), nowhere));
        loopBody.push_back(ifStmt(std::move(due), std::move(segments[i])));
    }
    loopBody.push_back(simpleStmt(ast::StmtKind::Exit, nowhere));
    ast::Stmt loop = simpleStmt(ast::StmtKind::While, nowhere);
    loop.value = boolLiteral(true, nowhere);
    loop.body = std::move(loopBody);
    std::vector<ast::Stmt> result;
    result.push_back(assignStmt(nameExpr(pc, nowhere), intLiteral(0, nowhere)));
    result.push_back(std::move(loop));
    return result;
}

} // namespace

namespace {

// The debugger's place for each root: elements wired together (rails aside, which Beremiz shares
// between rungs) are one network, named by the localId of its first root in execution order. So
// a breakpoint on a network halts once, and a step moves one network.
std::vector<qint64> networkPlaces(const Network &network, const std::vector<std::size_t> &roots)
{
    std::vector<std::size_t> parent(network.nodes().size());
    for (std::size_t i = 0; i < parent.size(); ++i)
        parent[i] = i;
    const auto find = [&parent](std::size_t i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    const auto isRail = [&network](std::size_t i) {
        return network.node(i).kind == NodeKind::LeftRail || network.node(i).kind == NodeKind::RightRail;
    };
    for (std::size_t i = 0; i < parent.size(); ++i) {
        if (isRail(i))
            continue;
        for (const std::size_t source : network.node(i).sources)
            if (source < parent.size() && !isRail(source))
                parent[find(i)] = find(source);
    }
    std::map<std::size_t, qint64> placeOfGroup;
    std::vector<qint64> places;
    for (const std::size_t root : roots) {
        const qint64 localId = qint64(network.node(root).localId);
        places.push_back(placeOfGroup.try_emplace(find(root), localId).first->second);
    }
    return places;
}

} // namespace

std::vector<ast::Stmt> lowerBody(const model::Body &body, LoweringContext &context)
{
    const std::vector<model::Element> *elements = body.elements();
    if (!elements)
        return {};
    Network network(*elements, context.owner, context.diagnostics);
    if (!reportForeignElements(network, context) || !network.ok() || !network.breakLoops(context.owner, context.diagnostics))
        return {};
    const std::vector<std::size_t> roots = network.rootOrder(body.layoutGenerated);
    Evaluator evaluator(network, context, body.language() == model::BodyLanguage::LD);
    const bool cfc = isCfc(body);
    evaluator.setElementPlaces(cfc);
    const std::map<QString, int> labels = labelSegments(network, roots, context);
    const bool jumps = std::ranges::any_of(network.nodes(), [](const Node &n) { return n.kind == NodeKind::Jump; });
    const QString pc = jumps ? evaluator.hiddenVariable(QStringLiteral("jump"), namedType(QStringLiteral("INT"))) : QString();
    evaluator.setJumpTargets(labels, pc);
    const std::vector<qint64> places = networkPlaces(network, roots);
    std::vector<std::vector<ast::Stmt>> segments(1);
    for (std::size_t r = 0; r < roots.size(); ++r) {
        if (network.node(roots[r]).kind == NodeKind::Label) {
            segments.emplace_back();
            continue;
        }
        std::vector<ast::Stmt> rootStatements;
        evaluator.setSink(&rootStatements);
        evaluator.run(roots[r]);
        if (!cfc) // CFC: each statement keeps its element's localId as its place
            setPlace(rootStatements, places[r]);
        std::ranges::move(rootStatements, std::back_inserter(segments.back()));
    }
    evaluator.declareHidden();
    if (jumps)
        return segmentLoop(std::move(segments), pc);
    std::vector<ast::Stmt> statements;
    for (std::vector<ast::Stmt> &segment : segments)
        std::ranges::move(segment, std::back_inserter(statements));
    return statements;
}

std::optional<ast::Expr> lowerInput(const model::Body &body, const model::ConnectionPointIn &input,
    LoweringContext &context)
{
    return InputLowering(body, context.owner, context.diagnostics).lower(input, context);
}

InputLowering::InputLowering(const model::Body &body, const QString &owner, Diagnostics &diagnostics)
    : m_body(body)
{
    const std::vector<model::Element> *elements = body.elements();
    if (!elements)
        return;
    auto network = std::make_unique<Network>(*elements, owner, diagnostics);
    if (network->ok() && network->breakLoops(owner, diagnostics))
        m_network = std::move(network);
}

InputLowering::~InputLowering() = default;

std::optional<ast::Expr> InputLowering::lower(const model::ConnectionPointIn &input, LoweringContext &context) const
{
    if (!m_network)
        return std::nullopt;
    // The element the input belongs to, for the location of diagnostics.
    quint64 owner = 0;
    for (const model::Element &element : *m_body.elements()) {
        for (const model::ConnectionPointIn *point : model::inputPoints(element)) {
            if (point == &input || (owner == 0 && *point == input)) // the caller may pass a copy
                owner = model::header(element).localId;
        }
    }
    Evaluator evaluator(*m_network, context, true);
    evaluator.setSink(context.setup);
    auto value = evaluator.valueOf(input, owner, QCoreApplication::translate("iec::interp::Compiler", "This condition"));
    evaluator.declareHidden();
    if (!value)
        return std::nullopt;
    return std::move(value->expr);
}

std::optional<model::Body> cfcDiagram(const model::Body &body)
{
    if (body.language() != model::BodyLanguage::ST || !body.text().trimmed().isEmpty())
        return std::nullopt;
    for (const model::AddDataEntry &entry : body.addData) {
        if (!entry.name.endsWith(QLatin1String("/plcopenxml/cfc"), Qt::CaseInsensitive))
            continue;
        // Read the diagram's elements as the FBD body of a one-POU project, with the reader that
        // reads every other diagram.
        QString inner = entry.content.trimmed();
        const qsizetype open = inner.indexOf(QLatin1Char('>'));
        const qsizetype close = inner.lastIndexOf(QLatin1String("</CFC>"));
        if (!inner.startsWith(QLatin1String("<CFC")) || open < 0)
            return std::nullopt;
        inner = close > open ? inner.mid(open + 1, close - open - 1) : QString();
        const QString xml = QStringLiteral("<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\"><types><dataTypes/><pous>"
                                           "<pou name=\"CFC\" pouType=\"program\"><body><FBD>%1</FBD></body></pou>"
                                           "</pous></types></project>")
                                .arg(inner);
        const model::plcopen::ReadResult read = model::plcopen::readProject(xml.toUtf8());
        if (read.project.types.pous.empty() || !read.project.types.pous.front().body())
            return std::nullopt;
        model::Body diagram = *read.project.types.pous.front().body();
        // CODESYS numbers the execution order from 0, which elsewhere (Beremiz) means "none".
        for (model::Element &element : *diagram.elements()) {
            if (auto &order = model::header(element).executionOrderId)
                *order += 1;
        }
        diagram.addData.push_back({QString::fromLatin1(kCfcMarkAddDataName), QStringLiteral("discard"), QString()});
        return diagram;
    }
    return std::nullopt;
}

bool isCfc(const model::Body &body)
{
    return std::ranges::any_of(body.addData, [](const model::AddDataEntry &entry) {
        return entry.name == QLatin1String(kCfcMarkAddDataName);
    });
}

} // namespace iec::interp::graphical
