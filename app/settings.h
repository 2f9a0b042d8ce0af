#pragma once

#include <QFont>
#include <QString>

class QSettings;

namespace iec::app {

// The user's preferences, read from and written to QSettings under fixed keys. A plain value so
// the settings dialog edits a copy and the window applies the result in one go.
struct Settings {
    // "" follows the system locale; otherwise a locale name such as "de" or "zh_CN".
    QString uiLanguage;
    QFont editorFont;
    int gridSize = 10;
    // 0 turns autosave off.
    int autosaveMinutes = 5;

    static Settings load(const QSettings &store);
    void save(QSettings &store) const;

    bool operator==(const Settings &) const = default;
};

// The UI languages IEC Studio ships, as (locale name, name of the language in itself).
struct UiLanguage {
    QString localeName;
    QString nativeName;
};
QList<UiLanguage> availableUiLanguages();

} // namespace iec::app
