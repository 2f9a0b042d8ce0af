#include "app/mainwindow.h"
#include "app/uitranslator.h"

#include <QApplication>
#include <QCommandLineParser>

int main(int argc, char *argv[])
{
    QApplication application(argc, argv);
    QApplication::setApplicationName(QStringLiteral("IEC Studio"));
    QApplication::setOrganizationName(QStringLiteral("IEC Studio"));
    QApplication::setApplicationVersion(QStringLiteral(IECSTUDIO_VERSION));

    iec::app::UiTranslator translator;
    translator.apply(QLocale::system());

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "IEC 61131-3 development environment"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("project"),
                                 QApplication::translate("main", "PLCopen XML project to open."));
    parser.process(application);

    iec::app::MainWindow window;
    window.show();
    return QApplication::exec();
}
