// bench_fbd_editor: the FBD editor on a body of 500 networks (4,000 elements).
//
// Prints the time to open the body in the editor (read, lay out, build the scene), the time of a
// command at the last and at the first network (the edit, the undo command, the scene following
// it), and the time of one online repaint of the visible networks. Run it offscreen from a
// Release build:
//   QT_QPA_PLATFORM=offscreen build/release/bench/editors/bench_fbd_editor [ROUNDS]
// Goals (issue 14): open < 0.5 s, a command < 30 ms.
#include "editors/common/diagramview.h"
#include "editors/fbd/fbdedits.h"
#include "editors/fbd/fbdeditor.h"
#include "editors/fbd/fbdwrite.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/runtime/snapshot.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QUndoStack>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

using namespace iec;
using namespace iec::editors::fbd;
using iec::editors::BoxSpec;
using Kind = FbdCursor::Kind;

namespace {

constexpr int kNetworks = 500;

// A network of eight elements: Q_n := (A_n AND NOT B_n) OR T_n.Q with T_n(IN := C_n, PT := T#1s).
void addNetwork(FbdDocument &doc, int n)
{
    const auto name = [n](const char *base) { return QStringLiteral("%1_%2").arg(QLatin1String(base)).arg(n); };
    const BoxSpec andSpec {QStringLiteral("AND"), false, {QStringLiteral("IN1"), QStringLiteral("IN2")}, {QStringLiteral("OUT")}, 0, 0, false};
    const BoxSpec orSpec {QStringLiteral("OR"), false, {QStringLiteral("IN1"), QStringLiteral("IN2")}, {QStringLiteral("OUT")}, 0, 0, false};
    const BoxSpec tonSpec {QStringLiteral("TON"), true, {QStringLiteral("IN"), QStringLiteral("PT")}, {QStringLiteral("Q"), QStringLiteral("ET")}, 0, 0, false};
    const FbdCursor input = insertNetwork(doc, FbdCursor::atNetwork(n - 1), true).cursor;
    setElementText(doc, input.element, name("A"));
    const quint64 andBox = insertOperator(doc, FbdCursor::at(Kind::End, n), andSpec).cursor.element;
    toggleNegation(doc, FbdCursor::at(Kind::Input, n, andBox, 1));
    const quint64 orBox = insertOperator(doc, FbdCursor::at(Kind::End, n), orSpec).cursor.element;
    const quint64 ton = insertOperator(doc, FbdCursor::at(Kind::Input, n, orBox, 1), tonSpec).cursor.element;
    setElementText(doc, ton, name("T"));
    for (quint64 id : std::vector<quint64>(doc.networks[std::size_t(n)].members)) {
        const QString text = elementText(doc, id);
        if (text != QLatin1String("???"))
            continue;
        const auto *out = std::get_if<model::OutVariable>(doc.element(id));
        const auto readers = readersOf(doc, doc.networks[std::size_t(n)], {id, 0});
        const bool pt = !readers.nodes.empty() && readers.nodes.front().first == ton && readers.nodes.front().second == 1;
        const bool in = !readers.nodes.empty() && readers.nodes.front().first == ton && readers.nodes.front().second == 0;
        setElementText(doc, id, out ? name("Q") : pt ? QStringLiteral("T#1s") : in ? name("C") : name("B"));
    }
}

model::Project bigProject()
{
    auto read = interp::frontend::readIecText(QStringLiteral("PROGRAM Main\nEND_PROGRAM\n"), QStringLiteral("bench"));
    FbdDocument doc = readFbd({});
    for (int n = 0; n < kNetworks; ++n)
        addNetwork(doc, n);
    writeFbd(doc);
    model::Body body = model::Body::withLanguage(model::BodyLanguage::FBD);
    *body.elements() = std::move(doc.elements);
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
    // An optional argument: how often each command is timed (the best is printed; more rounds
    // for a profiler).
    const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    model::ProjectModel projectModel;
    projectModel.reset(bigProject());
    const model::BodyRef ref {projectModel.project().types.pous.front().id};
    std::printf("FBD body: %d networks, %zu elements\n", kNetworks, projectModel.body(ref)->elements()->size());

    QUndoStack stack;
    QElapsedTimer timer;
    timer.start();
    FbdEditor editor(projectModel, ref, &stack);
    editor.resize(1200, 800);
    editor.show();
    app.processEvents();
    std::printf("open in the editor:               %8.1f ms   (goal < 500 ms)\n", ms(timer));

    const auto command = [&](int network, const char *where) {
        double best = 1e9;
        for (int round = 0; round < rounds; ++round) {
            editor.setCursor(FbdCursor::at(Kind::End, network));
            timer.restart();
            editor.insertAssignment();
            if (auto *field = editor.inPlaceEditor())
                field->cancel();
            app.processEvents();
            best = std::min(best, ms(timer));
            stack.undo();
            app.processEvents();
        }
        std::printf("insert an assignment at the %s network: %6.1f ms   (goal < 30 ms)\n", where, best);
    };
    command(kNetworks - 1, "last ");
    command(0, "first");

    editor.setOnlineInstance(QStringLiteral("Main"));
    const QStringList names = editor.onlineNames();
    double worst = 0;
    double total = 0;
    constexpr int kFrames = 40;
    for (int frame = 0; frame < kFrames; ++frame) {
        interp::RuntimeSnapshot snapshot;
        snapshot.cycle = frame;
        for (int i = 0; i < names.size(); ++i)
            snapshot.values.insert(names[i], (i + frame) % 3 ? QStringLiteral("TRUE") : QStringLiteral("FALSE"));
        timer.restart();
        editor.setOnlineSnapshot(&snapshot);
        editor.view()->viewport()->repaint();
        const double t = ms(timer);
        worst = std::max(worst, t);
        total += t;
    }
    std::printf("online repaint (%lld names):        %6.1f ms mean, %.1f ms worst\n",
        static_cast<long long>(names.size()), total / kFrames, worst);
    editor.setOnlineSnapshot(nullptr);
    return 0;
}
