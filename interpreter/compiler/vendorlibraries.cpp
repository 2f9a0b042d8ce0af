// Blocks of vendor libraries IEC Studio does not have (OpenPLC's TCP sockets, MQTT, CODESYS
// SoftMotion). A POU that declares one gets one warning naming the library, at its first use in
// the project; the rest is still checked, and the project runs unless a task reaches such a POU.
// Beremiz's SVGHMI types are read as the elementary types they stand for.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/svghmi.h"

#include <QCoreApplication>

#include <functional>

namespace iec::interp::detail {

QString vendorLibraryOf(const QString &upperName)
{
    struct Library {
        const char *prefix;
        const char *name;
    };
    static const Library libraries[] = {
        {"TCP_", QT_TRANSLATE_NOOP("iec::interp::Compiler", "the OpenPLC TCP socket library")},
        {"MQTT", QT_TRANSLATE_NOOP("iec::interp::Compiler", "an MQTT library")},
        {"MC_", QT_TRANSLATE_NOOP("iec::interp::Compiler", "CODESYS SoftMotion (PLCopen motion control)")},
        {"SMC_", QT_TRANSLATE_NOOP("iec::interp::Compiler", "CODESYS SoftMotion")},
        {"UDP_", QT_TRANSLATE_NOOP("iec::interp::Compiler", "the OpenPLC UDP socket library")},
        {"PYTHON_", QT_TRANSLATE_NOOP("iec::interp::Compiler", "Beremiz's Python blocks")},
    };
    for (const Library &l : libraries) {
        if (upperName.startsWith(QLatin1String(l.prefix)))
            return QCoreApplication::translate("iec::interp::Compiler", l.name);
    }
    return {};
}

} // namespace iec::interp::detail

namespace iec::interp {

QString svgHmiBaseType(const QString &upperName)
{
    if (upperName == QLatin1String("HMI_NODE"))
        return QStringLiteral("BOOL");
    if (upperName == QLatin1String("HMI_BOOL") || upperName == QLatin1String("HMI_INT")
        || upperName == QLatin1String("HMI_REAL") || upperName == QLatin1String("HMI_STRING"))
        return upperName.mid(4);
    return {};
}

} // namespace iec::interp

namespace iec::interp::detail {

void Codegen::missingVendorLibrary(const QString &block, const QString &library, SourceLocation at)
{
    const PouInfo *user = m_pou ? m_pou : m_declaring;
    if (user)
        m_needsVendorLibrary.insert(user->index, library);
    if (m_reportedLibraries.contains(library))
        return;
    m_reportedLibraries.insert(library);
    warning(at, QCoreApplication::translate("iec::interp::Compiler", "%1 is a block of %2, which IEC Studio does not have; the POUs that use it cannot run.").arg(block, library),
            QCoreApplication::translate("iec::interp::Compiler", "the rest of the project is still checked and runs"));
}

// A task that would run a POU needing a missing library: the project cannot run.
void Codegen::checkVendorLibrariesReachable()
{
    if (m_needsVendorLibrary.isEmpty())
        return;
    for (const ProgramInstance &program : m_module->programs) {
        const bool inTask = std::any_of(m_module->tasks.begin(), m_module->tasks.end(), [&](const TaskInfo &t) {
            return std::find(t.programs.begin(), t.programs.end(), int(&program - m_module->programs.data())) != t.programs.end();
        });
        if (!inTask)
            continue;
        std::vector<bool> seen(m_pous.size(), false);
        std::function<int(int)> needing = [&](int pou) -> int {
            if (seen[size_t(pou)])
                return -1;
            seen[size_t(pou)] = true;
            if (m_needsVendorLibrary.contains(pou))
                return pou;
            for (const auto &[callee, at] : m_calls[pou]) {
                if (const int found = needing(callee); found >= 0)
                    return found;
            }
            return -1;
        };
        if (const int found = needing(program.pou); found >= 0) {
            m_pouName = m_pous[size_t(program.pou)].name;
            error({}, QCoreApplication::translate("iec::interp::Compiler", "%1 cannot run: %2 uses %3.")
                          .arg(program.name, m_pous[size_t(found)].name, m_needsVendorLibrary.value(found)));
        }
    }
}

} // namespace iec::interp::detail
