#include "app/cli/commands.h"
#include "app/cli/render.h"

#include <QCoreApplication>

#include <cstdio>
#include <cstring>

int main(int argc, char *argv[])
{
    // render draws with the editors and needs a GUI application object instead.
    if (argc > 1 && std::strcmp(argv[1], "render") == 0)
        return iec::cli::renderMain(argc, argv);
    QCoreApplication application(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("iecstudio-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(IECSTUDIO_VERSION));

    QTextStream out(stdout);
    QTextStream err(stderr);
    QStringList arguments = QCoreApplication::arguments().mid(1);
    if (arguments.isEmpty()) {
        iec::cli::printUsage(err);
        return iec::cli::ExitUsage;
    }
    const QString first = arguments.takeFirst();
    if (first == QLatin1String("-h") || first == QLatin1String("--help") || first == QLatin1String("help"))
        return iec::cli::printUsage(out);
    if (first == QLatin1String("-v") || first == QLatin1String("--version")) {
        out << "iecstudio-cli " << QCoreApplication::applicationVersion() << "\n";
        return iec::cli::ExitOk;
    }
    for (const iec::cli::Command &command : iec::cli::commands()) {
        if (first == QLatin1String(command.name))
            return command.run(arguments, {out, err});
    }
    err << "iecstudio-cli: unknown command '" << first << "'. Run 'iecstudio-cli --help' for the list.\n";
    return iec::cli::ExitUsage;
}
