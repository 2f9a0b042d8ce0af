#pragma once

#include "model/datatypes.h"
#include "model/instances.h"
#include "model/pou.h"

#include <QString>

#include <optional>
#include <vector>

namespace iec::model {

struct FileHeader {
    QString companyName;
    std::optional<QString> companyURL;
    QString productName;
    QString productVersion;
    std::optional<QString> productRelease;
    QString creationDateTime; // xsd:dateTime, kept as written
    std::optional<QString> contentDescription;
    Extras extras;

    bool operator==(const FileHeader &) const = default;
};

struct Scaling {
    double x = 1;
    double y = 1;

    bool operator==(const Scaling &) const = default;
};

struct CoordinateInfo {
    std::optional<Scaling> pageSize;
    Scaling fbd;
    Scaling ld;
    Scaling sfc;

    bool operator==(const CoordinateInfo &) const = default;
};

// addDataInfo/info: declares a vendor extension used in addData.
struct AddDataInfo {
    QString name;
    std::optional<QString> version; // xsd:decimal, kept as written
    QString vendor;
    std::optional<FormattedText> description;

    bool operator==(const AddDataInfo &) const = default;
};

struct ContentHeader {
    QString name;
    std::optional<QString> version;
    std::optional<QString> modificationDateTime;
    std::optional<QString> organization;
    std::optional<QString> author;
    std::optional<QString> language;
    std::optional<QString> comment; // <Comment>
    CoordinateInfo coordinateInfo;
    std::optional<std::vector<AddDataInfo>> addDataInfo;
    AddData addData;
    Extras extras;

    bool operator==(const ContentHeader &) const = default;
};

struct Types {
    std::vector<DataTypeDecl> dataTypes;
    std::vector<Pou> pous;

    bool operator==(const Types &) const = default;
};

// The whole project as a value. Only ProjectModel changes the instance the application shows.
struct Project {
    FileHeader fileHeader;
    ContentHeader contentHeader;
    Types types;
    Instances instances;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    [[nodiscard]] const Pou *findPou(PouId id) const;
    [[nodiscard]] const Pou *findPou(const QString &name) const;
    [[nodiscard]] const DataTypeDecl *findDataType(const QString &name) const;

    bool operator==(const Project &) const = default;
};

} // namespace iec::model
