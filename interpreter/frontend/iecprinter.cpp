#include "interpreter/frontend/iecprinter.h"

#include "interpreter/frontend/codesysmembers.h"
#include "interpreter/frontend/duration.h"
#include "interpreter/runtime/valueformat.h"
#include "interpreter/sfc/sfctext.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QTextStream>

namespace iec::interp::frontend {

namespace {

const QString kIndent = QStringLiteral("    ");

QString indented(const QString &text, const QString &indent)
{
    QStringList lines = text.split(QLatin1Char('\n'));
    for (QString &line : lines) {
        if (!line.isEmpty())
            line.prepend(indent);
    }
    return lines.join(QLatin1Char('\n'));
}

QString printRange(const model::Range &range)
{
    return range.lower + QStringLiteral("..") + range.upper;
}

QString printEnum(const model::EnumType &type)
{
    QStringList values;
    for (const model::EnumValue &value : type.values)
        values << (value.value ? value.name + QStringLiteral(" := ") + *value.value : value.name);
    QString text = QLatin1Char('(') + values.join(QStringLiteral(", ")) + QLatin1Char(')');
    if (type.baseType)
        text += QLatin1Char(' ') + printDataType(**type.baseType); // CODESYS: (a, b) INT
    return text;
}

QString printVariable(const model::Variable &variable)
{
    QString line = variable.name;
    if (variable.address)
        line += QStringLiteral(" AT ") + *variable.address;
    line += QStringLiteral(" : ") + printDataType(variable.type);
    if (variable.initialValue)
        line += QStringLiteral(" := ") + printValue(*variable.initialValue);
    return line + QLatin1Char(';');
}

QString printStruct(const model::StructType &type)
{
    QString text = QStringLiteral("STRUCT\n");
    for (const model::Variable &member : type.members)
        text += kIndent + printVariable(member) + QLatin1Char('\n');
    return text + QStringLiteral("END_STRUCT");
}

QString varListKeyword(model::VarListKind kind)
{
    switch (kind) {
    case model::VarListKind::Local:
        return QStringLiteral("VAR");
    case model::VarListKind::Temp:
        return QStringLiteral("VAR_TEMP");
    case model::VarListKind::Input:
        return QStringLiteral("VAR_INPUT");
    case model::VarListKind::Output:
        return QStringLiteral("VAR_OUTPUT");
    case model::VarListKind::InOut:
        return QStringLiteral("VAR_IN_OUT");
    case model::VarListKind::External:
        return QStringLiteral("VAR_EXTERNAL");
    case model::VarListKind::Global:
        return QStringLiteral("VAR_GLOBAL");
    case model::VarListKind::Access:
        return QStringLiteral("VAR_ACCESS");
    }
    return QStringLiteral("VAR");
}

QString pouKeyword(model::PouKind kind)
{
    switch (kind) {
    case model::PouKind::Program:
        return QStringLiteral("PROGRAM");
    case model::PouKind::FunctionBlock:
        return QStringLiteral("FUNCTION_BLOCK");
    case model::PouKind::Function:
        return QStringLiteral("FUNCTION");
    }
    return QStringLiteral("PROGRAM");
}

QString printInterface(const model::Pou &pou)
{
    QString text;
    if (!pou.pouInterface)
        return text;
    for (const model::VarList &list : pou.pouInterface->varLists)
        text += printVarList(list);
    return text;
}

QString pouHeader(const model::Pou &pou)
{
    QString header = pouKeyword(pou.kind) + QLatin1Char(' ') + pou.name;
    if (pou.kind == model::PouKind::Function && pou.pouInterface && pou.pouInterface->returnType)
        header += QStringLiteral(" : ") + printDataType(*pou.pouInterface->returnType);
    return header + QLatin1Char('\n');
}

// The text of an ST/IL body, or a comment (and a warning) for a graphical one.
QString printBody(const model::Body &body, const QString &where, std::vector<PrintWarning> *warnings)
{
    if (!body.isGraphical()) {
        QString text = body.text();
        if (!text.isEmpty() && !text.endsWith(QLatin1Char('\n')))
            text += QLatin1Char('\n');
        return text;
    }
    const QString language = languageName(body.language());
    if (warnings) {
        warnings->push_back({where,
            QCoreApplication::translate("iec::interp::Compiler", "%1 is written in %2, which has no IEC text form; its body was left out.")
                .arg(where, language)});
    }
    return QStringLiteral("(* The %1 body of %2 has no IEC text form and was left out. *)\n").arg(language, where);
}

QString printTask(const model::Task &task)
{
    QStringList settings;
    if (task.single)
        settings << QStringLiteral("SINGLE := ") + *task.single;
    if (task.interval) {
        const auto ns = parseDuration(*task.interval);
        settings << QStringLiteral("INTERVAL := ") + (ns ? formatDuration(*ns) : *task.interval);
    }
    settings << QStringLiteral("PRIORITY := %1").arg(task.priority);
    return QStringLiteral("TASK %1(%2);\n").arg(task.name, settings.join(QStringLiteral(", ")));
}

QString printProgramInstance(const model::PouInstance &instance, const QString &task)
{
    const QString with = task.isEmpty() ? QString() : QStringLiteral(" WITH ") + task;
    if (!instance.typeName.isEmpty())
        return QStringLiteral("PROGRAM %1%2 : %3;\n").arg(instance.name, with, instance.typeName);
    // CODESYS 3.5 writes typeName="" and names the instance after its program (main), or after a
    // program it generates and does not export (VisuElems.Visu_Prg), which is left out.
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*$"));
    if (identifier.match(instance.name).hasMatch())
        return QStringLiteral("PROGRAM %1%2 : %1;\n").arg(instance.name, with);
    return QStringLiteral("(* PROGRAM %1%2 has no program type in the file and was left out. *)\n").arg(instance.name, with);
}

// A configuration's or resource's VAR_GLOBAL lists. IEC text has no name for a list; CODESYS
// V2.3 exports a global variable list's name in a comment before it, which the reader takes back.
QString printGlobalLists(const std::vector<model::VarList> &lists)
{
    QString text;
    for (const model::VarList &list : lists) {
        if (list.name && !list.name->isEmpty())
            text += QStringLiteral("(* @GLOBAL_VARIABLE_LIST := %1 *)\n").arg(*list.name);
        text += printVarList(list);
    }
    return text;
}

QString printResource(const model::Resource &resource)
{
    QString body = printGlobalLists(resource.globalVars);
    for (const model::Task &task : resource.tasks)
        body += printTask(task);
    for (const model::Task &task : resource.tasks) {
        for (const model::PouInstance &instance : task.pouInstances)
            body += printProgramInstance(instance, task.name);
    }
    for (const model::PouInstance &instance : resource.pouInstances)
        body += printProgramInstance(instance, {});
    // IEC wants a processor type after ON; PLCopen has none, so every resource runs on "PLC".
    return QStringLiteral("RESOURCE %1 ON PLC\n").arg(resource.name) + indented(body, kIndent)
        + QStringLiteral("END_RESOURCE\n");
}

} // namespace

QString languageName(model::BodyLanguage language)
{
    switch (language) {
    case model::BodyLanguage::ST:
        return QStringLiteral("ST");
    case model::BodyLanguage::IL:
        return QStringLiteral("IL");
    case model::BodyLanguage::LD:
        return QStringLiteral("LD");
    case model::BodyLanguage::FBD:
        return QStringLiteral("FBD");
    case model::BodyLanguage::SFC:
        return QStringLiteral("SFC");
    }
    return QString();
}

QString printDataType(const model::DataType &type)
{
    return std::visit(
        [](const auto &kind) -> QString {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (std::is_same_v<Kind, model::ElementaryType>) {
                return kind.name;
            } else if constexpr (std::is_same_v<Kind, model::StringType>) {
                const QString name = kind.wide ? QStringLiteral("WSTRING") : QStringLiteral("STRING");
                return kind.length ? name + QLatin1Char('[') + *kind.length + QLatin1Char(']') : name;
            } else if constexpr (std::is_same_v<Kind, model::ArrayType>) {
                QStringList dimensions;
                for (const model::Range &range : kind.dimensions)
                    dimensions << printRange(range);
                return QStringLiteral("ARRAY[%1] OF %2")
                    .arg(dimensions.join(QStringLiteral(", ")), printDataType(*kind.baseType));
            } else if constexpr (std::is_same_v<Kind, model::DerivedType>) {
                return kind.name;
            } else if constexpr (std::is_same_v<Kind, model::EnumType>) {
                return printEnum(kind);
            } else if constexpr (std::is_same_v<Kind, model::StructType>) {
                return printStruct(kind);
            } else if constexpr (std::is_same_v<Kind, model::SubrangeType>) {
                return QStringLiteral("%1 (%2)").arg(printDataType(*kind.baseType), printRange(kind.range));
            } else {
                return QStringLiteral("REF_TO ") + printDataType(*kind.baseType);
            }
        },
        type.kind);
}

QString printValue(const model::Value &value)
{
    return std::visit(
        [](const auto &kind) -> QString {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (std::is_same_v<Kind, model::SimpleValue>) {
                return kind.value.value_or(QString());
            } else if constexpr (std::is_same_v<Kind, model::ArrayValue>) {
                QStringList items;
                for (const model::ArrayValueItem &item : kind.values) {
                    const QString text = printValue(*item.value);
                    items << (item.repetitionValue ? *item.repetitionValue + QLatin1Char('(') + text + QLatin1Char(')')
                                                   : text);
                }
                return QLatin1Char('[') + items.join(QStringLiteral(", ")) + QLatin1Char(']');
            } else {
                QStringList items;
                for (const model::StructValueItem &item : kind.values)
                    items << item.member + QStringLiteral(" := ") + printValue(*item.value);
                return QLatin1Char('(') + items.join(QStringLiteral(", ")) + QLatin1Char(')');
            }
        },
        value.kind);
}

QString printVarList(const model::VarList &list)
{
    QString text = varListKeyword(list.kind);
    if (list.constant)
        text += QStringLiteral(" CONSTANT");
    if (list.retain)
        text += QStringLiteral(" RETAIN");
    if (list.nonretain)
        text += QStringLiteral(" NON_RETAIN");
    if (list.persistent)
        text += QStringLiteral(" PERSISTENT");
    text += QLatin1Char('\n');
    for (const model::Variable &variable : list.variables)
        text += indented(printVariable(variable), kIndent) + QLatin1Char('\n');
    return text + QStringLiteral("END_VAR\n");
}

QString printTypeDeclaration(const model::DataTypeDecl &type)
{
    QString line = type.name + QStringLiteral(" : ") + printDataType(type.baseType);
    if (type.initialValue)
        line += QStringLiteral(" := ") + printValue(*type.initialValue);
    return QStringLiteral("TYPE\n") + indented(line + QLatin1Char(';'), kIndent) + QStringLiteral("\nEND_TYPE\n");
}

QString printPouSkeleton(const model::Pou &pou)
{
    return pouHeader(pou) + printInterface(pou) + QStringLiteral("END_") + pouKeyword(pou.kind) + QLatin1Char('\n');
}

namespace {

// EXTENDS and IMPLEMENTS, and the methods and properties, CODESYS keeps in addData.
QString printObjectOrientation(const model::Pou &pou, QString &header)
{
    const model::plcopen::CodesysClass definition = model::plcopen::readCodesysClass(pou);
    if (!definition.extends.isEmpty() || !definition.implements.isEmpty()) {
        header.chop(1); // the line break
        if (!definition.extends.isEmpty())
            header += QStringLiteral(" EXTENDS ") + definition.extends;
        if (!definition.implements.isEmpty())
            header += QStringLiteral(" IMPLEMENTS ") + definition.implements.join(QStringLiteral(", "));
        header += QLatin1Char('\n');
    }
    QString members;
    for (const CodesysMemberSummary &member : codesysMembers(pou))
        members += printCodesysMember(pou, member.name);
    return members;
}

// The POU's body or one of its actions' (`where`: Pou or Pou.Action): text as it is, a chart as
// textual SFC; a chart the text form cannot say stays a comment.
QString printPart(const model::Pou &pou, const model::Body &body, const QString &where, std::vector<PrintWarning> *warnings)
{
    if (body.language() != model::BodyLanguage::SFC)
        return printBody(body, where, warnings);
    QStringList dropped;
    const auto chart = sfc::printChart(pou, body, where, nullptr, &dropped);
    if (!chart) {
        if (warnings) {
            warnings->push_back({where,
                QCoreApplication::translate("iec::interp::Compiler", "The chart of %1 cannot be written as textual SFC (it is incomplete, or has macro steps, actions written in a step or conditions drawn as networks); it was left out.")
                    .arg(where)});
        }
        return printBody(body, where, nullptr);
    }
    if (warnings && !dropped.isEmpty())
        warnings->push_back({where,
            QCoreApplication::translate("iec::interp::Compiler", "The entry, exit and active actions and the times of steps %1 have no IEC text form and were left out.")
                .arg(dropped.join(QStringLiteral(", ")))});
    return *chart;
}

} // namespace

QString printPou(const model::Pou &pou, std::vector<PrintWarning> *warnings)
{
    QString header = pouHeader(pou);
    const QString members = printObjectOrientation(pou, header);
    QString text = header + printInterface(pou) + members;
    if (const model::Body *body = pou.body())
        text += printPart(pou, *body, pou.name, warnings);
    for (const model::PouAction &action : pou.actions) {
        text += QStringLiteral("ACTION %1:\n").arg(action.name);
        text += printPart(pou, action.body, pou.name + QLatin1Char('.') + action.name, warnings);
        text += QStringLiteral("END_ACTION\n");
    }
    return text + QStringLiteral("END_") + pouKeyword(pou.kind) + QLatin1Char('\n');
}

QString printConfiguration(const model::Configuration &configuration)
{
    QString body = printGlobalLists(configuration.globalVars);
    for (const model::Resource &resource : configuration.resources)
        body += printResource(resource);
    return QStringLiteral("CONFIGURATION %1\n").arg(configuration.name) + indented(body, kIndent)
        + QStringLiteral("END_CONFIGURATION\n");
}

QString printProject(const model::Project &project, std::vector<PrintWarning> *warnings)
{
    QStringList parts;
    for (const model::DataTypeDecl &type : project.types.dataTypes)
        parts << printTypeDeclaration(type);
    if (const QString interfaces = printCodesysInterfaces(project); !interfaces.isEmpty())
        parts << interfaces;
    for (const model::Pou &pou : project.types.pous)
        parts << printPou(pou, warnings);
    for (const model::Configuration &configuration : project.instances.configurations)
        parts << printConfiguration(configuration);
    return parts.join(QLatin1Char('\n'));
}

} // namespace iec::interp::frontend
