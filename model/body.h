#pragma once

#include "model/element.h"
#include "model/opaque.h"

#include <QString>

#include <optional>
#include <variant>
#include <vector>

namespace iec::model {

enum class BodyLanguage { ST, IL, LD, FBD, SFC };

// Textual bodies keep the program text exactly (no XHTML).
struct StBody {
    QString text;

    bool operator==(const StBody &) const = default;
};

struct IlBody {
    QString text;

    bool operator==(const IlBody &) const = default;
};

// Graphical bodies: the elements in file order. `extras` keeps unknown children of the
// <FBD>/<LD>/<SFC> element.
struct FbdBody {
    std::vector<Element> elements;
    Extras extras;

    bool operator==(const FbdBody &) const = default;
};

struct LdBody {
    std::vector<Element> elements;
    Extras extras;

    bool operator==(const LdBody &) const = default;
};

struct SfcBody {
    std::vector<Element> elements;
    Extras extras;

    bool operator==(const SfcBody &) const = default;
};

// ppx:body.
struct Body {
    std::variant<StBody, IlBody, LdBody, FbdBody, SfcBody> content; // same order as BodyLanguage
    std::optional<QString> worksheetName;
    std::optional<QString> globalId;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;
    // The positions were computed on import because the file had none (every element at 0,0).
    // Stored in our own addData entry (kLayoutAddDataName) so that a reloaded model is equal.
    bool layoutGenerated = false;

    [[nodiscard]] BodyLanguage language() const { return static_cast<BodyLanguage>(content.index()); }
    [[nodiscard]] bool isGraphical() const { return elements() != nullptr; }
    // The elements of an LD, FBD or SFC body; nullptr for ST and IL.
    [[nodiscard]] const std::vector<Element> *elements() const;
    [[nodiscard]] std::vector<Element> *elements();
    // The text of an ST or IL body; empty for graphical bodies.
    [[nodiscard]] QString text() const;
    void setText(const QString &text); // only for ST and IL bodies

    static Body withLanguage(BodyLanguage language);

    bool operator==(const Body &) const = default;
};

} // namespace iec::model
