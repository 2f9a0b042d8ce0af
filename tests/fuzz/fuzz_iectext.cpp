// IEC text (.st): text -> model -> text. Reading never crashes; text that reads without errors
// prints as text that reads without errors and prints the same again (docs/interpreter.md), and
// its model survives PLCopen XML (what `iecstudio-cli convert` and the IDE's import do).
#include "fuzzsupport.h"

#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

using namespace iec;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const interp::frontend::TextReadResult first = interp::frontend::readIecText(fuzzing::text(data, size), QStringLiteral("p"));
    const QString printed = interp::frontend::printProject(first.project);
    if (first.diagnostics.hasErrors())
        return 0;
    const interp::frontend::TextReadResult second = interp::frontend::readIecText(printed, QStringLiteral("p"));
    FUZZ_CHECK(!second.diagnostics.hasErrors(), printed);
    FUZZ_CHECK(interp::frontend::printProject(second.project) == printed, printed);
    const QByteArray xml = model::plcopen::writeProject(first.project);
    const model::plcopen::ReadResult fromXml = model::plcopen::readProject(xml);
    FUZZ_CHECK(fromXml.isProject && fromXml.project == first.project, QString::fromUtf8(xml.left(4000)));
    return 0;
}
