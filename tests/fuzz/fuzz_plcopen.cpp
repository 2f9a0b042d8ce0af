// PLCopen XML: bytes -> reader -> model -> writer -> reader. Whatever the bytes, reading never
// crashes; a project that was read writes XML that reads back to the same model, and writing that
// again gives the same bytes (the writer is deterministic), with no character XML 1.0 does not
// allow (which other tools would refuse).
#include "fuzzsupport.h"

#include "model/filetext.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

#include <algorithm>

using namespace iec::model;

namespace {

// Raw, or as a character reference (which pugixml writes for a control character outside CDATA);
// the reader reports either.
bool holdsOnlyXmlCharacters(const QByteArray &bytes, const plcopen::ReadResult &read)
{
    const QString text = QString::fromUtf8(bytes);
    return std::ranges::all_of(text, [](QChar c) { return fileCanKeep(c.unicode()); })
        && std::ranges::none_of(read.diagnostics,
            [](const Diagnostic &d) { return d.message.startsWith(QLatin1String("Characters XML does not allow")); });
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(std::min(size, fuzzing::kMaxInput * 4)));
    const plcopen::ReadResult first = plcopen::readProject(bytes);
    if (!first.isProject)
        return 0;
    const QByteArray written = plcopen::writeProject(first.project);
    const plcopen::ReadResult second = plcopen::readProject(written);
    FUZZ_CHECK(holdsOnlyXmlCharacters(written, second), QString::fromUtf8(written.left(4000)));
    FUZZ_CHECK(second.isProject, QString::fromUtf8(written.left(2000)));
    FUZZ_CHECK(second.project == first.project, QString::fromUtf8(written.left(4000)));
    FUZZ_CHECK(plcopen::writeProject(second.project) == written, QString::fromUtf8(written.left(4000)));
    return 0;
}
