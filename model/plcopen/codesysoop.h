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

// An INTERFACE CODESYS keeps in an addData entry: its name and its methods and properties.
struct CodesysInterface {
    QString name;
    CodesysClass definition;
};
std::vector<CodesysInterface> readCodesysInterfaces(const Project &project);

} // namespace iec::model::plcopen
