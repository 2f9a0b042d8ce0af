#include "app/autodeclare.h"

#include "app/projectsymbols.h"
#include "editors/datatypes/typetext.h"
#include "editors/text/standardlibrary.h"
#include "interpreter/compiler/lexer.h"
#include "model/projectmodel.h"
#include "model/undo/variablecommands.h"

#include <QCoreApplication>
#include <QSet>

namespace iec::app {

namespace {

using interp::TokenKind;

struct Word {
    TokenKind kind;
    QString text; // upper case for keywords and operators, as written for the rest
};

std::vector<Word> wordsOf(const QString &text)
{
    std::vector<Word> words;
    for (const interp::Token &token : interp::tokenize(text)) {
        if (token.kind == TokenKind::Comment || token.kind == TokenKind::Pragma)
            continue;
        QString word = text.mid(token.offset, token.length);
        if (token.kind == TokenKind::Keyword || token.kind == TokenKind::Operator)
            word = word.toUpper();
        words.push_back({token.kind, word});
    }
    return words;
}

bool isName(const Word &word, const QString &name)
{
    return word.kind == TokenKind::Identifier && word.text.compare(name, Qt::CaseInsensitive) == 0;
}

// The members (T1.Q) and formal parameters (T1(IN := ...)) a body uses with `name`.
QSet<QString> usedParameters(const std::vector<Word> &words, const QString &name, bool *called)
{
    QSet<QString> used;
    for (size_t i = 0; i + 1 < words.size(); ++i) {
        if (!isName(words[i], name))
            continue;
        if (words[i + 1].text == QLatin1String(".") && i + 2 < words.size())
            used.insert(words[i + 2].text.toUpper());
        if (words[i + 1].text != QLatin1String("("))
            continue;
        *called = true;
        int depth = 0;
        for (size_t j = i + 1; j < words.size(); ++j) {
            if (words[j].text == QLatin1String("("))
                ++depth;
            else if (words[j].text == QLatin1String(")") && --depth == 0)
                break;
            else if (depth == 1 && j + 1 < words.size() && words[j].kind == TokenKind::Identifier
                && (words[j + 1].text == QLatin1String(":=") || words[j + 1].text == QLatin1String("=>")))
                used.insert(words[j].text.toUpper());
        }
    }
    return used;
}

bool hasAll(const QSet<QString> &parameters, const QSet<QString> &used)
{
    for (const QString &each : used) {
        if (!parameters.contains(each))
            return false;
    }
    return true;
}

bool fitsStandard(const editors::StdPou &pou, const QSet<QString> &used)
{
    QSet<QString> parameters;
    for (const editors::StdParameter &parameter : pou.inputs + pou.outputs)
        parameters.insert(parameter.name.toUpper());
    return hasAll(parameters, used);
}

// The first function block, the project's before the standard ones, that has every parameter used.
QString functionBlockFor(const model::Project &project, const QSet<QString> &used)
{
    for (const model::Pou &pou : project.types.pous) {
        if (pou.kind != model::PouKind::FunctionBlock || !pou.pouInterface)
            continue;
        QSet<QString> parameters;
        for (const model::VarList &list : pou.pouInterface->varLists) {
            for (const model::Variable &variable : list.variables)
                parameters.insert(variable.name.toUpper());
        }
        if (hasAll(parameters, used))
            return pou.name;
    }
    for (const QString &name : commonFunctionBlocks()) {
        const editors::StdPou *pou = editors::findStandardPou(name);
        if (pou && fitsStandard(*pou, used))
            return pou->name;
    }
    for (const editors::StdPou &pou : editors::standardPous()) {
        if (pou.kind == editors::StdPou::Kind::FunctionBlock && fitsStandard(pou, used))
            return pou.name;
    }
    return {};
}

bool isArithmetic(const QString &op)
{
    static const QSet<QString> ops {QStringLiteral("+"), QStringLiteral("-"), QStringLiteral("*"),
        QStringLiteral("/"), QStringLiteral("MOD"), QStringLiteral("ADD"), QStringLiteral("SUB"),
        QStringLiteral("MUL"), QStringLiteral("DIV"), QStringLiteral("GT"), QStringLiteral("GE"),
        QStringLiteral("LT"), QStringLiteral("LE"), QStringLiteral("EQ"), QStringLiteral("NE")};
    return ops.contains(op);
}

// The type a single operand next to the name says the name has; empty when it says nothing.
QString typeOfOperand(const model::Project &project, model::PouId pou, const Word &word)
{
    switch (word.kind) {
    case TokenKind::TimeLiteral:
        return QStringLiteral("TIME");
    case TokenKind::RealLiteral:
        return QStringLiteral("REAL");
    case TokenKind::StringLiteral:
        return QStringLiteral("STRING");
    case TokenKind::IntegerLiteral:
        return QStringLiteral("INT");
    case TokenKind::Keyword:
        return word.text == QLatin1String("TRUE") || word.text == QLatin1String("FALSE") ? QStringLiteral("BOOL")
                                                                                          : QString();
    case TokenKind::Identifier:
        if (const auto known = findVisibleVariable(project, pou, word.text))
            return editors::typeText(known->variable->type);
        return {};
    default:
        return {};
    }
}

// What one occurrence of the name (at `i`) says about its type; empty when it says nothing.
QString typeAt(const model::Project &project, model::PouId pou, const std::vector<Word> &words, size_t i)
{
    const auto at = [&](std::ptrdiff_t k) -> const Word * {
        const std::ptrdiff_t index = std::ptrdiff_t(i) + k;
        return index >= 0 && index < std::ptrdiff_t(words.size()) ? &words[size_t(index)] : nullptr;
    };
    // x := <expression>: the expression's first operand that tells.
    if (at(1) && at(1)->text == QLatin1String(":=")) {
        for (size_t j = i + 2; j < words.size() && words[j].text != QLatin1String(";"); ++j) {
            if (const QString type = typeOfOperand(project, pou, words[j]); !type.isEmpty())
                return type;
            if (isArithmetic(words[j].text))
                return QStringLiteral("INT");
        }
        return {};
    }
    // <operand> <op> x and x <op> <operand>, also y := x.
    for (const int side : {-1, 1}) {
        const Word *op = at(side);
        const Word *other = at(2 * side);
        if (!op)
            continue;
        if (op->kind == TokenKind::Operator && other && op->text != QLatin1String("(")
            && op->text != QLatin1String(")") && op->text != QLatin1String(";")) {
            if (const QString type = typeOfOperand(project, pou, *other); !type.isEmpty())
                return type;
        }
        if (isArithmetic(op->text))
            return QStringLiteral("INT");
    }
    return {};
}

} // namespace

const QStringList &commonFunctionBlocks()
{
    static const QStringList names {QStringLiteral("TON"), QStringLiteral("TOF"), QStringLiteral("TP"),
        QStringLiteral("CTU"), QStringLiteral("CTD"), QStringLiteral("CTUD"), QStringLiteral("R_TRIG"),
        QStringLiteral("F_TRIG"), QStringLiteral("SR"), QStringLiteral("RS")};
    return names;
}

QString guessVariableType(
    const model::Project &project, model::PouId pou, const QString &bodyText, const QString &name, bool il)
{
    Q_UNUSED(il); // IL operators are keywords to the lexer: ADD x reads like + x, S x like a coil
    const std::vector<Word> words = wordsOf(bodyText);
    bool called = false;
    const QSet<QString> used = usedParameters(words, name, &called);
    if (!used.isEmpty() || called) {
        if (const QString fb = functionBlockFor(project, used); !fb.isEmpty())
            return fb;
    }
    for (size_t i = 0; i < words.size(); ++i) {
        if (!isName(words[i], name))
            continue;
        if (const QString type = typeAt(project, pou, words, i); !type.isEmpty())
            return type;
    }
    return QStringLiteral("BOOL");
}

DeclareResult createDeclareCommand(model::ProjectModel &model, model::PouId pou, const editors::DeclarationRow &row)
{
    const model::Pou *found = model.project().findPou(pou);
    if (!found)
        return {.error = QCoreApplication::translate("iec::app::AutoDeclare", "The POU does not exist any more.")};
    const model::Interface before = found->pouInterface.value_or(model::Interface {});
    std::vector<editors::DeclarationRow> rows = editors::rowsFromInterface(before);
    auto at = rows.end();
    for (auto it = rows.begin(); it != rows.end(); ++it) {
        if (it->varClass == row.varClass)
            at = it + 1;
    }
    const auto index = int(at - rows.begin());
    rows.insert(at, row);
    const editors::RowsResult result = editors::interfaceFromRows(rows, before);
    if (!result.declarations) {
        for (const editors::RowProblem &problem : result.problems) {
            if (problem.row == index)
                return {.error = problem.message};
        }
        return {.error = result.problems.empty() ? QString() : result.problems.front().message};
    }
    auto *command = new model::SetInterfaceCommand(model, pou, result.declarations);
    command->setText(QCoreApplication::translate("iec::app::AutoDeclare", "Declare %1").arg(row.name));
    return {.command = command};
}

} // namespace iec::app
