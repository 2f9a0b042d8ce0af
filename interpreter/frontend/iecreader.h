#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"

#include "model/plcopen/codesysoop.h"
#include "model/project.h"

#include <QStringView>

#include <optional>

// Reads IEC 61131-3 text (.st: TYPE, PROGRAM, FUNCTION_BLOCK, FUNCTION, CONFIGURATION ... as the
// parser understands it) into the project model. Declarations become model values; ST and IL
// bodies keep their text exactly as written (comments included), so editing and converting
// back lose nothing the model can hold.
namespace iec::interp::frontend {

struct TextReadResult {
    model::Project project;
    Diagnostics diagnostics; // parse errors, and warnings for what the model cannot hold
};

// `projectName` becomes contentHeader/@name. With parse errors the project holds what was read.
TextReadResult readIecText(QStringView text, const QString &projectName);

struct InterfaceText {
    std::optional<model::plcopen::CodesysInterfaceDefinition> definition; // none after an error
    Diagnostics diagnostics; // at lines and columns of the text
};

// Reads one INTERFACE Name [EXTENDS ...] with its METHOD and PROPERTY prototypes and
// END_INTERFACE (the IDE's interface tab); anything else in the text is an error.
InterfaceText readInterfaceText(QStringView text);

// Declarations the parser read, as model values; what the model cannot hold is a warning.
std::vector<model::VarList> varListsFromAst(
    const std::vector<ast::VarSection> &sections, const QString &owner, Diagnostics &diagnostics);
model::DataType dataTypeFromAst(const ast::TypeSpec &spec);

} // namespace iec::interp::frontend
