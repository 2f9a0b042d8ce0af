#include "model/savedtrace.h"

#include <pugixml.hpp>

#include <algorithm>

namespace iec::model {

namespace {

bool isEntry(const AddDataEntry &entry)
{
    return entry.name == QLatin1String(kTraceAddDataName);
}

QString text(const pugi::xml_attribute &attribute)
{
    return QString::fromUtf8(attribute.value());
}

} // namespace

std::optional<SavedTrace> savedTrace(const Project &project)
{
    const auto entry = std::ranges::find_if(project.addData, isEntry);
    if (entry == project.addData.end())
        return std::nullopt;
    pugi::xml_document document;
    const std::string content = entry->content.toStdString();
    if (!document.load_buffer(content.data(), content.size()))
        return std::nullopt;
    const pugi::xml_node root = document.child("trace");
    if (!root)
        return std::nullopt;
    SavedTrace trace;
    for (pugi::xml_node node : root.children("variable")) {
        const QString name = text(node.attribute("name"));
        if (name.isEmpty())
            continue;
        trace.variables << name;
        if (node.attribute("hidden").as_bool(false))
            trace.hidden << name;
    }
    trace.everyCycles = std::clamp(root.attribute("everyCycles").as_int(1), 1, 1'000'000);
    trace.capacity = std::clamp(root.attribute("capacity").as_int(10'000), 2, 10'000'000);
    trace.historyScans = std::clamp(root.attribute("historyScans").as_int(1000), 1, 1'000'000);
    if (const pugi::xml_node trigger = root.child("trigger")) {
        trace.trigger = std::clamp(trigger.attribute("kind").as_int(0), 0, 3);
        trace.triggerVariable = text(trigger.attribute("variable"));
        trace.triggerLevel = trigger.attribute("level").as_double(0.5);
        trace.samplesAfterTrigger = std::clamp(trigger.attribute("after").as_int(100), 0, 10'000'000);
    }
    trace.recordCondition = text(root.child("condition").attribute("text"));
    return trace;
}

void setSavedTrace(Project &project, const SavedTrace &trace)
{
    std::erase_if(project.addData, isEntry);
    if (trace == SavedTrace())
        return;
    pugi::xml_document document;
    pugi::xml_node root = document.append_child("trace");
    root.append_attribute("everyCycles") = trace.everyCycles;
    root.append_attribute("capacity") = trace.capacity;
    root.append_attribute("historyScans") = trace.historyScans;
    for (const QString &name : trace.variables) {
        pugi::xml_node node = root.append_child("variable");
        node.append_attribute("name") = name.toStdString().c_str();
        if (trace.hidden.contains(name))
            node.append_attribute("hidden") = true;
    }
    if (trace.trigger != 0) {
        pugi::xml_node trigger = root.append_child("trigger");
        trigger.append_attribute("kind") = trace.trigger;
        trigger.append_attribute("variable") = trace.triggerVariable.toStdString().c_str();
        trigger.append_attribute("level") = trace.triggerLevel;
        trigger.append_attribute("after") = trace.samplesAfterTrigger;
    }
    if (!trace.recordCondition.isEmpty())
        root.append_child("condition").append_attribute("text") = trace.recordCondition.toStdString().c_str();
    struct Writer : pugi::xml_writer {
        std::string text;
        void write(const void *data, size_t size) override { text.append(static_cast<const char *>(data), size); }
    } writer;
    root.print(writer, "", pugi::format_raw);
    project.addData.push_back({QString::fromLatin1(kTraceAddDataName), QStringLiteral("discard"), QString::fromStdString(writer.text)});
}

} // namespace iec::model
