#include "model/plcopen/writer.h"

#include "model/plcopen/schema_project.h"
#include "model/savefile.h"

#include <algorithm>

namespace iec::model::plcopen {

namespace {

struct ByteWriter : pugi::xml_writer {
    QByteArray bytes;
    void write(const void *data, size_t size) override
    {
        bytes.append(static_cast<const char *>(data), qsizetype(size));
    }
};

WriteContext slotsOf(const Project &project)
{
    WriteContext context;
    for (const Pou &pou : project.types.pous) {
        if (pou.addDataSlot != 0)
            context.slotPous.emplace(pou.addDataSlot, &pou);
    }
    for (const DataTypeDecl &type : project.types.dataTypes) {
        if (type.addDataSlot != 0)
            context.slotDataTypes.emplace(type.addDataSlot, &type);
    }
    return context;
}

// A vendor POU whose addData entry is gone is written with the ordinary ones: never lose a POU.
void writeOrphans(pugi::xml_node root, WriteContext &context)
{
    const auto written
        = [&](quint32 slot) { return std::ranges::find(context.writtenSlots, slot) != context.writtenSlots.end(); };
    pugi::xml_node types = root.child("types");
    XmlOut dataTypes(types.child("dataTypes"), context);
    for (const auto &[slot, type] : std::map(context.slotDataTypes.begin(), context.slotDataTypes.end())) {
        if (!written(slot))
            dataTypes.child("dataType", *type);
    }
    XmlOut pous(types.child("pous"), context);
    for (const auto &[slot, pou] : std::map(context.slotPous.begin(), context.slotPous.end())) {
        if (!written(slot))
            pous.child("pou", *pou);
    }
}

bool usesPrefix(const Extras &extras, const char *prefix)
{
    return std::ranges::any_of(
        extras.attributes, [prefix](const UnknownAttribute &a) { return a.name.startsWith(QLatin1String(prefix)); });
}

} // namespace

QByteArray writeProject(const Project &project)
{
    pugi::xml_document document;
    pugi::xml_node root = document.append_child("project");
    root.append_attribute("xmlns").set_value(kTc6Namespace);
    root.append_attribute("xmlns:xhtml").set_value(kXhtmlNamespace);
    if (usesPrefix(project.extras, "xsi:"))
        root.append_attribute("xmlns:xsi").set_value("http://www.w3.org/2001/XMLSchema-instance");

    WriteContext context = slotsOf(project);
    XmlOut out(root, context);
    Schema<Project>::describe(out, project);
    writeOrphans(root, context);

    ByteWriter writer;
    // Indentation grows with depth, so a hostile, deeply nested opaque subtree would make indented
    // output quadratic in size; such documents are written without indentation (still deterministic).
    constexpr int kMaxIndentedDepth = 256;
    const bool indent = !nestsDeeperThan(document, kMaxIndentedDepth);
    document.save(writer, "  ", indent ? pugi::format_indent : pugi::format_raw, pugi::encoding_utf8);
    return writer.bytes;
}

bool saveProjectFile(const Project &project, const QString &path, QString *error)
{
    if (!project.fileHeader.creationDateTime.isEmpty())
        return saveFileAtomically(path, writeProject(project), error);
    Project stamped = project;
    stampCreationTime(stamped.fileHeader, QDateTime::currentDateTimeUtc());
    return saveFileAtomically(path, writeProject(stamped), error);
}

void stampCreationTime(FileHeader &header, const QDateTime &now)
{
    if (header.creationDateTime.isEmpty())
        header.creationDateTime = now.toUTC().toString(Qt::ISODate);
}

} // namespace iec::model::plcopen
