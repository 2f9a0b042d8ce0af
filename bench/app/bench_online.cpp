// bench_online: the window online with 200 watched variables and a 1 ms cycle at full speed.
// Measures the UI thread's event-loop latency: a 10 ms timer records how late each tick comes
// (max and p99 over a few seconds; target under 50 ms), and prints the cycles run meanwhile and
// the snapshots the window received.
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/online/onlinecontroller.h"
#include "app/online/watchpane.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>

using namespace iec;

namespace {

constexpr int kVariables = 200;
constexpr int kTickMs = 10;

QString programSource()
{
    QString declarations;
    QString body;
    for (int i = 0; i < kVariables; ++i) {
        declarations += QStringLiteral("  V%1 : DINT;\n").arg(i);
        body += QStringLiteral("V%1 := V%1 + %2;\n").arg(i).arg(i % 7 + 1);
    }
    return QStringLiteral("PROGRAM Main\nVAR\n%1END_VAR\n%2END_PROGRAM\n").arg(declarations, body);
}

struct Latency {
    double maxMs = 0;
    double p99Ms = 0;
    double meanMs = 0;
    int ticks = 0;
};

// Runs the event loop for `seconds` with a 10 ms timer and returns how late its ticks were.
Latency measure(double seconds)
{
    std::vector<double> late;
    QElapsedTimer clock;
    clock.start();
    qint64 previous = clock.nsecsElapsed();
    QTimer tick;
    tick.setTimerType(Qt::PreciseTimer);
    QObject::connect(&tick, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        late.push_back(std::max(0.0, double(now - previous) / 1e6 - kTickMs));
        previous = now;
    });
    tick.start(kTickMs);
    QEventLoop loop;
    QTimer::singleShot(int(seconds * 1000), &loop, &QEventLoop::quit);
    loop.exec();
    tick.stop();
    Latency result;
    result.ticks = int(late.size());
    if (late.empty())
        return result;
    std::sort(late.begin(), late.end());
    result.maxMs = late.back();
    result.p99Ms = late[std::min(late.size() - 1, size_t(double(late.size()) * 0.99))];
    double sum = 0;
    for (double value : late)
        sum += value;
    result.meanMs = sum / double(late.size());
    return result;
}

} // namespace

int main(int argc, char *argv[])
{
    qputenv("QT_QPA_PLATFORM", qgetenv("QT_QPA_PLATFORM").isEmpty() ? QByteArray("offscreen") : qgetenv("QT_QPA_PLATFORM"));
    QApplication application(argc, argv);
    QTemporaryDir config;
    qputenv("XDG_CONFIG_HOME", config.path().toLocal8Bit());
    const double seconds = argc > 1 ? QString::fromLocal8Bit(argv[1]).toDouble() : 3.0;

    app::MainWindow window;
    window.resize(1280, 800);
    window.show();
    window.projectModel().reset(interp::frontend::readIecText(programSource(), QStringLiteral("Bench")).project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}}); // its values show too
    for (int i = 0; i < kVariables; ++i)
        window.watchPane().addVariable(QStringLiteral("Main.V%1").arg(i));

    const Latency offline = measure(1.0);
    std::printf("offline (idle window):   ticks %4d  max %6.2f ms  p99 %6.2f ms  mean %5.2f ms\n", offline.ticks,
                offline.maxMs, offline.p99Ms, offline.meanMs);

    app::OnlineController &online = window.online();
    online.setCycleTime(1'000'000);
    online.setSpeed(app::RunSpeed::AsFastAsPossible);
    int snapshots = 0;
    QObject::connect(&online, &app::OnlineController::snapshotShown, [&snapshots] { ++snapshots; });
    QElapsedTimer wall;
    wall.start();
    online.loginAndRun();
    if (!online.isOnline()) {
        std::fprintf(stderr, "login failed\n");
        return 1;
    }
    const Latency running = measure(seconds);
    const double elapsed = double(wall.nsecsElapsed()) / 1e9;
    const int cycles = online.latestSnapshot() ? online.latestSnapshot()->cycle : 0;
    std::printf("online, %d watched, 1 ms cycle, full speed, %.1f s:\n", kVariables, seconds);
    std::printf("  UI latency: ticks %4d  max %6.2f ms  p99 %6.2f ms  mean %5.2f ms  (target: max < 50 ms)\n",
                running.ticks, running.maxMs, running.p99Ms, running.meanMs);
    std::printf("  cycles run: %d (%.0f per second), snapshots shown: %d (%.1f per second)\n", cycles,
                cycles / elapsed, snapshots, snapshots / elapsed);
    QElapsedTimer logout;
    logout.start();
    online.logout();
    std::printf("  logout took %.1f ms\n", double(logout.nsecsElapsed()) / 1e6);
    return running.maxMs < 50 ? 0 : 2;
}
