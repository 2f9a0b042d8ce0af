#pragma once

// Two archives with the same vocabulary. Each Schema<T>::describe(archive, value) lists the
// attributes and children of one XSD element once, in the XSD's sequence order; XmlIn reads them
// and XmlOut writes them. So the reader and the writer of every element kind are the same lines.

#include "model/diagnostic.h"
#include "model/plcopen/xmlcodec.h"
#include "model/project.h"

#include <pugixml.hpp>

#include <QCoreApplication>

#include <QString>

#include <cstring>
#include <optional>
#include <unordered_map>
#include <variant>
#include <vector>

namespace iec::model::plcopen {

inline constexpr const char *kTc6Namespace = "http://www.plcopen.org/xml/tc6_0201";
inline constexpr const char *kTc6OldNamespace = "http://www.plcopen.org/xml/tc6_0200";
inline constexpr const char *kXhtmlNamespace = "http://www.w3.org/1999/xhtml";
// Our own addData entry on a body whose layout was generated on import.
inline constexpr const char *kLayoutAddDataName = "https://iec-studio.org/layout";
// Stands in for a POU or data type that lives in a vendor addData entry (see Pou::addDataSlot).
inline constexpr const char *kSlotElement = "iecstudio-addDataSlot";

// The element name without a namespace prefix.
const char *localName(pugi::xml_node node);
bool hasLocalName(pugi::xml_node node, const char *name);
// Compact text of a node (pugixml format_raw), used for opaque content.
QString rawXml(pugi::xml_node node);

// Whether some node below `root` is more than `limit` levels deep (iterative).
bool nestsDeeperThan(pugi::xml_node root, int limit);

// Visits every node below `root` in document order without recursion (hostile files nest
// deeply). `visit(node)` returns whether to descend into that node.
template<class Visit> void walkDescendants(pugi::xml_node root, Visit visit)
{
    pugi::xml_node node = root.first_child();
    while (node) {
        if (visit(node) && node.first_child()) {
            node = node.first_child();
            continue;
        }
        while (node && node != root && !node.next_sibling())
            node = node.parent();
        if (!node || node == root)
            return;
        node = node.next_sibling();
    }
}

template<class T> struct Schema; // specialisations in schema_*.h

struct ReadContext {
    std::vector<Diagnostic> diagnostics;
    std::vector<qsizetype> lineStarts; // byte offsets where lines begin
    int depth = 0;
    quint32 nextSlot = 1;
    std::vector<Pou> addDataPous;
    std::vector<DataTypeDecl> addDataTypes;
    std::optional<QString> pouName; // the POU being read, for diagnostics

    static constexpr int kMaxDepth = 200; // deeper nesting is hostile input, not a project

    void indexLines(const char *data, qsizetype size);
    void report(Diagnostic::Severity severity, pugi::xml_node where, const QString &message,
        std::optional<quint64> localId = {});
    void reportAtOffset(Diagnostic::Severity severity, qsizetype offset, const QString &message);
};

class XmlIn
{
public:
    static constexpr bool reading = true;

    XmlIn(pugi::xml_node node, ReadContext &context)
        : m_node(node)
        , m_context(context)
    { }

    [[nodiscard]] pugi::xml_node node() const { return m_node; }
    [[nodiscard]] ReadContext &context() { return m_context; }

    // A required attribute.
    template<class T> void attr(const char *name, T &value)
    {
        if (const pugi::xml_attribute attribute = take(name))
            parse(attribute, value);
        else
            reportMissing("attribute", name);
    }

    template<class T> void attr(const char *name, std::optional<T> &value)
    {
        if (const pugi::xml_attribute attribute = take(name)) {
            T parsed {};
            if (parse(attribute, parsed))
                value = std::move(parsed);
        }
    }

    // An optional attribute with a default the model stores instead of "absent".
    template<class T> void attr(const char *name, T &value, const T &fallback)
    {
        value = fallback;
        if (const pugi::xml_attribute attribute = take(name))
            parse(attribute, value);
    }

    template<class T> void child(const char *name, T &value)
    {
        markKnown(name);
        if (const pugi::xml_node node = firstChild(name))
            read(node, value);
        else
            reportMissing("element", name);
    }

    template<class T> void child(const char *name, std::optional<T> &value)
    {
        markKnown(name);
        if (const pugi::xml_node node = firstChild(name)) {
            T parsed {};
            read(node, parsed);
            value = std::move(parsed);
        }
    }

    template<class T> void children(const char *name, std::vector<T> &values)
    {
        markKnown(name);
        for (pugi::xml_node node = m_node.first_child(); node; node = node.next_sibling()) {
            if (node.type() == pugi::node_element && hasLocalName(node, name))
                read(node, values.emplace_back());
        }
    }

    // A list of children that may be empty but whose container is optional in the XSD.
    template<class T> void children(const char *container, const char *name, std::optional<std::vector<T>> &values)
    {
        markKnown(container);
        if (const pugi::xml_node node = firstChild(container)) {
            markRead(node);
            XmlIn sub(node, m_context);
            sub.children(name, values.emplace());
            sub.finishWithoutExtras();
        }
    }

    // <container><name/>...</container> read into a plain vector (the container may be absent).
    template<class T> void containerList(const char *container, const char *name, std::vector<T> &values, bool = false)
    {
        markKnown(container);
        if (const pugi::xml_node node = firstChild(container)) {
            markRead(node);
            XmlIn sub(node, m_context);
            sub.children(name, values);
            sub.finishWithoutExtras();
        }
    }

    // <container><name .../></container> holding one value.
    template<class T> void nested(const char *container, const char *name, T &value)
    {
        markKnown(container);
        if (const pugi::xml_node node = firstChild(container)) {
            markRead(node);
            XmlIn sub(node, m_context);
            sub.child(name, value);
            sub.finishWithoutExtras();
        } else {
            reportMissing("element", container);
        }
    }

    // A choice of exactly one child among the tags of V's alternatives.
    template<class V> void choice(V &value, const char *what)
    {
        bool found = false;
        [&]<std::size_t... I>(std::index_sequence<I...>)
        {
            (markKnown(Schema<std::variant_alternative_t<I, V>>::tag), ...);
            (void)((!found && (found = readChoice<I>(value))) || ...);
        }
        (std::make_index_sequence<std::variant_size_v<V>>());
        if (!found)
            reportMissing("element", what);
    }

    // Free-form content (XHTML): nothing here is unknown.
    void skipRest() { m_finished = true; }

    // An element whose content is text (<expression>, <variable>, <Comment>).
    void text(const char *name, QString &value);
    void text(const char *name, std::optional<QString> &value);

    // The children of a choice: every child whose name is the tag of an alternative of V.
    template<class V> void choiceList(std::vector<V> &values)
    {
        [&]<std::size_t... I>(std::index_sequence<I...>)
        {
            (markKnown(Schema<std::variant_alternative_t<I, V>>::tag), ...);
        }
        (std::make_index_sequence<std::variant_size_v<V>>());
        for (pugi::xml_node node = m_node.first_child(); node; node = node.next_sibling()) {
            if (node.type() == pugi::node_element)
                readAlternative(node, values);
        }
    }

    void addData(AddData &entries, bool required = false);
    // Keeps whatever the schema did not name here, and reports it.
    void finish(Extras &extras);
    // For elements without Extras in the model: reports unknown content, which is dropped.
    void finishWithoutExtras();

    void markKnown(const char *name) { m_knownChildren.push_back(name); }
    // The child elements whose content went into the model. A child with a known name that was not
    // read is a repeat of one the XSD allows once: finish() keeps it, like an unknown element.
    void markRead(pugi::xml_node child) { m_readChildren.push_back(child.internal_object()); }
    [[nodiscard]] pugi::xml_node firstChild(const char *name) const;

    template<class T> void read(pugi::xml_node node, T &value)
    {
        markRead(node);
        if (m_context.depth >= ReadContext::kMaxDepth) {
            m_context.report(Diagnostic::Severity::Error, node,
                QCoreApplication::translate("iec::model::plcopen::Reader",
                    "The elements are nested too deeply; the content below is skipped."));
            return;
        }
        ++m_context.depth;
        XmlIn sub(node, m_context);
        Schema<T>::describe(sub, value);
        if (!sub.m_finished)
            sub.finishWithoutExtras();
        --m_context.depth;
    }

private:
    template<std::size_t I, class V> bool readChoice(V &value)
    {
        const pugi::xml_node node = firstChild(Schema<std::variant_alternative_t<I, V>>::tag);
        if (!node)
            return false;
        read(node, value.template emplace<I>());
        return true;
    }

    template<class V> void readAlternative(pugi::xml_node node, std::vector<V> &values)
    {
        const char *name = localName(node);
        [&]<std::size_t... I>(std::index_sequence<I...>)
        {
            (void)((std::strcmp(name, Schema<std::variant_alternative_t<I, V>>::tag) == 0
                           ? (read(node, values.emplace_back().template emplace<I>()), true)
                           : false)
                || ...);
        }
        (std::make_index_sequence<std::variant_size_v<V>>());
    }

    pugi::xml_attribute take(const char *name)
    {
        m_knownAttributes.push_back(name);
        return m_node.attribute(name);
    }

    template<class T> bool parse(pugi::xml_attribute attribute, T &value)
    {
        if (Codec<T>::parse(attribute.value(), value))
            return true;
        m_badAttributes.push_back(attribute.name());
        m_context.report(Diagnostic::Severity::Error, m_node,
            QCoreApplication::translate("iec::model::plcopen::Reader",
                "The attribute %1=\"%2\" of <%3> has an invalid value; it is kept as written.")
                .arg(QString::fromUtf8(attribute.name()), QString::fromUtf8(attribute.value()),
                    QString::fromUtf8(localName(m_node))));
        return false;
    }

    void reportMissing(const char *what, const char *name);
    [[nodiscard]] bool isKnownChild(const char *name) const;
    [[nodiscard]] bool isKnownAttribute(const char *name) const;
    void collectUnknown(Extras *extras);
    static QString unreadElementMessage(const char *name, const QString &parent, bool known, bool kept);

    pugi::xml_node m_node;
    ReadContext &m_context;
    std::vector<const char *> m_knownAttributes;
    std::vector<const char *> m_knownChildren;
    std::vector<const pugi::xml_node_struct *> m_readChildren;
    std::vector<const char *> m_badAttributes; // present but unparsable: kept verbatim in Extras
    bool m_finished = false;
};

struct WriteContext {
    std::unordered_map<quint32, const Pou *> slotPous;
    std::unordered_map<quint32, const DataTypeDecl *> slotDataTypes;
    std::vector<quint32> writtenSlots; // slots whose placeholder was found and replaced
};

class XmlOut
{
public:
    static constexpr bool reading = false;

    XmlOut(pugi::xml_node node, WriteContext &context)
        : m_node(node)
        , m_context(context)
    { }

    [[nodiscard]] pugi::xml_node node() const { return m_node; }
    [[nodiscard]] WriteContext &context() { return m_context; }

    template<class T> void attr(const char *name, const T &value)
    {
        m_node.append_attribute(name).set_value(Codec<T>::format(value).c_str());
    }

    template<class T> void attr(const char *name, const std::optional<T> &value)
    {
        if (value)
            attr(name, *value);
    }

    template<class T> void attr(const char *name, const T &value, const T &fallback)
    {
        if (!(value == fallback))
            attr(name, value);
    }

    template<class T> void child(const char *name, const T &value) { write(m_node.append_child(name), value); }

    template<class T> void child(const char *name, const std::optional<T> &value)
    {
        if (value)
            child(name, *value);
    }

    template<class T> void children(const char *name, const std::vector<T> &values)
    {
        for (const T &value : values)
            child(name, value);
    }

    template<class T>
    void children(const char *container, const char *name, const std::optional<std::vector<T>> &values)
    {
        if (values) {
            XmlOut sub(m_node.append_child(container), m_context);
            sub.children(name, *values);
        }
    }

    template<class T>
    void containerList(
        const char *container, const char *name, const std::vector<T> &values, bool writeWhenEmpty = false)
    {
        if (values.empty() && !writeWhenEmpty)
            return;
        XmlOut sub(m_node.append_child(container), m_context);
        sub.children(name, values);
    }

    template<class T> void nested(const char *container, const char *name, const T &value)
    {
        XmlOut sub(m_node.append_child(container), m_context);
        sub.child(name, value);
    }

    template<class V> void choice(const V &value, const char *)
    {
        std::visit(
            [&](const auto &alternative) {
                using T = std::decay_t<decltype(alternative)>;
                child(Schema<T>::tag, alternative);
            },
            value);
    }

    void skipRest() { }

    void text(const char *name, const QString &value);
    void text(const char *name, const std::optional<QString> &value);

    template<class V> void choiceList(const std::vector<V> &values)
    {
        for (const V &value : values) {
            std::visit(
                [&](const auto &alternative) {
                    using T = std::decay_t<decltype(alternative)>;
                    child(Schema<T>::tag, alternative);
                },
                value);
        }
    }

    void addData(const AddData &entries, bool required = false);
    void finish(const Extras &extras);
    void finishWithoutExtras() { }

    template<class T> void write(pugi::xml_node node, const T &value)
    {
        XmlOut sub(node, m_context);
        Schema<T>::describe(sub, value);
    }

private:
    void replaceSlots(pugi::xml_node data);

    pugi::xml_node m_node;
    WriteContext &m_context;
};

// Appends the elements of an XML fragment (opaque content) as children of `parent`.
void appendFragment(pugi::xml_node parent, const QString &xml);

} // namespace iec::model::plcopen
