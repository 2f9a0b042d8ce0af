#pragma once

#include "model/plcopen/xmlarchive.h"

// Older and hand-made PLCopen files that are not quite valid, mended before they are read so
// they load (with a warning each) and are written back valid:
//   - an <action> of an action block without localId (a fresh one) or relPosition (0, 0);
//   - <pouInstance type="..."> instead of typeName= (older Beremiz, CoDeSys 2.3 exports);
//   - a creationDateTime with a space between date and time instead of 'T'.
namespace iec::model::plcopen {

void repairOldForms(pugi::xml_node root, ReadContext &context);

} // namespace iec::model::plcopen
