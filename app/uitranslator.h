#pragma once

#include <QLocale>
#include <QObject>

class QTranslator;

namespace iec::app {

// Installs IEC Studio's own translation and Qt's for one UI language, replacing the previous
// ones; installing sends LanguageChange to every widget, so open windows retranslate themselves.
class UiTranslator : public QObject
{
    Q_OBJECT

public:
    explicit UiTranslator(QObject *parent = nullptr);

    // Returns false when IEC Studio has no translation for the locale (English is then shown).
    bool apply(const QLocale &locale);

private:
    void removeInstalled();

    QTranslator *m_appTranslator = nullptr;
    QTranslator *m_qtTranslator = nullptr;
};

} // namespace iec::app
