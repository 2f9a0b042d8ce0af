#include "editors/common/boxspec.h"

#include "editors/text/standardlibrary.h"

#include <QCoreApplication>

namespace iec::editors {

using namespace model;

namespace {

bool isBoolType(const QString &type)
{
    const QString t = type.trimmed().toUpper();
    return t == QLatin1String("BOOL") || t == QLatin1String("ANY_BIT") || t == QLatin1String("ANY");
}

bool isBoolType(const DataType &type)
{
    const auto *elementary = std::get_if<ElementaryType>(&type.kind);
    return elementary && elementary->name.compare(QLatin1String("BOOL"), Qt::CaseInsensitive) == 0;
}

// The rung pins: the first BOOL pin on each side, or EN/ENO when there is none or when asked.
void chooseRungPins(BoxSpec &spec, const std::vector<bool> &boolInputs, const std::vector<bool> &boolOutputs)
{
    const auto first = [](const std::vector<bool> &flags) {
        const auto it = std::ranges::find(flags, true);
        return it == flags.end() ? -1 : int(it - flags.begin());
    };
    spec.rungInput = first(boolInputs);
    spec.rungOutput = first(boolOutputs);
    if (spec.rungInput < 0 || spec.rungOutput < 0)
        spec.withEn = true;
}

std::optional<BoxSpec> fromStandardLibrary(const StdPou &pou, bool withEn)
{
    BoxSpec spec;
    spec.typeName = pou.name;
    spec.functionBlock = pou.kind == StdPou::Kind::FunctionBlock;
    spec.withEn = withEn;
    std::vector<bool> boolInputs;
    std::vector<bool> boolOutputs;
    for (const StdParameter &p : pou.inputs) {
        spec.inputs << p.name;
        boolInputs.push_back(isBoolType(p.type));
    }
    if (spec.functionBlock) {
        for (const StdParameter &p : pou.outputs) {
            spec.outputs << p.name;
            boolOutputs.push_back(isBoolType(p.type));
        }
    } else {
        spec.outputs << QStringLiteral("OUT");
        // Comparisons and arithmetic run on EN/ENO, as in CODESYS.
        boolOutputs.push_back(false);
        boolInputs.assign(boolInputs.size(), false);
    }
    if (!withEn)
        chooseRungPins(spec, boolInputs, boolOutputs);
    return spec;
}

// The logic operators are boxes too (they are operators in ST, so not in the function table):
// the rung passes through their first input, AND(rung, b) is the rung AND b.
std::optional<BoxSpec> logicOperator(const QString &name, bool withEn)
{
    const QString upper = name.toUpper();
    BoxSpec spec;
    spec.typeName = upper;
    spec.withEn = withEn;
    spec.outputs << QStringLiteral("OUT");
    if (upper == QLatin1String("NOT"))
        spec.inputs << QStringLiteral("IN");
    else if (upper == QLatin1String("AND") || upper == QLatin1String("OR") || upper == QLatin1String("XOR"))
        spec.inputs << QStringLiteral("IN1") << QStringLiteral("IN2");
    else
        return std::nullopt;
    return spec;
}

std::optional<BoxSpec> fromProject(const Pou &pou, bool withEn)
{
    BoxSpec spec;
    spec.typeName = pou.name;
    spec.functionBlock = pou.kind == PouKind::FunctionBlock;
    spec.withEn = withEn;
    std::vector<bool> boolInputs;
    std::vector<bool> boolOutputs;
    if (pou.pouInterface) {
        for (const VarList &list : pou.pouInterface->varLists) {
            for (const Variable &v : list.variables) {
                if (list.kind == VarListKind::Input || list.kind == VarListKind::InOut) {
                    spec.inputs << v.name;
                    boolInputs.push_back(list.kind == VarListKind::Input && isBoolType(v.type));
                } else if (list.kind == VarListKind::Output && spec.functionBlock) {
                    spec.outputs << v.name;
                    boolOutputs.push_back(isBoolType(v.type));
                }
            }
        }
    }
    if (!spec.functionBlock) {
        spec.outputs << QStringLiteral("OUT");
        boolOutputs.push_back(pou.pouInterface && pou.pouInterface->returnType && isBoolType(*pou.pouInterface->returnType));
    }
    if (!withEn)
        chooseRungPins(spec, boolInputs, boolOutputs);
    return spec;
}

} // namespace

std::optional<BoxSpec> boxSpecFor(const Project &project, const QString &typeName, bool withEn, QString *error)
{
    const QString name = typeName.trimmed();
    if (const Pou *pou = project.findPou(name)) {
        if (pou->kind == PouKind::Program) {
            if (error)
                *error = QCoreApplication::translate("iec::editors::ld::LdEdits", "%1 is a program: a box calls a function or a function block.").arg(pou->name);
            return std::nullopt;
        }
        return fromProject(*pou, withEn);
    }
    if (const StdPou *pou = findStandardPou(name))
        return fromStandardLibrary(*pou, withEn);
    if (std::optional<BoxSpec> spec = logicOperator(name, withEn))
        return spec;
    if (error)
        *error = QCoreApplication::translate("iec::editors::ld::LdEdits",
            "There is no function or function block called %1 (in the standard library or the project).").arg(name);
    return std::nullopt;
}

bool isExtensible(const QString &typeName)
{
    static const QStringList kExtensible {QStringLiteral("ADD"), QStringLiteral("MUL"), QStringLiteral("AND"),
        QStringLiteral("OR"), QStringLiteral("XOR"), QStringLiteral("MAX"), QStringLiteral("MIN"),
        QStringLiteral("CONCAT"), QStringLiteral("MUX")};
    return kExtensible.contains(typeName.trimmed(), Qt::CaseInsensitive);
}

namespace {

model::BlockVariable unwiredPin(const QString &name, bool input)
{
    model::BlockVariable v;
    v.formalParameter = name;
    if (input)
        v.connectionPointIn.emplace();
    else
        v.connectionPointOut.emplace();
    return v;
}

} // namespace

model::Block blockFromSpec(const BoxSpec &spec)
{
    model::Block block;
    block.typeName = spec.typeName;
    if (spec.functionBlock)
        block.instanceName = kPlaceholder;
    if (spec.withEn) {
        block.inputVariables.push_back(unwiredPin(QStringLiteral("EN"), true));
        block.outputVariables.push_back(unwiredPin(QStringLiteral("ENO"), false));
    }
    for (const QString &name : spec.inputs)
        block.inputVariables.push_back(unwiredPin(name, true));
    for (const QString &name : spec.outputs)
        block.outputVariables.push_back(unwiredPin(name, false));
    return block;
}

} // namespace iec::editors
