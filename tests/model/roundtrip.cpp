#include "roundtrip.h"

#include "model/plcopen/writer.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTextStream>

namespace iec::test {

using namespace model;

QString schemaErrors(const QByteArray &xml)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("out.xml"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(xml) != xml.size())
        return QStringLiteral("cannot write %1").arg(path);
    file.close();
    QProcess xmllint;
    xmllint.start(QStringLiteral("xmllint"),
        {QStringLiteral("--noout"), QStringLiteral("--nonet"), QStringLiteral("--schema"),
            QStringLiteral(IEC_SHARED_DIR "/plcopen/tc6_xml_v201.xsd"), path});
    if (!xmllint.waitForFinished(60000))
        return QStringLiteral("xmllint did not run: %1").arg(xmllint.errorString());
    if (xmllint.exitStatus() == QProcess::NormalExit && xmllint.exitCode() == 0)
        return {};
    return QString::fromUtf8(xmllint.readAllStandardError()).left(3000);
}

QString savedSchemaErrors(const Project &project)
{
    Project saved = project; // saveProjectFile stamps a missing creation time the same way
    plcopen::stampCreationTime(saved.fileHeader, QDateTime::currentDateTimeUtc());
    return schemaErrors(plcopen::writeProject(saved));
}

namespace {

template<class T> QString compareVectors(const QString &what, const std::vector<T> &a, const std::vector<T> &b)
{
    if (a.size() != b.size())
        return QStringLiteral("%1: %2 vs %3 entries").arg(what).arg(a.size()).arg(b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!(a[i] == b[i]))
            return QStringLiteral("%1[%2] differs").arg(what).arg(i);
    }
    return {};
}

QString compareBodies(const QString &where, const Body &a, const Body &b)
{
    if (a.content.index() != b.content.index())
        return where + QStringLiteral(": language");
    if (a.text() != b.text())
        return where + QStringLiteral(": text");
    if (a.elements() && b.elements()) {
        if (QString d = compareVectors(where + QStringLiteral(" element"), *a.elements(), *b.elements()); !d.isEmpty())
            return d;
    }
    if (a.layoutGenerated != b.layoutGenerated)
        return where + QStringLiteral(": layoutGenerated");
    if (!(a.addData == b.addData))
        return where + QStringLiteral(": addData");
    return a == b ? QString() : where + QStringLiteral(": other body fields");
}

} // namespace

QString firstDifference(const Project &a, const Project &b)
{
    if (!(a.fileHeader == b.fileHeader))
        return QStringLiteral("fileHeader");
    if (!(a.contentHeader == b.contentHeader))
        return QStringLiteral("contentHeader");
    if (QString d = compareVectors(QStringLiteral("dataTypes"), a.types.dataTypes, b.types.dataTypes); !d.isEmpty())
        return d;
    if (a.types.pous.size() != b.types.pous.size())
        return QStringLiteral("pou count %1 vs %2").arg(a.types.pous.size()).arg(b.types.pous.size());
    for (std::size_t i = 0; i < a.types.pous.size(); ++i) {
        const Pou &p = a.types.pous[i];
        const Pou &q = b.types.pous[i];
        if (p == q)
            continue;
        const QString where = QStringLiteral("pou %1").arg(p.name);
        if (p.bodies.size() != q.bodies.size())
            return where + QStringLiteral(": body count");
        for (std::size_t k = 0; k < p.bodies.size(); ++k) {
            if (QString d = compareBodies(where, p.bodies[k], q.bodies[k]); !d.isEmpty())
                return d;
        }
        if (!(p.pouInterface == q.pouInterface))
            return where + QStringLiteral(": interface");
        if (!(p.actions == q.actions))
            return where + QStringLiteral(": actions");
        if (!(p.transitions == q.transitions))
            return where + QStringLiteral(": transitions");
        return where + QStringLiteral(": other fields");
    }
    if (!(a.instances == b.instances))
        return QStringLiteral("instances");
    if (!(a.addData == b.addData))
        return QStringLiteral("project addData");
    return a == b ? QString() : QStringLiteral("project: other fields");
}

QString diagnosticsText(const std::vector<Diagnostic> &diagnostics)
{
    QString text;
    for (const Diagnostic &d : diagnostics)
        text += QStringLiteral("%1:%2: %3\n").arg(d.line).arg(d.column).arg(d.message);
    return text;
}

QString corpusPath(const QString &file)
{
    return QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + file;
}

} // namespace iec::test
