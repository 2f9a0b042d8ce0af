#include "app/settings.h"

#include <QFontDatabase>
#include <QSettings>

namespace iec::app {

namespace {

const QString kUiLanguage = QStringLiteral("ui/language");
const QString kEditorFont = QStringLiteral("editor/font");
const QString kGridSize = QStringLiteral("diagram/gridSize");
const QString kAutosaveMinutes = QStringLiteral("project/autosaveMinutes");

constexpr int kMinGrid = 2;
constexpr int kMaxGrid = 100;
constexpr int kMaxAutosaveMinutes = 120;

} // namespace

Settings Settings::load(const QSettings &store)
{
    Settings settings;
    settings.editorFont = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    settings.uiLanguage = store.value(kUiLanguage).toString();
    if (store.contains(kEditorFont))
        settings.editorFont.fromString(store.value(kEditorFont).toString());
    // Values edited by hand in the settings file are clamped rather than trusted.
    settings.gridSize = std::clamp(store.value(kGridSize, settings.gridSize).toInt(), kMinGrid, kMaxGrid);
    settings.autosaveMinutes
        = std::clamp(store.value(kAutosaveMinutes, settings.autosaveMinutes).toInt(), 0, kMaxAutosaveMinutes);
    return settings;
}

void Settings::save(QSettings &store) const
{
    store.setValue(kUiLanguage, uiLanguage);
    store.setValue(kEditorFont, editorFont.toString());
    store.setValue(kGridSize, gridSize);
    store.setValue(kAutosaveMinutes, autosaveMinutes);
}

QList<UiLanguage> availableUiLanguages()
{
    // Language names are written in their own language on purpose: a user who cannot read the
    // current UI language must still find their own.
    return {
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("zh_CN"), QStringLiteral("简体中文")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
    };
}

} // namespace iec::app
