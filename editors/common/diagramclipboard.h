#pragma once

#include "editors/common/editorlanguage.h"
#include "model/body.h"
#include "model/element.h"

#include <QString>

#include <memory>
#include <unordered_map>
#include <vector>

class QMimeData;

// The clipboard of every graphical editor: copied elements travel as a PLCopen fragment
// (model/plcopen/fragment.h) under our own MIME type, and as its XML text, so a copy survives
// between windows and can be looked at. Pasting accepts only a fragment of the editor's own
// language and gives the elements fresh localIds; anything else is refused with a message and
// changes nothing.
namespace iec::editors {

inline constexpr const char *kElementsMimeType = "application/x-iecstudio-plcopen-elements";

[[nodiscard]] std::unique_ptr<QMimeData> elementsMimeData(EditorLanguage language, const std::vector<model::Element> &elements);
// Puts the elements on the system clipboard.
void copyElementsToClipboard(EditorLanguage language, const std::vector<model::Element> &elements);

struct PastedElements {
    QString error; // why nothing can be pasted; empty when `elements` are ready
    std::vector<model::Element> elements;

    [[nodiscard]] bool ok() const { return error.isEmpty(); }
};

// The elements of `data` when it holds a fragment of `language`, renumbered from `firstFreeId`
// (renumberElements). `data` may be nullptr (an empty clipboard).
[[nodiscard]] PastedElements elementsFromMimeData(const QMimeData *data, EditorLanguage language, quint64 firstFreeId);
[[nodiscard]] PastedElements elementsFromClipboard(EditorLanguage language, quint64 firstFreeId);
// Whether the system clipboard holds our MIME type (a cheap test for enabling Paste; the
// language is checked when pasting).
[[nodiscard]] bool clipboardHasElements();

// Gives the elements the localIds firstFreeId, firstFreeId + 1, ... in their order (the actions
// of action blocks after them), points the connections between them at the new ids and drops
// connections to elements that are not among them. Returns old localId → new localId.
std::unordered_map<quint64, quint64> renumberElements(std::vector<model::Element> &elements, quint64 firstFreeId);

} // namespace iec::editors
