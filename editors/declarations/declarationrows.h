#pragma once

#include "editors/declarations/declarationtext.h"

#include "model/pou.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

// The declaration editor's table, without widgets: one row per variable, and back.
namespace iec::editors {

enum class DeclarationColumn { Name, Class, Type, InitialValue, Address, Comment };
inline constexpr int kDeclarationColumnCount = 6;

// One variable as the table shows it: every cell is the text the user sees and edits. The class is
// the section keyword with its qualifier ("VAR_INPUT", "VAR CONSTANT", "VAR_GLOBAL RETAIN").
struct DeclarationRow {
    QString name;
    QString varClass = QStringLiteral("VAR");
    QString type = QStringLiteral("BOOL");
    QString initialValue;
    QString address;
    QString comment;

    bool operator==(const DeclarationRow &) const = default;
};

// A problem with one cell of the table (0-based row).
struct RowProblem {
    int row = 0;
    DeclarationColumn column = DeclarationColumn::Name;
    QString message;

    bool operator==(const RowProblem &) const = default;
};

struct RowsResult {
    std::optional<model::Interface> declarations; // set only when there are no problems
    std::vector<RowProblem> problems;
};

// The classes a row may have, in the order the class editor offers them.
[[nodiscard]] QStringList declarationClasses();

[[nodiscard]] std::vector<DeclarationRow> rowsFromInterface(const model::Interface &declarations);
// Every problem of every row (names, classes, types, initial values, addresses, duplicates).
[[nodiscard]] std::vector<RowProblem> validateRows(const std::vector<DeclarationRow> &rows);
// Consecutive rows of the same class form one var list. `base` as in readDeclarationText.
[[nodiscard]] RowsResult interfaceFromRows(const std::vector<DeclarationRow> &rows, const model::Interface &base = {});
// The first name "<stem>N" (N = 1, 2, ...) that no row uses.
[[nodiscard]] QString freeVariableName(const std::vector<DeclarationRow> &rows, const QString &stem);

} // namespace iec::editors
