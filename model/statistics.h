#pragma once

#include "model/project.h"

#include <QString>

#include <map>

namespace iec::model {

// Counts for `iecstudio-cli info` (docs/cli-info.md). A file and its round-tripped copy give
// the same numbers.
struct ProjectStatistics {
    int pous = 0;
    std::map<QString, int> pousByKind; // program, functionBlock, function (always all three)
    std::map<QString, int> pousByLanguage; // ST, IL, LD, FBD, SFC (always all five) and "none"
    int dataTypes = 0;
    int variables = 0; // POU interfaces plus configuration and resource global variables
    int actions = 0;
    int transitions = 0;
    int elements = 0; // top-level elements of every POU, action and transition body
    std::map<QString, int> elementsByKind; // XSD element name -> count (only kinds that occur)

    bool operator==(const ProjectStatistics &) const = default;
};

ProjectStatistics statistics(const Project &project);

QString pouKindName(PouKind kind); // program, functionBlock, function
QString bodyLanguageName(BodyLanguage language); // ST, IL, LD, FBD, SFC

} // namespace iec::model
