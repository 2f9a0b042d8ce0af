#include "app/examples.h"

#include "model/plcopen/reader.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace iec::app {

QList<Example> Examples::list()
{
    QList<Example> examples;
    const QDir directory(QStringLiteral(":/examples"));
    for (const QFileInfo &file : directory.entryInfoList({QStringLiteral("*.xml")}, QDir::Files, QDir::Name)) {
        const model::plcopen::ReadResult read = model::plcopen::readProjectFile(file.filePath());
        const QString name = read.project.contentHeader.name;
        examples.append({file.filePath(), name.isEmpty() ? file.completeBaseName() : name});
    }
    std::ranges::sort(
        examples, [](const Example &a, const Example &b) { return QString::localeAwareCompare(a.title, b.title) < 0; });
    return examples;
}

} // namespace iec::app
