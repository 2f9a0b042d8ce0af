#include "editors/common/diagramonline.h"

#include "editors/text/onlinevalues.h"

#include <QRegularExpression>

namespace iec::editors {

bool isVariablePath(const QString &text)
{
    static const QRegularExpression path(
        QStringLiteral(R"(^(%[IQM][XBWDL]?\d+(\.\d+)*|[A-Za-z_]\w*(\.[A-Za-z_]\w*|\[\d+\])*)$)"));
    return path.match(text.trimmed()).hasMatch();
}

bool isTrueLiteral(const QString &literal)
{
    return literal.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0;
}

QHash<QString, QString> instancePinNames(const model::Block &block, const QString &instance)
{
    QHash<QString, QString> names;
    if (!block.instanceName || !isVariablePath(*block.instanceName))
        return names;
    for (const auto *list : {&block.inputVariables, &block.inOutVariables, &block.outputVariables})
        for (const model::BlockVariable &pin : *list)
            if (pin.formalParameter.compare(QLatin1String("EN"), Qt::CaseInsensitive) != 0
                && pin.formalParameter.compare(QLatin1String("ENO"), Qt::CaseInsensitive) != 0)
                names.insert(pin.formalParameter.toUpper(), onlineName(instance, *block.instanceName + QLatin1Char('.') + pin.formalParameter));
    return names;
}

} // namespace iec::editors
