#pragma once

#include "interpreter/compiler/diagnostics.h"

#include "model/plcopen/codesysoop.h"
#include "model/pou.h"
#include "model/project.h"

#include <QString>
#include <QStringList>
#include <QStringView>

#include <optional>
#include <vector>

// A function block's methods and properties, which CODESYS keeps in the POU's addData
// (model/plcopen/codesysoop.h), as text in the form of IEC 61131-3 edition 3:
//   METHOD [PRIVATE|PROTECTED|INTERNAL|PUBLIC] [ABSTRACT|FINAL] Name [: Type]
//   VAR_INPUT ... END_VAR ...
//   body
//   END_METHOD
// and PROPERTY Name : Type with GET ... END_GET and SET ... END_SET, ended by END_PROPERTY.
// The IDE edits members in this form, and .st files hold them inside FUNCTION_BLOCK.
namespace iec::interp::frontend {

struct CodesysMemberSummary {
    QString name;
    bool property = false;
};

// The methods and properties of `pou`, in the order they stand; a property once.
std::vector<CodesysMemberSummary> codesysMembers(const model::Pou &pou);

// Member `name` of `pou` as text; empty when `pou` has no such member. A body in a graphical
// language has no text form: it shows as a comment and `editable` is set false.
QString printCodesysMember(const model::Pou &pou, const QString &name, bool *editable = nullptr);

// Every INTERFACE the project keeps in CODESYS's addData, as INTERFACE Name [EXTENDS ...] with its
// prototypes and END_INTERFACE.
QString printCodesysInterfaces(const model::Project &project);
// Their names, in the order they stand; one of them as text (empty when there is none).
QStringList codesysInterfaceNames(const model::Project &project);
QString printCodesysInterface(const model::Project &project, const QString &name);

struct CodesysMemberText {
    std::optional<model::plcopen::CodesysMemberDefinition> definition; // none after an error
    Diagnostics diagnostics; // at lines and columns of the text, in POU "owner.Name"
};

// Reads one METHOD ... END_METHOD or PROPERTY ... END_PROPERTY of the POU named `owner`.
// Bodies are kept exactly as written.
CodesysMemberText readCodesysMemberText(QStringView text, const QString &owner);

// The 1-based lines where the bodies of a member's text start, to place the compiler's messages
// about them (they count lines in the body, POU "Owner.Name"): a method's body; a property's GET
// and SET bodies. 0: no such body.
struct MemberBodyLines {
    int body = 0;
    int getter = 0;
    int setter = 0;
};
MemberBodyLines memberBodyLines(QStringView text);

} // namespace iec::interp::frontend
