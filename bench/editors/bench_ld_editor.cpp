// bench_ld_editor: the LD editor on a body of 1,000 networks (about 10,000 elements).
//
// Prints the time to open the body in the editor (read, lay out, build the scene), the time of a
// command at the last and at the first network (the edit, the undo command, the scene following
// it), and the time of one online repaint of the visible networks (a snapshot applied and the
// viewport painted), as the online mode does 20 times a second. Run it offscreen from a Release
// build:
//   QT_QPA_PLATFORM=offscreen build/release/bench/editors/bench_ld_editor
// Goals (issue 12): open < 0.5 s, a command < 30 ms, a repaint < 10 ms.
#include "editors/common/diagramview.h"
#include "editors/ld/ldedits.h"
#include "editors/ld/ldeditor.h"
#include "editors/ld/ldwrite.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/runtime/snapshot.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QUndoStack>

#include <algorithm>
#include <cstdio>

using namespace iec;
using namespace iec::editors::ld;
using iec::editors::BoxSpec;

namespace {

constexpr int kNetworks = 1000;

// A network of about ten elements: (A | B) /C TON (Q1 | Q2).
void addNetwork(LadderDocument &doc, int n)
{
    const auto name = [n](const char *base) { return QStringLiteral("%1_%2").arg(QLatin1String(base)).arg(n); };
    LdCursor cursor = insertNetwork(doc, LdCursor::atNetwork(n - 1), true).cursor;
    const quint64 a = insertContact(doc, cursor).cursor.element();
    setElementText(doc, a, name("A"));
    const quint64 b = insertParallelContact(doc, LdCursor::atElement(n, a), true).cursor.element();
    setElementText(doc, b, name("B"));
    const quint64 c = insertContact(doc, LdCursor::atNetwork(n)).cursor.element();
    setElementText(doc, c, name("C"));
    toggleNegation(doc, LdCursor::atElement(n, c));
    const BoxSpec ton {QStringLiteral("TON"), true, {QStringLiteral("IN"), QStringLiteral("PT")}, {QStringLiteral("Q"), QStringLiteral("ET")}, 0, 0, false};
    const quint64 t = insertBox(doc, LdCursor::atNetwork(n), ton).cursor.element();
    setElementText(doc, t, name("T"));
    const quint64 q1 = insertCoil(doc, LdCursor::atNetwork(n)).cursor.element();
    setElementText(doc, q1, name("Q1"));
    const quint64 q2 = insertCoil(doc, LdCursor::atNetwork(n)).cursor.element();
    setElementText(doc, q2, name("Q2"));
}

model::Project bigProject()
{
    auto read = interp::frontend::readIecText(QStringLiteral("PROGRAM Main\nEND_PROGRAM\n"), QStringLiteral("bench"));
    LadderDocument doc = readLadder({});
    for (int n = 0; n < kNetworks; ++n)
        addNetwork(doc, n);
    writeLadder(doc);
    model::Body body = model::Body::withLanguage(model::BodyLanguage::LD);
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
    model::ProjectModel projectModel;
    projectModel.reset(bigProject());
    const model::BodyRef ref {projectModel.project().types.pous.front().id};
    std::printf("LD body: %d networks, %zu elements\n", kNetworks, projectModel.body(ref)->elements()->size());

    QUndoStack stack;
    QElapsedTimer timer;
    timer.start();
    LdEditor editor(projectModel, ref, &stack);
    editor.resize(1200, 800);
    editor.show();
    app.processEvents();
    std::printf("open in the editor:              %8.1f ms   (goal < 500 ms)\n", ms(timer));

    const auto command = [&](int network, const char *where) {
        const quint64 first = editor.document().networks[std::size_t(network)].members.empty()
            ? 0
            : rungElements(editor.document().networks[std::size_t(network)].rung).front();
        editor.setCursor(LdCursor::atElement(network, first));
        double best = 1e9;
        for (int round = 0; round < 5; ++round) {
            timer.restart();
            editor.insertContact();
            if (auto *field = editor.inPlaceEditor())
                field->cancel();
            app.processEvents();
            best = std::min(best, ms(timer));
            stack.undo();
            app.processEvents();
            editor.setCursor(LdCursor::atElement(network, first));
        }
        std::printf("insert a contact at the %s network: %6.1f ms   (goal < 30 ms)\n", where, best);
    };
    command(kNetworks - 1, "last ");
    command(0, "first");

    // Online: the visible networks' variables change every frame.
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
    std::printf("online repaint (%lld names):       %6.1f ms mean, %.1f ms worst   (goal < 10 ms)\n",
        static_cast<long long>(names.size()), total / kFrames, worst);
    editor.setOnlineSnapshot(nullptr);
    return 0;
}
