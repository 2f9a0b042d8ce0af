#include "app/uitranslator.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

namespace iec::app {

UiTranslator::UiTranslator(QObject *parent)
    : QObject(parent)
    , m_appTranslator(new QTranslator(this))
    , m_qtTranslator(new QTranslator(this))
{
}

bool UiTranslator::apply(const QLocale &locale)
{
    removeInstalled();
    // qt_add_translations embeds the .qm files under :/i18n.
    const bool appLoaded = m_appTranslator->load(locale, QStringLiteral("iecstudio"), QStringLiteral("_"),
                                                 QStringLiteral(":/i18n"));
    if (appLoaded)
        QCoreApplication::installTranslator(m_appTranslator);
    // Qt's own strings (standard dialog buttons) come from the system's qt6-translations-l10n.
    if (m_qtTranslator->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                             QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(m_qtTranslator);
    return appLoaded;
}

void UiTranslator::removeInstalled()
{
    QCoreApplication::removeTranslator(m_appTranslator);
    QCoreApplication::removeTranslator(m_qtTranslator);
}

} // namespace iec::app
