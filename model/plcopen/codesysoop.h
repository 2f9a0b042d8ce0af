#pragma once

#include "model/pou.h"
#include "model/project.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

// Object orientation as CODESYS 3.5 writes it into PLCopen XML: a function block's methods and
// properties in its addData (.../plcopenxml/method, .../plcopenxml/property), EXTENDS and
// IMPLEMENTS in its interface's addData (.../plcopenxml/pouinheritance), and interfaces in
// addData entries of the project or a resource (.../plcopenxml/interface). They are read here
// for the compiler; the addData itself stays as it is in the model, so a file is written back
// unchanged.
namespace iec::model::plcopen {

struct CodesysMember {
    enum class Kind { Method, Getter, Setter };
    Kind kind = Kind::Method;
    QString name;
    QStringList qualifiers; // PUBLIC, PRIVATE, PROTECTED, INTERNAL, ABSTRACT, FINAL (upper case)
    Interface interface;    // the variables (and the method's return type)
    std::optional<DataType> type; // a property's type
    std::optional<Body> body;     // none: a prototype
};

struct CodesysClass {
    QString extends;
    QStringList implements; // an interface: the interfaces it extends
    std::vector<CodesysMember> members;
};

// The methods, properties, EXTENDS and IMPLEMENTS CODESYS keeps in `pou`'s addData.
CodesysClass readCodesysClass(const Pou &pou);

// A method or property to store in CODESYS's form: what readCodesysClass reads back.
struct CodesysMemberDefinition {
    struct Accessor {
        Interface interface; // its local variables
        std::optional<Body> body; // none: a prototype (ABSTRACT)
    };
    bool property = false;
    QString name;
    // The declaration as text (header and variables), kept in the member's own addData as CODESYS
    // does (InterfaceAsPlainText): it carries the qualifiers (PRIVATE, ABSTRACT ...).
    QString declarationText;
    Interface interface;       // a method's variables and return type; a property's type as returnType
    std::optional<Body> body;  // a method's; none: a prototype
    std::optional<Accessor> getter, setter; // a property's
};

// `addData` (a POU's) with the member called `name` replaced by `member` where it stands, keeping
// its ObjectId and the rest of its own addData; appended in an entry of its own when no member
// is called `name`. Every other entry stays as it is, byte for byte.
AddData addDataWithMember(const AddData &addData, const QString &name, const CodesysMemberDefinition &member);
// `addData` without the member called `name`.
AddData addDataWithoutMember(const AddData &addData, const QString &name);

// An INTERFACE to store in CODESYS's form: its name, the interfaces it extends and the
// prototypes of its methods and properties (their bodies are not written).
struct CodesysInterfaceDefinition {
    QString name;
    QStringList extends;
    std::vector<CodesysMemberDefinition> members;
};

// The project's addData with the INTERFACE called `replacing` (case-insensitive) replaced by
// `definition` where it stands, keeping its attributes (ObjectId); appended in CODESYS's
// interface entry of its own when none is called `replacing`. Every other entry stays as it is.
AddData addDataWithInterface(const AddData &addData, const QString &replacing, const CodesysInterfaceDefinition &definition);
// `addData` without the INTERFACE called `name` (an entry left empty goes too).
AddData addDataWithoutInterface(const AddData &addData, const QString &name);
// True when `addData` itself (not a configuration's or resource's) keeps INTERFACE `name`.
bool keepsInterface(const AddData &addData, const QString &name);
// An interface's addData saying EXTENDS `extends` and IMPLEMENTS `implements` (CODESYS's
// pouinheritance entry, replaced or added; none when both are empty).
AddData addDataWithInheritance(const AddData &addData, const QString &extends, const QStringList &implements);

// An INTERFACE CODESYS keeps in an addData entry: its name and its methods and properties.
struct CodesysInterface {
    QString name;
    CodesysClass definition;
};
std::vector<CodesysInterface> readCodesysInterfaces(const Project &project);

} // namespace iec::model::plcopen
