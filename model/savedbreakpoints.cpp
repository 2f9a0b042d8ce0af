#include "model/savedbreakpoints.h"

#include <QStringList>

#include <pugixml.hpp>

#include <algorithm>

namespace iec::model {

namespace {

bool isEntry(const AddDataEntry &entry)
{
    return entry.name == QLatin1String(kBreakpointsAddDataName);
}

std::string utf8(const QString &text)
{
    return text.toStdString();
}

} // namespace

std::vector<SavedBreakpoint> savedBreakpoints(const Project &project)
{
    std::vector<SavedBreakpoint> breakpoints;
    const auto entry = std::ranges::find_if(project.addData, isEntry);
    if (entry == project.addData.end())
        return breakpoints;
    pugi::xml_document document;
    const std::string content = utf8(entry->content);
    if (!document.load_buffer(content.data(), content.size()))
        return breakpoints;
    for (pugi::xml_node node : document.child("breakpoints").children("breakpoint")) {
        SavedBreakpoint b;
        b.pou = QString::fromUtf8(node.attribute("pou").value());
        b.action = QString::fromUtf8(node.attribute("action").value());
        b.line = node.attribute("line").as_int(0);
        b.localId = node.attribute("localId").as_llong(-1);
        for (const QString &id : QString::fromUtf8(node.attribute("elements").value()).split(QLatin1Char(' '), Qt::SkipEmptyParts))
            if (bool ok = false; id.toLongLong(&ok) >= 0 && ok)
                b.elements.push_back(id.toLongLong());
        b.hitRule = std::clamp(node.attribute("hitRule").as_int(0), 0, 3);
        b.hitTarget = std::max(1, node.attribute("hitTarget").as_int(1));
        b.condition = QString::fromUtf8(node.attribute("condition").value());
        b.enabled = node.attribute("enabled").as_bool(true);
        if (!b.pou.isEmpty() && (b.line > 0 || b.localId >= 0))
            breakpoints.push_back(std::move(b));
    }
    return breakpoints;
}

void setSavedBreakpoints(Project &project, const std::vector<SavedBreakpoint> &breakpoints)
{
    std::erase_if(project.addData, isEntry);
    if (breakpoints.empty())
        return;
    pugi::xml_document document;
    pugi::xml_node root = document.append_child("breakpoints");
    for (const SavedBreakpoint &b : breakpoints) {
        pugi::xml_node node = root.append_child("breakpoint");
        node.append_attribute("pou") = utf8(b.pou).c_str();
        if (!b.action.isEmpty())
            node.append_attribute("action") = utf8(b.action).c_str();
        if (b.line > 0)
            node.append_attribute("line") = b.line;
        if (b.localId >= 0)
            node.append_attribute("localId") = static_cast<long long>(b.localId);
        if (!b.elements.empty()) {
            QStringList ids;
            for (const qint64 id : b.elements)
                ids << QString::number(id);
            node.append_attribute("elements") = utf8(ids.join(QLatin1Char(' '))).c_str();
        }
        if (b.hitRule != 0) {
            node.append_attribute("hitRule") = b.hitRule;
            node.append_attribute("hitTarget") = b.hitTarget;
        }
        if (!b.condition.isEmpty())
            node.append_attribute("condition") = utf8(b.condition).c_str();
        if (!b.enabled)
            node.append_attribute("enabled") = false;
    }
    struct Writer : pugi::xml_writer {
        std::string text;
        void write(const void *data, size_t size) override { text.append(static_cast<const char *>(data), size); }
    } writer;
    root.print(writer, "", pugi::format_raw);
    project.addData.push_back({QString::fromLatin1(kBreakpointsAddDataName), QStringLiteral("discard"), QString::fromStdString(writer.text)});
}

} // namespace iec::model
