#include "model/sfcoptions.h"

#include <pugixml.hpp>

#include <algorithm>

namespace iec::model {

namespace {

// The entry's content is one element: <stepOptions simplified="true" entry="A" .../>.
constexpr const char *kElement = "stepOptions";

struct Attribute {
    const char *name;
    QString StepOptions::*field;
};

constexpr Attribute kTextAttributes[] = {
    {"entry", &StepOptions::entryAction},
    {"exit", &StepOptions::exitAction},
    {"active", &StepOptions::activeAction},
    {"minTime", &StepOptions::minTime},
    {"maxTime", &StepOptions::maxTime},
};

template<typename Data> auto findEntry(Data &data)
{
    return std::find_if(data.begin(), data.end(),
        [](const AddDataEntry &entry) { return entry.name == QLatin1String(kStepOptionsAddDataName); });
}

QString serialize(const StepOptions &options)
{
    pugi::xml_document document;
    pugi::xml_node node = document.append_child(kElement);
    if (options.simplified)
        node.append_attribute("simplified") = "true";
    for (const Attribute &attribute : kTextAttributes) {
        const QString &value = options.*attribute.field;
        if (!value.isEmpty())
            node.append_attribute(attribute.name) = value.toStdString().c_str();
    }
    struct Writer : pugi::xml_writer {
        std::string text;
        void write(const void *data, size_t size) override { text.append(static_cast<const char *>(data), size); }
    } writer;
    node.print(writer, "", pugi::format_raw);
    return QString::fromStdString(writer.text);
}

} // namespace

StepOptions stepOptions(const Step &step)
{
    StepOptions options;
    const auto entry = findEntry(step.addData);
    if (entry == step.addData.end())
        return options;
    pugi::xml_document document;
    const std::string content = entry->content.toStdString();
    if (!document.load_buffer(content.data(), content.size()))
        return options;
    const pugi::xml_node node = document.child(kElement);
    options.simplified = node.attribute("simplified").as_bool();
    for (const Attribute &attribute : kTextAttributes)
        options.*attribute.field = QString::fromUtf8(node.attribute(attribute.name).as_string());
    return options;
}

void setStepOptions(Step &step, const StepOptions &options)
{
    auto entry = findEntry(step.addData);
    if (options.isDefault()) {
        if (entry != step.addData.end())
            step.addData.erase(entry);
        return;
    }
    if (entry == step.addData.end()) {
        step.addData.push_back({QString::fromLatin1(kStepOptionsAddDataName), QStringLiteral("preserve"), {}});
        entry = std::prev(step.addData.end());
    }
    entry->content = serialize(options);
}

} // namespace iec::model
