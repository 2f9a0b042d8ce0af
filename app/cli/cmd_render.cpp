// iecstudio-cli render FILE --pou NAME [--action A | --transition T] OUT.svg|OUT.png|OUT.pdf: a
// graphical body drawn as its editor draws it, without a display. Built into its own library (iec_cli_render) because it loads the
// editors; the rest of the CLI stays free of GUI code.

#include "app/cli/commands.h"
#include "app/cli/projectinput.h"
#include "app/cli/render.h"
#include "model/statistics.h"

#include "editors/common/diagramexport.h"
#include "editors/common/diagramscene.h"
#include "editors/common/editorregistry.h"
#include "editors/standardeditors.h"
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
    model::BodyRef::Part part = model::BodyRef::Part::Pou;
    QString partName; // the action or transition
    QString out;
};

const char *const kUsage = "Usage: iecstudio-cli render FILE --pou NAME [--action NAME | --transition NAME] "
                           "OUT.svg|OUT.png|OUT.pdf\n";

// "--pou NAME" or "--pou=NAME"; false (and a message) when the name is missing.
bool takeValue(const QStringList &arguments, qsizetype &i, const QString &option, QString &value, QTextStream &err,
    const char *what)
{
    const QString &argument = arguments[i];
    if (argument.startsWith(option + QLatin1Char('='))) {
        value = argument.mid(option.size() + 1);
        return true;
    }
    if (i + 1 >= arguments.size()) {
        err << "iecstudio-cli: render: " << option << " needs the name of " << what << ".\n";
        return false;
    }
    value = arguments[++i];
    return true;
}

std::optional<RenderArguments> parse(const QStringList &arguments, QTextStream &err)
{
    RenderArguments result;
    QStringList positional;
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &argument = arguments[i];
        const QString option = argument.section(QLatin1Char('='), 0, 0);
        if (option == QLatin1String("--pou")) {
            if (!takeValue(arguments, i, option, result.pou, err, "a POU"))
                return std::nullopt;
        } else if (option == QLatin1String("--action") || option == QLatin1String("--transition")) {
            const bool action = option == QLatin1String("--action");
            if (!result.partName.isEmpty()) {
                err << "iecstudio-cli: render: give one --action or --transition.\n";
                return std::nullopt;
            }
            if (!takeValue(arguments, i, option, result.partName, err, action ? "an action" : "a transition"))
                return std::nullopt;
            result.part = action ? model::BodyRef::Part::Action : model::BodyRef::Part::Transition;
        } else if (argument.startsWith(QLatin1String("-"))) {
            err << "iecstudio-cli: render: unknown option '" << argument << "'.\n";
            return std::nullopt;
        } else {
            positional << argument;
        }
    }
    if (positional.size() != 2 || result.pou.isEmpty()) {
        err << kUsage;
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
    const QString pouName = pou->name; // `pou` points into the project moved below
    model::ProjectModel projectModel;
    projectModel.reset(std::move(loaded.project));
    // The model numbers the POUs as it takes them: look the POU up there.
    const model::BodyRef ref {projectModel.project().findPou(pouName)->id, args->part, args->partName};
    const model::Body *body = projectModel.body(ref);
    if (!body) {
        io.err << "iecstudio-cli: render: POU '" << pouName << "' has no "
               << (args->part == model::BodyRef::Part::Action ? "action" : "transition") << " named '" << args->partName
               << "'.\n";
        return ExitUsage;
    }
    editors::registerStandardEditors();
    const editors::EditorLanguage language = editors::editorLanguage(*body);
    const editors::EditorFactory *factory = editors::EditorRegistry::instance().find(language);
    if (!factory) {
        const QString what = args->part == model::BodyRef::Part::Pou ? QStringLiteral("POU '%1'").arg(pouName)
            : QStringLiteral("%1 '%2.%3'")
                  .arg(args->part == model::BodyRef::Part::Action ? QStringLiteral("Action") : QStringLiteral("Transition"),
                      pouName, args->partName);
        QStringList drawable;
        for (const editors::EditorLanguage known : editors::EditorRegistry::instance().languages())
            drawable << editors::editorLanguageName(known);
        io.err << "iecstudio-cli: render: " << what << " is written in " << editors::editorLanguageName(language)
               << ", which cannot be drawn yet (" << drawable.join(QStringLiteral(", ")) << " can).\n";
        return ExitFailed;
    }
    const std::unique_ptr<editors::DiagramPolicy> policy = factory->createPolicy();
    editors::DiagramScene scene(projectModel, ref, *policy);
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
