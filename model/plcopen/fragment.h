#pragma once

#include "model/diagnostic.h"
#include "model/body.h"
#include "model/element.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace iec::model::plcopen {

// A piece of a graphical body on its own, as the editors copy it: the elements written exactly as
// in a body of the file (everything the file keeps, addData included), inside
//   <fragment xmlns="http://www.plcopen.org/xml/tc6_0201" language="LD"> ... </fragment>
// `language` names the editor language the elements come from ("LD", "FBD", "CFC", "SFC").
QByteArray writeElementsFragment(const QString &language, const std::vector<Element> &elements);

struct FragmentReadResult {
    // Why the bytes are not a fragment ("" when they are): not XML, another root element, content
    // that cannot be read without losing something.
    QString error;
    QString language;
    std::vector<Element> elements;
    std::vector<Diagnostic> diagnostics; // what the reader noticed (warnings too)

    [[nodiscard]] bool ok() const { return error.isEmpty(); }
};

// Reads what writeElementsFragment wrote. Never throws; anything else is an error, not a guess.
FragmentReadResult readElementsFragment(const QByteArray &xml);

// A diagram another tool keeps under a root element of its own (CODESYS: <CFC> in a body's
// addData): the root's children are read as a body's elements, whatever the root is called and
// whether or not it declares the TC6 namespace. `language` stays empty. Never throws.
FragmentReadResult readElementsUnder(const QByteArray &xml);
// The elements written as in a body of the file under a root element `rootName` that declares no
// namespace (it goes into addData, inside a project that declares them), unindented as the model
// keeps addData.
QByteArray writeElementsUnder(const char *rootName, const std::vector<Element> &elements);

} // namespace iec::model::plcopen
