// PLCopen XML: bytes -> reader -> model -> writer -> reader. Whatever the bytes, reading never
// crashes; a project that was read writes XML that reads back to the same model, and writing that
// again gives the same bytes (the writer is deterministic).
#include "fuzzsupport.h"

#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

using namespace iec::model;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(std::min(size, fuzzing::kMaxInput * 4)));
    const plcopen::ReadResult first = plcopen::readProject(bytes);
    if (!first.isProject)
        return 0;
    const QByteArray written = plcopen::writeProject(first.project);
    const plcopen::ReadResult second = plcopen::readProject(written);
    FUZZ_CHECK(second.isProject, QString::fromUtf8(written.left(2000)));
    FUZZ_CHECK(second.project == first.project, QString::fromUtf8(written.left(4000)));
    FUZZ_CHECK(plcopen::writeProject(second.project) == written, QString::fromUtf8(written.left(4000)));
    return 0;
}
