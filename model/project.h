#pragma once

#include "model/ids.h"

#include <QString>

#include <vector>

namespace iec::model {

enum class PouKind { Program, FunctionBlock, Function };
enum class BodyLanguage { ST, IL, LD, FBD, SFC };

struct Pou {
    PouId id;
    QString name;
    PouKind kind = PouKind::Program;
    BodyLanguage language = BodyLanguage::ST;
    QString bodyText; // ST and IL bodies

    bool operator==(const Pou &) const = default;
};

// The whole project as a value. Only ProjectModel changes the instance the application shows.
struct Project {
    QString name;
    std::vector<Pou> pous;

    [[nodiscard]] const Pou *findPou(PouId id) const;
    [[nodiscard]] const Pou *findPou(const QString &name) const;

    bool operator==(const Project &) const = default;
};

} // namespace iec::model
