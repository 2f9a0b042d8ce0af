#include "app/mainwindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>

int main(int argc, char *argv[])
{
    QApplication application(argc, argv);
    QApplication::setApplicationName(QStringLiteral("IEC Studio"));
    QApplication::setOrganizationName(QStringLiteral("IEC Studio"));
    QApplication::setApplicationVersion(QStringLiteral(IECSTUDIO_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("IEC 61131-3 development environment"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("project"), QStringLiteral("PLCopen XML project (or IEC 61131-3 text, .st) to open."));
    parser.process(application);

    iec::app::MainWindow window;
    window.show();
    // A recovered project takes the window; the project named on the command line waits.
    window.offerRecoveryInteractive();
    if (!parser.positionalArguments().isEmpty() && !window.hasUnsavedChanges()) {
        QString error;
        if (!window.openProject(parser.positionalArguments().constFirst(), &error))
            QMessageBox::critical(&window, QApplication::translate("main", "Open Project"), error);
    }
    return QApplication::exec();
}
