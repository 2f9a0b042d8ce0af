#pragma once

#include "model/pou.h"

#include <QString>
#include <QStringView>

#include <optional>
#include <vector>

// The declaration editor's text view, without widgets: an interface printed as VAR ... END_VAR
// sections (one declaration a line, its comment after it) and such text read back and checked.
namespace iec::editors {

// A problem in declaration text, 1-based like the compiler's diagnostics.
struct DeclarationProblem {
    int line = 1;
    int column = 1;
    QString message;

    bool operator==(const DeclarationProblem &) const = default;
};

struct DeclarationTextResult {
    std::optional<model::Interface> declarations; // set only when there are no problems
    std::vector<DeclarationProblem> problems;
    // Where each var list's header and each variable (in order, across the lists) is written;
    // set with `declarations`, so checks made later can point at the line.
    std::vector<DeclarationProblem> sectionPlaces;
    std::vector<DeclarationProblem> variablePlaces;
};

// The var lists of `declarations` as IEC text; a variable's documentation follows it as (* ... *).
[[nodiscard]] QString declarationText(const model::Interface &declarations);

// Reads and checks `text`. What the text cannot express (the return type, addData, unknown XML,
// documentation of the lists) is taken from `base`, and a variable keeps its addData, globalId
// and unknown XML when a variable of the same name was in `base`.
[[nodiscard]] DeclarationTextResult readDeclarationText(QStringView text, const model::Interface &base = {});

// One declaration as the text view writes it: "name AT address : type := initial; (* comment *)".
// Empty address, initial value and comment are left out.
[[nodiscard]] QString declarationLine(const QString &name, const QString &address, const QString &type,
    const QString &initialValue, const QString &comment);

// "VAR_INPUT RETAIN": the keyword line that opens the list's section.
[[nodiscard]] QString sectionHeader(const model::VarList &list);

// The messages of the checks that the table and the text share.
[[nodiscard]] QString invalidNameMessage(const QString &name);
[[nodiscard]] QString invalidAddressMessage(const QString &address);
[[nodiscard]] QString duplicateNameMessage(const QString &name);

// %IX0.0, %QW3, %MD10, %QB7, %I*: a located variable's address.
[[nodiscard]] bool isValidAddress(const QString &address);
// An IEC identifier that is no keyword or elementary type name.
[[nodiscard]] bool isValidIdentifier(const QString &name);

} // namespace iec::editors
