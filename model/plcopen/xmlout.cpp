// XmlOut: the writing archive, and the writer's handling of vendor addData.

#include "model/plcopen/schema_project.h"

#include <map>

namespace iec::model::plcopen {

void XmlOut::text(const char *name, const QString &value)
{
    m_node.append_child(name).text().set(toFileUtf8(value).constData());
}

void XmlOut::text(const char *name, const std::optional<QString> &value)
{
    if (value)
        text(name, *value);
}

void XmlOut::finish(const Extras &extras)
{
    for (const UnknownAttribute &attribute : extras.attributes) {
        // An attribute that was present but unparsable is written back as it was.
        const std::string name = attribute.name.toStdString();
        pugi::xml_attribute existing = m_node.attribute(name.c_str());
        if (!existing)
            existing = m_node.append_attribute(name.c_str());
        existing.set_value(toFileUtf8(attribute.value).constData());
    }
    // Each unknown element goes after the last known sibling it followed in the file.
    std::map<QString, pugi::xml_node> lastInserted;
    for (const UnknownElement &unknown : extras.elements) {
        pugi::xml_document fragment;
        const QByteArray bytes = toFileUtf8(unknown.xml);
        if (!fragment.load_buffer(
                bytes.constData(), bytes.size(),
                // As the reader parses (reader.cpp): an element holding only whitespace keeps it.
                pugi::parse_default | pugi::parse_ws_pcdata_single | pugi::parse_fragment, pugi::encoding_utf8))
            continue;
        pugi::xml_node after = lastInserted[unknown.anchor];
        if (!after && !unknown.anchor.isEmpty()) {
            const std::string anchor = unknown.anchor.toStdString();
            for (pugi::xml_node child = m_node.first_child(); child; child = child.next_sibling()) {
                if (child.type() == pugi::node_element && hasLocalName(child, anchor.c_str()))
                    after = child;
            }
        }
        for (pugi::xml_node node = fragment.first_child(); node; node = node.next_sibling()) {
            if (after)
                after = m_node.insert_copy_after(node, after);
            else if (unknown.anchor.isEmpty())
                after = m_node.prepend_copy(node);
            else
                after = m_node.append_copy(node); // the anchor is gone: keep the content at the end
        }
        lastInserted[unknown.anchor] = after;
    }
}

void XmlOut::addData(const AddData &entries, bool required)
{
    if (entries.empty() && !required)
        return;
    pugi::xml_node addData = m_node.append_child("addData");
    for (const AddDataEntry &entry : entries) {
        pugi::xml_node data = addData.append_child("data");
        data.append_attribute("name").set_value(toFileUtf8(entry.name).constData());
        data.append_attribute("handleUnknown").set_value(toFileUtf8(entry.handleUnknown).constData());
        appendFragment(data, entry.content);
        replaceSlots(data);
    }
}

namespace {

void findSlots(pugi::xml_node data, std::vector<pugi::xml_node> &found)
{
    walkDescendants(data, [&](pugi::xml_node node) {
        if (node.type() != pugi::node_element)
            return false;
        if (!std::strcmp(node.name(), kSlotElement)) {
            found.push_back(node);
            return false;
        }
        return true;
    });
}

} // namespace

// Puts the POUs and data types that live in vendor addData back in place of their placeholders.
// A placeholder whose POU was deleted takes its <data> wrapper with it.
void XmlOut::replaceSlots(pugi::xml_node data)
{
    std::vector<pugi::xml_node> placeholders;
    findSlots(data, placeholders);
    for (pugi::xml_node placeholder : placeholders) {
        const quint32 slot = placeholder.attribute("slot").as_uint();
        const bool isPou = !std::strcmp(placeholder.attribute("kind").value(), "pou");
        pugi::xml_node parent = placeholder.parent();
        bool written = false;
        if (isPou) {
            if (const auto it = m_context.slotPous.find(slot); it != m_context.slotPous.end()) {
                write(parent.insert_child_before("pou", placeholder), *it->second);
                written = true;
            }
        } else if (const auto it = m_context.slotDataTypes.find(slot); it != m_context.slotDataTypes.end()) {
            write(parent.insert_child_before("dataType", placeholder), *it->second);
            written = true;
        }
        parent.remove_child(placeholder);
        if (written)
            m_context.writtenSlots.push_back(slot);
        else if (hasLocalName(parent, "data") && !parent.first_child() && parent.parent())
            parent.parent().remove_child(parent);
    }
}

} // namespace iec::model::plcopen
