#pragma once

#include <QString>

#include <vector>

namespace iec::model {

// Content the model does not interpret but must write back unchanged ("nothing lost").

// One <data> entry of an <addData> element. `content` is the inner XML as compact text.
struct AddDataEntry {
    QString name; // an URI naming the vendor extension
    QString handleUnknown; // preserve | discard | implementation
    QString content; // serialized child elements (pugixml format_raw)

    bool operator==(const AddDataEntry &) const = default;
};
using AddData = std::vector<AddDataEntry>;

struct UnknownAttribute {
    QString name;
    QString value;

    bool operator==(const UnknownAttribute &) const = default;
};

// A child element the schema does not allow here. `anchor` is the name of the known sibling it
// followed (empty: it came before every known child), so the writer puts it back in place.
struct UnknownElement {
    QString anchor;
    QString xml;

    bool operator==(const UnknownElement &) const = default;
};

struct Extras {
    std::vector<UnknownAttribute> attributes;
    std::vector<UnknownElement> elements;

    [[nodiscard]] bool isEmpty() const { return attributes.empty() && elements.empty(); }
    bool operator==(const Extras &) const = default;
};

// ppx:formattedText: XHTML in the file. The model keeps the plain text; when the XHTML was richer
// than one paragraph of text, `xhtml` keeps it verbatim so it is written back unchanged.
struct FormattedText {
    QString text;
    QString xhtml; // empty unless the original markup must be preserved

    bool operator==(const FormattedText &) const = default;
};

} // namespace iec::model
