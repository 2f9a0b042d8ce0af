#pragma once

#include "model/project.h"

#include <QString>
#include <QStringList>

// Prints the project model as IEC 61131-3 text (the textual form of part 3 of the standard):
// TYPE ... END_TYPE, PROGRAM / FUNCTION_BLOCK / FUNCTION with their VAR sections and ST or IL
// bodies, and CONFIGURATION / RESOURCE / TASK. The same text is what `iecstudio-cli convert`
// writes and what the compiler front end parses declarations from (projectsource.h), so a
// declaration diagnostic points at a line the user can see with `convert FILE OUT.st`.
namespace iec::interp::frontend {

// A problem met while printing (a graphical body has no text form): POU and one sentence.
struct PrintWarning {
    QString pou;
    QString message;
};

QString printDataType(const model::DataType &type);
QString printValue(const model::Value &value);
QString printVarList(const model::VarList &list);

// TYPE name : ... ; END_TYPE for one declared type.
QString printTypeDeclaration(const model::DataTypeDecl &type);
// The POU's header and interface with an empty body: PROGRAM Main VAR ... END_VAR END_PROGRAM.
QString printPouSkeleton(const model::Pou &pou);
// The whole POU with its body (and actions). Graphical bodies become a comment and a warning.
QString printPou(const model::Pou &pou, std::vector<PrintWarning> *warnings = nullptr);
QString printConfiguration(const model::Configuration &configuration);

// Every data type, every POU and every configuration, in that order.
QString printProject(const model::Project &project, std::vector<PrintWarning> *warnings = nullptr);

// The IEC keyword of a body language for messages: ST, IL, LD, FBD, SFC.
QString languageName(model::BodyLanguage language);

} // namespace iec::interp::frontend
