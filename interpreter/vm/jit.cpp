#include "interpreter/vm/jit.h"

#include "interpreter/vm/jittranslator.h"

#include <QtGlobal>

#include <cstdio>
#include <cstring>

#if defined(__x86_64__) && defined(__linux__)
#include <sys/mman.h>
#define IEC_JIT_X64 1
#endif

namespace iec::interp {

bool jitEnabled()
{
#ifdef IEC_JIT_X64
    return qEnvironmentVariable("IEC_JIT") != QLatin1String("0");
#else
    return false;
#endif
}

namespace {

using namespace x64;
using jit::Region;
using jit::RegionTranslator;

// IEC_JIT_DUMP=FILE writes the machine code, for `objdump -D -b binary -m i386:x86-64 FILE`.
void dumpIfAsked(const std::vector<std::uint8_t> &code)
{
    const QByteArray path = qgetenv("IEC_JIT_DUMP");
    if (path.isEmpty())
        return;
    if (FILE *f = std::fopen(path.constData(), "wb")) {
        std::fwrite(code.data(), 1, code.size(), f);
        std::fclose(f);
    }
}

#ifdef IEC_JIT_X64
void *mapExecutable(const std::vector<std::uint8_t> &code)
{
    void *p = mmap(nullptr, code.size(), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
        return nullptr;
    std::memcpy(p, code.data(), code.size());
    if (mprotect(p, code.size(), PROT_READ | PROT_EXEC) != 0) {
        munmap(p, code.size());
        return nullptr;
    }
    return p;
}
#endif

} // namespace

JitProgram::~JitProgram()
{
#ifdef IEC_JIT_X64
    if (m_machineCode)
        munmap(m_machineCode, m_machineCodeSize);
#endif
}

std::unique_ptr<JitProgram> JitProgram::compile(const Module &module)
{
#ifdef IEC_JIT_X64
    if (!jitEnabled())
        return nullptr;
    const std::vector<Region> regions = jit::findRegions(module);
    if (regions.empty())
        return nullptr;
    Emitter emitter;
    struct Translated {
        Label prologue;
        std::vector<std::pair<std::uint32_t, Label>> entries;
    };
    std::vector<Translated> translated;
    std::unique_ptr<JitProgram> program(new JitProgram);
    for (const Region &region : regions) {
        RegionTranslator translator(module, emitter, region);
        if (!translator.translate()) {
            // describe() promised more than the translator does: a bug; run interpreted.
            Q_ASSERT_X(false, "JitProgram::compile", "an instruction describe() accepts has no translation");
            return nullptr;
        }
        Translated t{translator.prologue(), {}};
        for (std::uint32_t pc : region.entries)
            t.entries.emplace_back(pc, translator.labelOf(pc));
        translated.push_back(std::move(t));
        ++program->m_stats.regions;
        program->m_stats.instructions += region.end - region.begin;
    }
    if (!emitter.finish() || emitter.size() == 0)
        return nullptr;
    dumpIfAsked(emitter.code());
    void *machineCode = mapExecutable(emitter.code());
    if (!machineCode)
        return nullptr;
    program->m_machineCode = machineCode;
    program->m_machineCodeSize = emitter.size();
    program->m_stats.bytes = emitter.size();
    program->m_code = module.code;
    auto *base = static_cast<std::uint8_t *>(machineCode);
    for (const Translated &t : translated) {
        const auto region = reinterpret_cast<NativeRegion>(base + emitter.offsetOf(t.prologue));
        for (const auto &[pc, label] : t.entries) {
            Instr enter;
            enter.op = op::JitEnter;
            enter.a = std::uint32_t(program->m_entries.size());
            program->m_code[pc] = enter;
            program->m_entries.push_back({region, base + emitter.offsetOf(label)});
        }
    }
    return program;
#else
    Q_UNUSED(module);
    return nullptr;
#endif
}

} // namespace iec::interp
