#pragma once

#include <QCoreApplication>
#include <QSettings>
#include <QTemporaryDir>

// The window tests keep the user's settings out: settings in a temporary folder, a test
// organisation, English.
inline void useTestSettings(const QTemporaryDir &home)
{
    qputenv("XDG_CONFIG_HOME", home.path().toLocal8Bit());
    QCoreApplication::setOrganizationName(QStringLiteral("IEC Studio Tests"));
    QSettings().setValue(QStringLiteral("ui/language"), QStringLiteral("en"));
}
