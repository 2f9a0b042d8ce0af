#pragma once

#include "model/elements_fbd.h"
#include "model/project.h"

#include <QString>
#include <QStringList>

#include <optional>

// What a box in a rung looks like: its pins from the standard library (the CODESYS V2.3 set the
// editors offer) or from the project's own POU, and which pins carry the rung: a function
// block's first BOOL input and output (TON's IN and Q, CTU's CU and Q), a logic function's first
// input and its output (AND, OR, XOR, NOT); everything else (and every "box with EN") runs on
// EN/ENO.
namespace iec::editors {

// What a new box is: its type and pins (from the standard library or the project's POU), and
// which pins carry an LD rung. `withEn` adds EN/ENO in front (CoDeSys "box with EN").
struct BoxSpec {
    QString typeName;
    bool functionBlock = false; // needs an instance (its name is "???" until typed)
    QStringList inputs;
    QStringList outputs;
    int rungInput = 0;  // index in inputs
    int rungOutput = 0; // index in outputs, -1 when the box passes no power on
    bool withEn = false;
};

// The text a new element shows until the user types its variable (CoDeSys does the same).
inline const QString kPlaceholder = QStringLiteral("???");

// Whether a box of this type takes any number of inputs (ADD, MUL, AND, OR, XOR, MAX, MIN,
// CONCAT, MUX).
bool isExtensible(const QString &typeName);


std::optional<BoxSpec> boxSpecFor(const model::Project &project, const QString &typeName, bool withEn, QString *error);

// The block of a new box (FBD, CFC): its pins unwired, EN/ENO first when the spec asks for them,
// "???" as a function block's instance name.
model::Block blockFromSpec(const BoxSpec &spec);

} // namespace iec::editors
