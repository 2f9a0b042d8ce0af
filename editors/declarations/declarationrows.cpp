#include "editors/declarations/declarationrows.h"

#include "interpreter/frontend/iecprinter.h"

#include <QCoreApplication>

namespace iec::editors {

namespace {

// The one variable `text` declares, when it declares exactly one and parses.
std::optional<model::Variable> singleVariable(const QString &text)
{
    const DeclarationTextResult read = readDeclarationText(text);
    if (!read.declarations || read.declarations->varLists.size() != 1
        || read.declarations->varLists.front().variables.size() != 1)
        return std::nullopt;
    return read.declarations->varLists.front().variables.front();
}

bool classParses(const QString &varClass)
{
    const DeclarationTextResult read = readDeclarationText(QString(varClass + QStringLiteral("\nEND_VAR\n")));
    return read.declarations && read.declarations->varLists.size() == 1;
}

// The type alone must declare one variable without an initial value: "INT := 5" or "INT; b : BOOL"
// belong in other cells.
bool typeParses(const QString &type)
{
    const auto variable = singleVariable(QStringLiteral("VAR\nx : %1;\nEND_VAR\n").arg(type));
    return variable && !variable->initialValue;
}

bool initialValueParses(const QString &type, const QString &initialValue)
{
    return singleVariable(QStringLiteral("VAR\nx : %1 := %2;\nEND_VAR\n").arg(type, initialValue)).has_value();
}

void validateRow(const DeclarationRow &row, int index, std::vector<RowProblem> &problems)
{
    if (!isValidIdentifier(row.name))
        problems.push_back({index, DeclarationColumn::Name, invalidNameMessage(row.name)});
    if (!classParses(row.varClass))
        problems.push_back({index, DeclarationColumn::Class,
            QCoreApplication::translate("iec::editors::DeclarationRows", "\"%1\" is not a variable class.")
                .arg(row.varClass)});
    const bool typeOk = typeParses(row.type);
    if (!typeOk)
        problems.push_back({index, DeclarationColumn::Type,
            QCoreApplication::translate("iec::editors::DeclarationRows", "\"%1\" is not a data type.").arg(row.type)});
    if (typeOk && !row.initialValue.trimmed().isEmpty() && !initialValueParses(row.type, row.initialValue))
        problems.push_back({index, DeclarationColumn::InitialValue,
            QCoreApplication::translate("iec::editors::DeclarationRows", "\"%1\" is not an initial value for %2.")
                .arg(row.initialValue, row.type)});
    if (!row.address.isEmpty() && !isValidAddress(row.address))
        problems.push_back({index, DeclarationColumn::Address, invalidAddressMessage(row.address)});
}

// Consecutive rows of one class become one section; each row is one line.
QString textFromRows(const std::vector<DeclarationRow> &rows)
{
    QString text;
    for (size_t i = 0; i < rows.size(); ++i) {
        const DeclarationRow &row = rows[i];
        if (i == 0 || rows[i - 1].varClass != row.varClass)
            text += row.varClass + QLatin1Char('\n');
        text += QStringLiteral("    ")
            + declarationLine(row.name, row.address, row.type, row.initialValue.trimmed(), row.comment)
            + QLatin1Char('\n');
        if (i + 1 == rows.size() || rows[i + 1].varClass != row.varClass)
            text += QStringLiteral("END_VAR\n");
    }
    return text;
}

} // namespace

QStringList declarationClasses()
{
    return {QStringLiteral("VAR"), QStringLiteral("VAR CONSTANT"), QStringLiteral("VAR RETAIN"),
        QStringLiteral("VAR_INPUT"), QStringLiteral("VAR_INPUT RETAIN"), QStringLiteral("VAR_OUTPUT"),
        QStringLiteral("VAR_OUTPUT RETAIN"), QStringLiteral("VAR_IN_OUT"), QStringLiteral("VAR_EXTERNAL"),
        QStringLiteral("VAR_EXTERNAL CONSTANT"), QStringLiteral("VAR_GLOBAL"), QStringLiteral("VAR_GLOBAL CONSTANT"),
        QStringLiteral("VAR_GLOBAL RETAIN"), QStringLiteral("VAR_TEMP")};
}

std::vector<DeclarationRow> rowsFromInterface(const model::Interface &declarations)
{
    std::vector<DeclarationRow> rows;
    for (const model::VarList &list : declarations.varLists) {
        const QString varClass = sectionHeader(list);
        for (const model::Variable &variable : list.variables) {
            rows.push_back({variable.name, varClass, interp::frontend::printDataType(variable.type),
                variable.initialValue ? interp::frontend::printValue(*variable.initialValue) : QString(),
                variable.address.value_or(QString()),
                variable.documentation ? variable.documentation->text : QString()});
        }
    }
    return rows;
}

std::vector<RowProblem> validateRows(const std::vector<DeclarationRow> &rows)
{
    std::vector<RowProblem> problems;
    QStringList seen;
    for (int index = 0; index < int(rows.size()); ++index) {
        const DeclarationRow &row = rows[size_t(index)];
        validateRow(row, index, problems);
        if (seen.contains(row.name, Qt::CaseInsensitive))
            problems.push_back({index, DeclarationColumn::Name, duplicateNameMessage(row.name)});
        seen << row.name;
    }
    return problems;
}

RowsResult interfaceFromRows(const std::vector<DeclarationRow> &rows, const model::Interface &base)
{
    RowsResult result;
    result.problems = validateRows(rows);
    if (!result.problems.empty())
        return result;
    DeclarationTextResult read = readDeclarationText(textFromRows(rows), base);
    // Every row was checked on its own, so a problem here would be a gap in validateRows.
    for (const DeclarationProblem &problem : read.problems)
        result.problems.push_back({0, DeclarationColumn::Name, problem.message});
    result.declarations = std::move(read.declarations);
    return result;
}

QString freeVariableName(const std::vector<DeclarationRow> &rows, const QString &stem)
{
    for (int number = 1;; ++number) {
        const QString name = stem + QString::number(number);
        const bool taken = std::ranges::any_of(
            rows, [&](const DeclarationRow &row) { return row.name.compare(name, Qt::CaseInsensitive) == 0; });
        if (!taken)
            return name;
    }
}

} // namespace iec::editors
