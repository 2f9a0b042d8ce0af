// bench_cfc_editor: the CFC editor on a chart of 500 boxes (1,025 elements, 1,000 wires).
//
// Prints the time to open the chart in the editor (items and every wire routed), the time one
// step of dragging a box takes (its wires re-routed around the boxes near them, as the scene does
// on every mouse move), and the time of the move command at the drop (the edit, the undo command,
// the scene following it), the first and a later one. Run it offscreen from a Release build:
//   QT_QPA_PLATFORM=offscreen build/release/bench/editors/bench_cfc_editor
// Goal (issue 15): a drag step < 30 ms.
#include "editors/cfc/cfceditor.h"
#include "editors/cfc/cfcedits.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/editorlanguage.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QUndoStack>

#include <algorithm>
#include <cstdio>

using namespace iec;
using namespace iec::editors::cfc;

namespace {

constexpr int kColumns = 20;
constexpr int kRows = 25;

model::BlockVariable pin(const QString &name, bool input)
{
    model::BlockVariable v;
    v.formalParameter = name;
    if (input)
        v.connectionPointIn.emplace();
    else
        v.connectionPointOut.emplace();
    return v;
}

// Rows of ADD boxes, each adding an input variable to the box before it; each row ends in an
// output.
model::Project bigProject()
{
    auto read = interp::frontend::readIecText(QStringLiteral("PROGRAM Main\nEND_PROGRAM\n"), QStringLiteral("bench"));
    std::vector<model::Element> elements;
    for (int row = 0; row < kRows; ++row) {
        quint64 previous = 0;
        for (int column = 0; column < kColumns; ++column) {
            const double x = 120 + column * 200;
            const double y = 40 + row * 100;
            model::InVariable in;
            in.expression = QStringLiteral("X%1_%2").arg(row).arg(column);
            in.connectionPointOut.emplace();
            insertElement(elements, in, {x - 100, y + 50});
            const quint64 inId = model::header(elements.back()).localId;
            model::Block add;
            add.typeName = QStringLiteral("ADD");
            add.inputVariables = {pin(QStringLiteral("IN1"), true), pin(QStringLiteral("IN2"), true)};
            add.outputVariables = {pin(QStringLiteral("OUT"), false)};
            insertElement(elements, add, {x, y});
            const quint64 box = model::header(elements.back()).localId;
            connectPins(elements, inId, std::nullopt, box, 1);
            if (previous)
                connectPins(elements, previous, QStringLiteral("OUT"), box, 0);
            previous = box;
        }
        model::OutVariable out;
        out.expression = QStringLiteral("Y%1").arg(row);
        out.connectionPointIn.emplace();
        insertElement(elements, out, {120 + kColumns * 200.0, 60 + row * 100.0});
        connectPins(elements, previous, QStringLiteral("OUT"), model::header(elements.back()).localId, 0);
    }
    model::Body body = model::Body::withLanguage(model::BodyLanguage::FBD);
    body.addData.push_back({QString::fromLatin1(editors::kIecStudioCfcAddDataName), QStringLiteral("implementation"), QStringLiteral("<cfc/>")});
    *body.elements() = std::move(elements);
    read.project.types.pous.front().bodies = {std::move(body)};
    return read.project;
}

double ms(const QElapsedTimer &timer)
{
    return double(timer.nsecsElapsed()) / 1e6;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    model::ProjectModel projectModel;
    projectModel.reset(bigProject());
    const model::BodyRef ref {projectModel.project().types.pous.front().id};
    std::printf("CFC body: %d boxes, %zu elements\n", kRows * kColumns, projectModel.body(ref)->elements()->size());

    QUndoStack stack;
    QElapsedTimer timer;
    timer.start();
    CfcEditor editor(projectModel, ref, &stack);
    editor.resize(1200, 800);
    editor.show();
    app.processEvents();
    std::printf("open in the editor:          %8.1f ms\n", ms(timer));

    // A box in the middle of the chart, dragged 200 units down and right in 40 mouse steps.
    quint64 box = 0; // row 12, column 10
    for (const model::Element &e : *projectModel.body(ref)->elements())
        if (std::holds_alternative<model::Block>(e) && model::header(e).position == model::Position {120 + 10 * 200, 40 + 12 * 100})
            box = model::header(e).localId;
    editors::DiagramScene &scene = *editor.scene();
    editors::DiagramItem *item = scene.itemFor(box);
    const QPointF start = item->pos();
    editor.view()->centerOn(item);
    double worst = 0;
    double total = 0;
    constexpr int kSteps = 40;
    for (int step = 1; step <= kSteps; ++step) {
        const QPointF delta(step * 5.0, step * 5.0);
        timer.restart();
        item->setPos(start + delta);
        scene.policy().itemsDragged(scene, {box}, delta);
        editor.view()->viewport()->repaint();
        const double t = ms(timer);
        worst = std::max(worst, t);
        total += t;
    }
    std::printf("drag step (re-route + paint): %7.2f ms mean, %.2f ms worst   (goal < 30 ms)\n", total / kSteps, worst);

    // The first command measures and writes every element's size (the chart was made without
    // them); later ones measure only what changed.
    timer.restart();
    Q_EMIT scene.elementsMoved({box}, {start + QPointF(200, 200)});
    app.processEvents();
    std::printf("drop (the first move command): %5.1f ms\n", ms(timer));
    timer.restart();
    Q_EMIT scene.elementsMoved({box}, {start + QPointF(100, 200)});
    app.processEvents();
    std::printf("drop (a later move command):   %5.1f ms\n", ms(timer));
    return 0;
}
