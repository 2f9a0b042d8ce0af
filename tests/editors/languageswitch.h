#pragma once

// A UI language switch that a test can see: every text in brackets ("[Zoom In]"), installed and
// removed as the app's translator is, with the LanguageChange it posts delivered at once.
#include <QCoreApplication>
#include <QEvent>
#include <QTranslator>

namespace iec::tests {

class BracketTranslator : public QTranslator
{
public:
    QString translate(const char *, const char *sourceText, const char *, int) const override
    {
        return QStringLiteral("[%1]").arg(QString::fromUtf8(sourceText));
    }
    bool isEmpty() const override { return false; }
};

// Installs `install` and/or removes `remove`, then delivers the LanguageChange.
inline void switchLanguage(QTranslator *install, QTranslator *remove)
{
    if (install)
        QCoreApplication::installTranslator(install);
    if (remove)
        QCoreApplication::removeTranslator(remove);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

} // namespace iec::tests
