// iecstudio-cli render FILE --pou NAME OUT.svg|OUT.png|OUT.pdf: a POU body drawn as the editor
// draws it, without a display. Built into its own library (iec_cli_render) because it loads the
// editors; the rest of the CLI stays free of GUI code.

#include "app/cli/commands.h"
#include "app/cli/projectinput.h"
#include "app/cli/render.h"
#include "model/statistics.h"

#include "editors/common/diagramexport.h"
#include "editors/common/diagramscene.h"
#include "editors/sfc/sfcscene.h"
#include "model/body.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QFileInfo>

#include <cstdio>

namespace iec::cli {

namespace {

struct RenderArguments {
    QString file;
    QString pou;
    QString out;
};

std::optional<RenderArguments> parse(const QStringList &arguments, QTextStream &err)
{
    RenderArguments result;
    QStringList positional;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &argument = arguments[i];
        if (argument == QLatin1String("--pou")) {
            if (i + 1 >= arguments.size()) {
                err << "iecstudio-cli: render: --pou needs the name of a POU.\n";
                return std::nullopt;
            }
            result.pou = arguments[++i];
        } else if (argument.startsWith(QLatin1String("--pou="))) {
            result.pou = argument.mid(6);
        } else if (argument.startsWith(QLatin1String("-"))) {
            err << "iecstudio-cli: render: unknown option '" << argument << "'.\n";
            return std::nullopt;
        } else {
            positional << argument;
        }
    }
    if (positional.size() != 2 || result.pou.isEmpty()) {
        err << "Usage: iecstudio-cli render FILE --pou NAME OUT.svg|OUT.png|OUT.pdf\n";
        return std::nullopt;
    }
    result.file = positional[0];
    result.out = positional[1];
    const QString suffix = QFileInfo(result.out).suffix().toLower();
    if (suffix != QLatin1String("svg") && suffix != QLatin1String("png") && suffix != QLatin1String("pdf")) {
        err << "iecstudio-cli: render: " << result.out << ": the picture must end in .svg, .png or .pdf.\n";
        return std::nullopt;
    }
    return result;
}

} // namespace

int runRender(const QStringList &arguments, Io io)
{
    const std::optional<RenderArguments> args = parse(arguments, io.err);
    if (!args)
        return ExitUsage;
    if (!qobject_cast<QApplication *>(QCoreApplication::instance())) {
        io.err << "iecstudio-cli: render: needs the GUI libraries (run it as 'iecstudio-cli render ...').\n";
        return ExitFailed;
    }
    LoadedProject loaded = loadProject(args->file, io.err);
    if (loaded.status != ExitOk)
        return loaded.status;
    const model::Pou *pou = loaded.project.findPou(args->pou);
    if (!pou) {
        io.err << "iecstudio-cli: render: " << args->file << " has no POU named '" << args->pou << "'.\n";
        return ExitUsage;
    }
    const model::Body *body = pou->body();
    if (!body || body->language() != model::BodyLanguage::SFC) {
        io.err << "iecstudio-cli: render: POU '" << pou->name << "' is written in "
               << model::bodyLanguageName(body ? body->language() : model::BodyLanguage::ST)
               << ", which cannot be drawn yet (SFC can).\n";
        return ExitFailed;
    }
    const model::PouId id = pou->id; // `pou` points into the project moved below
    model::ProjectModel projectModel;
    projectModel.reset(std::move(loaded.project));
    editors::sfc::SfcPolicy policy;
    editors::DiagramScene scene(projectModel, model::BodyRef {id}, policy);
    scene.rebuild();
    const QString problem = editors::exportScene(scene, args->out);
    if (!problem.isEmpty()) {
        io.err << "iecstudio-cli: render: " << problem << "\n";
        return ExitIoError;
    }
    return ExitOk;
}

namespace {

// Qt's own warnings (fonts, runtime directories of the offscreen platform) say nothing about the
// drawing; the command's messages go to stderr through its own stream.
void quietQtWarnings(QtMsgType type, const QMessageLogContext &, const QString &message)
{
    if (type == QtCriticalMsg || type == QtFatalMsg)
        std::fprintf(stderr, "%s\n", qPrintable(message));
}

} // namespace

int renderMain(int argc, char *argv[])
{
    qInstallMessageHandler(quietQtWarnings);
    // No display needed: draw offscreen unless the caller chose a platform.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication application(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("iecstudio-cli"));
    QTextStream out(stdout);
    QTextStream err(stderr);
    return runRender(QCoreApplication::arguments().mid(2), {out, err});
}

} // namespace iec::cli
