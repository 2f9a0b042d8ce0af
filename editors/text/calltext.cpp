#include "editors/text/calltext.h"

#include <QMimeData>

namespace iec::editors {

namespace {

QStringList assignments(const QStringList &names, const char *arrow)
{
    QStringList result;
    for (const QString &name : names)
        result << name + QLatin1Char(' ') + QLatin1String(arrow) + QLatin1Char(' ');
    return result;
}

} // namespace

QString callText(TextLanguage language, const CallSignature &signature)
{
    QStringList parameters = assignments(signature.inputs, ":=");
    const QString callee = signature.functionBlock ? signature.name + QStringLiteral("_1") : signature.name;
    if (language == TextLanguage::IL) {
        const QString call = callee + QLatin1Char('(') + parameters.join(QStringLiteral(", ")).trimmed() + QLatin1Char(')');
        return signature.functionBlock ? QStringLiteral("CAL ") + call : call;
    }
    if (signature.functionBlock)
        parameters += assignments(signature.outputs, "=>");
    const QString call = callee + QLatin1Char('(') + parameters.join(QStringLiteral(", ")).trimmed() + QLatin1Char(')');
    return signature.functionBlock ? call + QLatin1Char(';') : call;
}

QString mimeCallMimeType(TextLanguage language)
{
    return QString::fromLatin1(language == TextLanguage::IL ? kIlCallMimeType : kStCallMimeType);
}

QMimeData *pouMimeData(const CallSignature &signature)
{
    auto *data = new QMimeData;
    data->setData(QString::fromLatin1(kPouMimeType), signature.name.toUtf8());
    data->setData(QString::fromLatin1(kStCallMimeType), callText(TextLanguage::ST, signature).toUtf8());
    data->setData(QString::fromLatin1(kIlCallMimeType), callText(TextLanguage::IL, signature).toUtf8());
    data->setText(callText(TextLanguage::ST, signature));
    return data;
}

} // namespace iec::editors
