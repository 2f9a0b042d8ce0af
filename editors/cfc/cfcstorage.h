#pragma once

#include "model/body.h"
#include "model/element.h"

#include <QString>

#include <optional>
#include <vector>

// Where a CFC body keeps its diagram, and CODESYS's form of it (docs/editors-cfc.md).
//
// - IEC Studio writes a CFC as an FBD body marked with the addData entry
//   kIecStudioCfcAddDataName: the elements, their positions in drawing units and their
//   executionOrderIds are plain PLCopen, so Beremiz opens it as an FBD with the same drawing and
//   order.
// - CODESYS writes an empty ST body whose addData entry `…/plcopenxml/cfc` holds <CFC> with the
//   elements: positions on its grid, every wire routed through an anonymous connector, the
//   execution order counted from 0. The editor shows it in its own terms and writes it back in
//   CODESYS's only when it was edited (the entry is left as it was otherwise).
namespace iec::editors::cfc {

enum class CfcStorage { Elements, Codesys };

// How `body` keeps a CFC diagram; nullopt when it is not a CFC body.
[[nodiscard]] std::optional<CfcStorage> cfcStorageOf(const model::Body &body);
// The index in body.addData of CODESYS's CFC entry, -1 when there is none.
[[nodiscard]] int codesysCfcEntry(const model::Body &body);

// One CODESYS grid step in drawing units: a box's pin pitch.
inline constexpr double kCodesysGrid = 20;

struct CodesysCfcRead {
    std::vector<model::Element> elements;
    QString error; // why the content cannot be shown; empty when it was read
};

// The diagram of CODESYS's <CFC> content as the editor shows it: positions in drawing units (a
// pin on grid row y sits at y * kCodesysGrid), the anonymous connectors taken out (their readers
// wired to what feeds them), pins without relPositions, execution order counted from 1.
[[nodiscard]] CodesysCfcRead readCodesysCfc(const QString &content);
// The reverse, as CODESYS writes it: grid positions, one anonymous connector after each output
// that has readers, relPositions on the pins, the order from 0.
[[nodiscard]] QString writeCodesysCfc(const std::vector<model::Element> &elements);

} // namespace iec::editors::cfc
