// XmlIn: the reading archive, and the reader's handling of vendor addData.

#include "model/plcopen/schema_project.h"

#include <algorithm>

namespace iec::model::plcopen {

void ReadContext::indexLines(const char *data, qsizetype size)
{
    lineStarts.clear();
    lineStarts.push_back(0);
    for (qsizetype i = 0; i < size; ++i) {
        if (data[i] == '\n')
            lineStarts.push_back(i + 1);
    }
}

void ReadContext::reportAtOffset(Diagnostic::Severity severity, qsizetype offset, const QString &message)
{
    Diagnostic diagnostic {.severity = severity, .message = message, .pouName = pouName};
    if (offset >= 0 && !lineStarts.empty()) {
        const auto next = std::upper_bound(lineStarts.begin(), lineStarts.end(), offset);
        diagnostic.line = int(next - lineStarts.begin());
        diagnostic.column = int(offset - *(next - 1)) + 1;
    }
    diagnostics.push_back(std::move(diagnostic));
}

void ReadContext::report(
    Diagnostic::Severity severity, pugi::xml_node where, const QString &message, std::optional<quint64> localId)
{
    // offset_debug points at the element name; the '<' is one byte before it.
    const qsizetype offset = where ? qsizetype(where.offset_debug()) : -1;
    reportAtOffset(severity, offset > 0 ? offset - 1 : offset, message);
    // Diagnostics inside a graphical element name it, so an editor can select it.
    if (quint64 id = 0; !localId && where && Codec<quint64>::parse(where.attribute("localId").value(), id))
        localId = id;
    diagnostics.back().localId = localId;
}

pugi::xml_node XmlIn::firstChild(const char *name) const
{
    for (pugi::xml_node node = m_node.first_child(); node; node = node.next_sibling()) {
        if (node.type() == pugi::node_element && hasLocalName(node, name))
            return node;
    }
    return {};
}

void XmlIn::text(const char *name, QString &value)
{
    markKnown(name);
    if (const pugi::xml_node node = firstChild(name)) {
        markRead(node);
        value = QString::fromUtf8(node.text().get());
    } else
        reportMissing("element", name);
}

void XmlIn::text(const char *name, std::optional<QString> &value)
{
    markKnown(name);
    if (const pugi::xml_node node = firstChild(name)) {
        markRead(node);
        value = QString::fromUtf8(node.text().get());
    }
}

void XmlIn::reportMissing(const char *what, const char *name)
{
    const QString element = QString::fromUtf8(localName(m_node));
    const QString missing = QString::fromUtf8(name);
    m_context.report(Diagnostic::Severity::Error, m_node,
        !std::strcmp(what, "attribute")
            ? QCoreApplication::translate("iec::model::plcopen::Reader", "<%1> lacks the required attribute '%2'.")
                  .arg(element, missing)
            : QCoreApplication::translate("iec::model::plcopen::Reader", "<%1> lacks the required element <%2>.")
                  .arg(element, missing));
}

bool XmlIn::isKnownChild(const char *name) const
{
    return std::ranges::any_of(m_knownChildren, [name](const char *known) { return !std::strcmp(known, name); });
}

bool XmlIn::isKnownAttribute(const char *name) const
{
    const bool bad = std::ranges::any_of(m_badAttributes, [name](const char *b) { return !std::strcmp(b, name); });
    return !bad
        && std::ranges::any_of(m_knownAttributes, [name](const char *known) { return !std::strcmp(known, name); });
}

void XmlIn::collectUnknown(Extras *extras)
{
    m_finished = true;
    const QString element = QString::fromUtf8(localName(m_node));
    // Known attributes with a bad value come first, in the order they were read, then the unknown
    // ones in file order: the order the writer puts them in, so that a file read, written and read
    // again gives the same model (fuzz_plcopen found one with an unknown attribute first).
    if (extras)
        for (const char *name : m_badAttributes) {
            const QString key = QString::fromUtf8(name);
            const bool listed = std::ranges::any_of(extras->attributes, [&](const UnknownAttribute &a) { return a.name == key; });
            if (pugi::xml_attribute attribute = m_node.attribute(name); attribute && !listed)
                extras->attributes.push_back({key, QString::fromUtf8(attribute.value())});
        }
    for (pugi::xml_attribute attribute = m_node.first_attribute(); attribute; attribute = attribute.next_attribute()) {
        const char *name = attribute.name();
        // Namespace declarations are the writer's business; xsi: attributes are harmless hints.
        if (isKnownAttribute(name) || !std::strncmp(name, "xmlns", 5))
            continue;
        const bool bad = std::ranges::any_of(m_badAttributes, [name](const char *b) { return !std::strcmp(b, name); });
        if (extras && !bad)
            extras->attributes.push_back({QString::fromUtf8(name), QString::fromUtf8(attribute.value())});
        if (!bad && std::strncmp(name, "xsi:", 4))
            m_context.report(Diagnostic::Severity::Warning, m_node,
                extras ? QCoreApplication::translate(
                    "iec::model::plcopen::Reader", "Unknown attribute '%1' on <%2> is kept as it is.")
                             .arg(QString::fromUtf8(name), element)
                       : QCoreApplication::translate(
                           "iec::model::plcopen::Reader", "Unknown attribute '%1' on <%2> is ignored.")
                             .arg(QString::fromUtf8(name), element));
    }
    std::ranges::sort(m_readChildren);
    auto wasRead
        = [this](pugi::xml_node node) { return std::ranges::binary_search(m_readChildren, node.internal_object()); };
    QString anchor;
    for (pugi::xml_node node = m_node.first_child(); node; node = node.next_sibling()) {
        if (node.type() != pugi::node_element)
            continue;
        const char *name = localName(node);
        const bool known = isKnownChild(name);
        if (known && wasRead(node)) {
            anchor = QString::fromUtf8(name);
            continue;
        }
        // A repeat of an element the XSD allows once is kept where it stood, after the first: written
        // back in place, the same one is read first again (fuzz_plcopen found repeated <interface>s).
        if (extras)
            extras->elements.push_back({anchor, rawXml(node)});
        m_context.report(Diagnostic::Severity::Warning, node, unreadElementMessage(name, element, known, extras));
    }
}

QString XmlIn::unreadElementMessage(const char *name, const QString &parent, bool known, bool kept)
{
    const QString child = QString::fromUtf8(name);
    if (known)
        return kept ? QCoreApplication::translate("iec::model::plcopen::Reader",
                   "<%1> in <%2> is more than the file format allows there; it is kept as it is, but not read.")
                          .arg(child, parent)
                    : QCoreApplication::translate("iec::model::plcopen::Reader",
                        "<%1> in <%2> is more than the file format allows there; it is ignored.")
                          .arg(child, parent);
    return kept
        ? QCoreApplication::translate("iec::model::plcopen::Reader", "Unknown element <%1> in <%2> is kept as it is.")
              .arg(child, parent)
        : QCoreApplication::translate("iec::model::plcopen::Reader", "Unknown element <%1> in <%2> is ignored.")
              .arg(child, parent);
}

void XmlIn::finish(Extras &extras)
{
    collectUnknown(&extras);
}

void XmlIn::finishWithoutExtras()
{
    collectUnknown(nullptr);
}

namespace {

// Finds the POUs and data types a vendor keeps in addData: a <pou> or <dataType> element that is
// the content of a <data> entry, at any depth (TwinCAT nests them inside an application entry).
void findVendorDeclarations(pugi::xml_node data, std::vector<pugi::xml_node> &found)
{
    walkDescendants(data, [&](pugi::xml_node node) {
        if (node.type() != pugi::node_element)
            return false;
        if ((hasLocalName(node, "pou") || hasLocalName(node, "dataType")) && hasLocalName(node.parent(), "data")) {
            found.push_back(node);
            return false; // its own addData is read with it
        }
        return true;
    });
}

// pugixml frees a removed subtree recursively, so only shallow declarations are moved out of the
// opaque content; anything deeper is hostile and stays opaque.
bool isShallow(pugi::xml_node node)
{
    constexpr int kMaxRemovableDepth = 1000;
    return !nestsDeeperThan(node, kMaxRemovableDepth);
}

} // namespace

void XmlIn::addData(AddData &entries, bool required)
{
    markKnown("addData");
    const pugi::xml_node addData = firstChild("addData");
    if (!addData) {
        if (required)
            reportMissing("element", "addData");
        return;
    }
    markRead(addData);
    XmlIn list(addData, m_context);
    list.markKnown("data");
    for (pugi::xml_node data = addData.first_child(); data; data = data.next_sibling()) {
        if (data.type() != pugi::node_element || !hasLocalName(data, "data"))
            continue;
        list.markRead(data);
        AddDataEntry &entry = entries.emplace_back();
        XmlIn entryIn(data, m_context);
        entryIn.attr("name", entry.name);
        entryIn.attr("handleUnknown", entry.handleUnknown);

        std::vector<pugi::xml_node> declarations;
        findVendorDeclarations(data, declarations);
        for (pugi::xml_node declaration : declarations) {
            if (!isShallow(declaration)) {
                m_context.report(Diagnostic::Severity::Warning, declaration,
                    QCoreApplication::translate("iec::model::plcopen::Reader",
                        "A declaration in addData is nested too deeply to read; it is kept as it is."));
                continue;
            }
            const quint32 slot = m_context.nextSlot++;
            const bool isPou = hasLocalName(declaration, "pou");
            // Read into a local value: a vendor POU may itself hold vendor POUs in its addData.
            if (isPou) {
                Pou pou;
                read(declaration, pou);
                pou.addDataSlot = slot;
                m_context.addDataPous.push_back(std::move(pou));
            } else {
                DataTypeDecl type;
                read(declaration, type);
                type.addDataSlot = slot;
                m_context.addDataTypes.push_back(std::move(type));
            }
            pugi::xml_node placeholder = declaration.parent().insert_child_before(kSlotElement, declaration);
            placeholder.append_attribute("kind").set_value(isPou ? "pou" : "dataType");
            placeholder.append_attribute("slot").set_value(slot);
            declaration.parent().remove_child(declaration);
        }
        for (pugi::xml_node content = data.first_child(); content; content = content.next_sibling()) {
            entry.content += rawXml(content);
        }
        entryIn.m_finished = true; // the content is opaque by definition
        entryIn.m_knownAttributes.push_back("name");
        entryIn.m_knownAttributes.push_back("handleUnknown");
    }
    list.finishWithoutExtras();
}

} // namespace iec::model::plcopen
