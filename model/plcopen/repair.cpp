#include "model/plcopen/repair.h"

#include <QSet>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace iec::model::plcopen {

namespace {

quint64 largestLocalId(pugi::xml_node root)
{
    quint64 largest = 0;
    walkDescendants(root, [&](pugi::xml_node node) {
        if (node.type() != pugi::node_element)
            return false;
        if (const pugi::xml_attribute id = node.attribute("localId"))
            largest = std::max<quint64>(largest, std::strtoull(id.value(), nullptr, 10));
        return true;
    });
    return largest;
}

// nextId: 0 until a fresh localId is first needed (most files need none, so the whole document
// is not searched for the largest one).
void repairAction(pugi::xml_node action, pugi::xml_node root, quint64 &nextId, ReadContext &context)
{
    if (!action.attribute("localId")) {
        if (nextId == 0)
            nextId = largestLocalId(root);
        const quint64 id = ++nextId;
        action.append_attribute("localId").set_value(std::to_string(id).c_str());
        context.report(Diagnostic::Severity::Warning, action,
            QCoreApplication::translate("iec::model::plcopen::Reader", "This <action> has no localId; it was given %1.").arg(id), id);
    }
    bool placed = false;
    for (pugi::xml_node child = action.first_child(); child && !placed; child = child.next_sibling())
        placed = child.type() == pugi::node_element && hasLocalName(child, "relPosition");
    if (!placed) {
        // The XSD puts relPosition before reference/inline.
        pugi::xml_node position = action.prepend_child("relPosition");
        position.append_attribute("x").set_value("0");
        position.append_attribute("y").set_value("0");
        context.report(Diagnostic::Severity::Warning, action, QCoreApplication::translate("iec::model::plcopen::Reader", "This <action> has no position; it is placed at (0, 0)."));
    }
}

void repairPouInstance(pugi::xml_node instance, ReadContext &context)
{
    const pugi::xml_attribute type = instance.attribute("type");
    if (!type || instance.attribute("typeName"))
        return;
    instance.append_attribute("typeName").set_value(type.value());
    instance.remove_attribute(type);
    context.report(Diagnostic::Severity::Warning, instance,
        QCoreApplication::translate("iec::model::plcopen::Reader", "<pouInstance> names its POU with 'type'; PLCopen calls it 'typeName', which it is written as."));
}

void repairDateTime(pugi::xml_node header, ReadContext &context)
{
    pugi::xml_attribute created = header.attribute("creationDateTime");
    const std::string value = created.value();
    const auto space = value.find(' ');
    if (!created || space != 10) // 2024-01-31 12:00:00
        return;
    std::string mended = value;
    mended[space] = 'T';
    created.set_value(mended.c_str());
    context.report(Diagnostic::Severity::Warning, header,
        QCoreApplication::translate("iec::model::plcopen::Reader", "creationDateTime '%1' has a space where XML wants a 'T'; it is written as '%2'.")
            .arg(QString::fromStdString(value), QString::fromStdString(mended)));
}

// UTF-16 and UTF-32 have NUL bytes in every character; pugixml converts them, and their NULs are
// not looked for. The test is pugixml's own guess (a byte order mark, or '<' in the first one, two
// or four bytes), so that a UTF-8 file that merely starts with a NUL still has it mended.
bool isWideEncoding(const QByteArray &bytes)
{
    const QByteArrayView start = QByteArrayView(bytes).first(std::min<qsizetype>(bytes.size(), 4));
    return start.startsWith("\xFE\xFF") || start.startsWith("\xFF\xFE") || start.startsWith(QByteArrayView("\0<", 2))
        || start.startsWith(QByteArrayView("<\0", 2)) || start.startsWith(QByteArrayView("\0\0\0<", 4))
        || start.startsWith(QByteArrayView("\0\0\xFE\xFF", 4));
}

// The end of the markup that starts at `at` and holds no character references (a CDATA section,
// a comment, a processing instruction), or -1.
qsizetype endOfLiteralMarkup(const QByteArray &bytes, qsizetype at)
{
    const auto skipTo = [&](const char *open, const char *close) -> qsizetype {
        if (!QByteArrayView(bytes).sliced(at).startsWith(open))
            return -1;
        const qsizetype end = bytes.indexOf(close, at + qsizetype(std::strlen(open)));
        return end < 0 ? bytes.size() : end + qsizetype(std::strlen(close));
    };
    for (const auto &[open, close] : {std::pair("<![CDATA[", "]]>"), std::pair("<!--", "-->"), std::pair("<?", "?>")}) {
        if (const qsizetype end = skipTo(open, close); end >= 0)
            return end;
    }
    return -1;
}

// If a character reference to NUL (&#0;, &#x000;, ...) starts at `at`, turns it into one to U+0001.
// Returns where the scan goes on.
qsizetype mendNulReference(QByteArray &bytes, qsizetype at)
{
    qsizetype digits = at + 2;
    const bool hex = digits < bytes.size() && bytes[digits] == 'x';
    if (hex)
        ++digits;
    qsizetype end = digits;
    // As pugixml adds the digits up: in 32 bits that wrap, so &#4294967296; is a NUL too. Such a
    // value ends in an even digit (in hexadecimal 0), so one more in the last digit makes it 1.
    std::uint32_t value = 0;
    while (end < bytes.size() && (hex ? std::isxdigit(uchar(bytes[end])) : std::isdigit(uchar(bytes[end])))) {
        const char c = bytes[end];
        const std::uint32_t digit = std::isdigit(uchar(c)) ? std::uint32_t(c - '0') : std::uint32_t((c | 0x20) - 'a' + 10);
        value = value * (hex ? 16u : 10u) + digit;
        ++end;
    }
    if (end > digits && end < bytes.size() && bytes[end] == ';' && value == 0)
        bytes[end - 1] = char(bytes[end - 1] + 1);
    return end;
}

// How many bytes of the UTF-8 at `text` form a character XML does not allow (0 if it is allowed).
int disallowedLength(const unsigned char *text)
{
    if (text[0] < 0x20 && text[0] != '\t' && text[0] != '\n' && text[0] != '\r')
        return 1;
    if (text[0] == 0xEF && text[1] == 0xBF && (text[2] == 0xBE || text[2] == 0xBF)) // U+FFFE, U+FFFF
        return 3;
    return 0;
}

// Leaves the characters XML does not allow out of `value`, counting them; false when it has none.
bool dropDisallowed(const char *value, std::string &kept, qsizetype &dropped)
{
    const auto *text = reinterpret_cast<const unsigned char *>(value);
    std::size_t at = 0;
    for (; text[at]; ++at) {
        if (disallowedLength(text + at))
            break;
    }
    if (!text[at])
        return false;
    kept.assign(value, at);
    while (text[at]) {
        if (const int length = disallowedLength(text + at)) {
            ++dropped;
            at += std::size_t(length);
            continue;
        }
        kept.push_back(char(text[at++]));
        // What is kept may join into U+FFFE or U+FFFF across a dropped character (EF 01 BF BE).
        if (kept.size() >= 3 && disallowedLength(reinterpret_cast<const unsigned char *>(kept.data() + kept.size() - 3)) == 3) {
            kept.resize(kept.size() - 3);
            ++dropped;
        }
    }
    return true;
}

// Text left blank by dropping its characters is removed as the parser drops blank text (reader.cpp
// parses with parse_ws_pcdata_single: blank text stays only as an element's single child, and
// empty text never), so the file reads as the one written from it (found by fuzz_plcopen).
bool isBlankBesideOthers(pugi::xml_node text)
{
    const std::string_view value = text.value();
    if (value.empty())
        return true;
    if (value.find_first_not_of(" \t\r\n") != std::string_view::npos)
        return false;
    return text.previous_sibling() || text.next_sibling();
}

} // namespace

QByteArray withNulAsAnotherControlCharacter(const QByteArray &bytes)
{
    if (isWideEncoding(bytes) || (!bytes.contains('\0') && !bytes.contains("&#")))
        return bytes;
    QByteArray mended = bytes;
    mended.replace('\0', '\x01');
    // One pass, linear in the size of the file (a CDATA section's end is looked for once).
    for (qsizetype at = 0; at < mended.size();) {
        if (mended[at] == '<') {
            if (const qsizetype end = endOfLiteralMarkup(mended, at); end >= 0) {
                at = end;
                continue;
            }
        } else if (mended[at] == '&' && at + 1 < mended.size() && mended[at + 1] == '#') {
            at = mendNulReference(mended, at);
            continue;
        }
        ++at;
    }
    return mended;
}

void dropCharactersXmlDoesNotAllow(pugi::xml_document &document, ReadContext &context)
{
    qsizetype dropped = 0;
    std::string kept;
    const auto mend = [&](auto item) {
        if (dropDisallowed(item.value(), kept, dropped))
            item.set_value(kept.c_str());
    };
    pugi::xml_node firstPlace;
    std::vector<pugi::xml_node> blank;
    walkDescendants(document, [&](pugi::xml_node node) {
        const qsizetype before = dropped;
        if (node.type() == pugi::node_element) {
            for (pugi::xml_attribute attribute : node.attributes())
                mend(attribute);
        } else {
            mend(node);
            if (dropped > before && node.type() == pugi::node_pcdata && isBlankBesideOthers(node))
                blank.push_back(node);
        }
        if (before == 0 && dropped > 0) // an element's name still points into the file, to locate it
            firstPlace = node.type() == pugi::node_element ? node : node.parent();
        return node.type() == pugi::node_element;
    });
    for (pugi::xml_node node : blank)
        node.parent().remove_child(node);
    // The characters are not named: a NUL was read as U+0001.
    if (dropped > 0)
        context.report(Diagnostic::Severity::Warning, firstPlace,
            QCoreApplication::translate("iec::model::plcopen::Reader",
                "Characters XML does not allow (control characters, U+FFFE or U+FFFF) were left out of the "
                "file, %1 in all, so that the project is saved as valid XML.")
                .arg(dropped));
}

void keepFirstOfRepeatedAttributes(pugi::xml_document &document, ReadContext &context)
{
    QSet<QString> names; // as the model keeps them: bytes that are not UTF-8 read as U+FFFD
    walkDescendants(document, [&](pugi::xml_node node) {
        if (node.type() != pugi::node_element)
            return false;
        if (!node.first_attribute() || node.first_attribute() == node.last_attribute())
            return true;
        names.clear();
        std::vector<std::pair<std::string, std::string>> kept;
        bool repeated = false;
        for (pugi::xml_attribute attribute : node.attributes()) {
            const QString name = QString::fromUtf8(attribute.name());
            if (names.contains(name)) {
                if (!repeated)
                    context.report(Diagnostic::Severity::Warning, node,
                        QCoreApplication::translate("iec::model::plcopen::Reader",
                            "<%1> has the attribute %2 more than once; the first is kept.")
                            .arg(QString::fromUtf8(node.name()), name));
                repeated = true;
            } else {
                names.insert(name);
                kept.emplace_back(attribute.name(), attribute.value());
            }
        }
        // Removing one attribute walks the list: all go, and the first of each comes back.
        if (repeated) {
            node.remove_attributes();
            for (const auto &[name, value] : kept)
                node.append_attribute(name.c_str()).set_value(value.c_str());
        }
        return true;
    });
}

void repairOldForms(pugi::xml_node root, ReadContext &context)
{
    quint64 nextId = 0;
    walkDescendants(root, [&](pugi::xml_node node) {
        if (node.type() != pugi::node_element)
            return false;
        if (hasLocalName(node, "action") && hasLocalName(node.parent(), "actionBlock"))
            repairAction(node, root, nextId, context);
        else if (hasLocalName(node, "pouInstance"))
            repairPouInstance(node, context);
        else if (hasLocalName(node, "fileHeader"))
            repairDateTime(node, context);
        return !hasLocalName(node, "addData"); // vendor content is kept as written
    });
}

} // namespace iec::model::plcopen
