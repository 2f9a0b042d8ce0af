#pragma once

#include "model/plcopen/xmlarchive.h"

// Older and hand-made PLCopen files that are not quite valid, mended before they are read so
// they load (with a warning each) and are written back valid:
//   - an <action> of an action block without localId (a fresh one) or relPosition (0, 0);
//   - <pouInstance type="..."> instead of typeName= (older Beremiz, CoDeSys 2.3 exports);
//   - a creationDateTime with a space between date and time instead of 'T'.
namespace iec::model::plcopen {

void repairOldForms(pugi::xml_node root, ReadContext &context);

// XML 1.0 allows no control character but tab and line breaks, nor U+FFFE or U+FFFF, not even
// written as a character reference; some tools write them all the same. pugixml reads most of
// them, but a NUL ends its text there, cutting off the rest.
//
// Before the parse: each NUL of a UTF-8 file (a raw byte, or &#0; outside CDATA sections, comments
// and processing instructions) becomes U+0001, in as many bytes, so lines and columns stay right.
[[nodiscard]] QByteArray withNulAsAnotherControlCharacter(const QByteArray &bytes);
// After the parse: such characters are left out of every text and attribute value, with one
// warning at the first, so that what is read can be written back as valid XML.
void dropCharactersXmlDoesNotAllow(pugi::xml_document &document, ReadContext &context);

// An element may not have one attribute twice; pugixml reads it all the same. The first is kept,
// with a warning, so that what is read is what is written (found by fuzz_plcopen).
void keepFirstOfRepeatedAttributes(pugi::xml_document &document, ReadContext &context);

} // namespace iec::model::plcopen
