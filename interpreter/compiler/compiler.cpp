// The compiler driver: collects declarations, lays out memory, compiles every POU, checks for
// recursion and builds the tasks.
#include "interpreter/compiler/compiler.h"

#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/compilerstack.h"
#include "interpreter/compiler/parser.h"

#include <QCoreApplication>
#include <QSet>

#include <functional>

namespace iec::interp {

namespace {

// Whether a VAR_EXTERNAL's declared type is its global's: the same named type, or written out
// alike (ARRAY[0..31] OF DINT in both places makes two type objects of one shape).
bool sameShape(const Type *a, const Type *b)
{
    if (a == b)
        return true;
    if (!a || !b || a->kind != b->kind)
        return false;
    switch (a->kind) {
    case TypeKind::Elementary: return a->elem == b->elem; // a subrange may be declared on either side
    case TypeKind::String: return a->capacity == b->capacity && a->wide == b->wide;
    case TypeKind::Array: {
        if (a->dims.size() != b->dims.size())
            return false;
        for (size_t i = 0; i < a->dims.size(); ++i) {
            if (a->dims[i].low != b->dims[i].low || a->dims[i].high != b->dims[i].high)
                return false;
        }
        return sameShape(a->element, b->element);
    }
    default: return false; // structs, enums and blocks are named: one object per name
    }
}

} // namespace

namespace detail {

using namespace ast;

Codegen::Codegen(Diagnostics &diagnostics, const CompileOptions &options)
    : m_diagnostics(diagnostics)
    , m_options(options)
    , m_module(std::make_shared<Module>())
{
    m_module->types = std::make_shared<TypeTable>();
    m_types = m_module->types.get();
}

std::uint32_t Codegen::instr(std::uint16_t opcode, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, std::uint16_t aux)
{
    m_module->code.push_back({opcode, aux, a, b, c, d});
    return static_cast<std::uint32_t>(m_module->code.size() - 1);
}

void Codegen::markLine(SourceLocation at)
{
    const qint64 place = at.place == SourceLocation::kNoPlace ? -1 : at.place >= 0 ? at.place : at.localId;
    if (!m_pou || (at.line == m_lastLine && place == m_lastLocalId))
        return;
    m_lastLine = at.line;
    m_lastLocalId = place;
    if (!m_module->lines.empty() && m_module->lines.back().pc == here())
        m_module->lines.back() = {here(), m_lineOwner, at.line, place};
    else
        m_module->lines.push_back({here(), m_lineOwner, at.line, place});
}

bool Codegen::lastWrites(std::uint32_t operand) const
{
    // Only temporaries: a variable written by the last instruction may be read again later. And
    // never across a jump target: merging would move the target past the merged instruction.
    return !m_module->code.empty() && m_module->code.back().a == operand && (operand & kInstanceRelative) == 0
        && (operand & kTempMarker) != 0 && m_module->code.size() > m_pouCodeStart && m_lastTarget != here();
}

void Codegen::fuseStepIntoBranch(std::uint32_t top, std::uint32_t test)
{
    std::vector<Instr> &code = m_module->code;
    // The test is the one branch at `test`, nothing jumps to it, and the body ends just before it.
    if (code.size() != size_t(test) + 1 || test == 0 || test - 1 < top || test - 1 < m_pouCodeStart || m_lastTarget >= test)
        return;
    const Instr branch = code[test];
    const Instr add = code[test - 1];
    struct Pair {
        std::uint16_t branch, step;
    };
    static constexpr Pair pairs[] = {{op::BrLe, op::IncBrLe}, {op::BrLt, op::IncBrLt}, {op::BrGe, op::IncBrGe}, {op::BrGt, op::IncBrGt}};
    for (const Pair &pair : pairs) {
        const int vt = int(branch.op) - int(pair.branch);
        if (vt < 0 || vt >= kVtCount)
            continue;
        const std::uint32_t counter = add.a;
        if (vt == int(VT::F32) || vt == int(VT::F64) || add.op != op::Add + vt || branch.a != top || branch.b != counter
            || branch.c == counter)
            return;
        const std::uint32_t step = add.b == counter ? add.c : add.c == counter ? add.b : counter;
        if (step == counter)
            return;
        code.pop_back();
        code.back() = {static_cast<std::uint16_t>(pair.step + vt), 0, counter, step, branch.c, top};
        // The fused instruction counts the rounds, so an endless loop is still reported at its test.
        std::vector<LineEntry> &lines = m_module->lines;
        if (!lines.empty() && lines.back().pc == test) {
            lines.back().pc = test - 1;
            if (lines.size() >= 2 && lines[lines.size() - 2].pc == test - 1)
                lines.erase(lines.end() - 2);
        }
        return;
    }
}

std::uint32_t Codegen::branchIf(const Value &condition, bool when, std::uint32_t target)
{
    if (condition.kind == Value::Kind::Operand && lastWrites(condition.operand)) {
        const Instr last = m_module->code.back();
        struct Fusion {
            std::uint16_t compare, branch, inverse;
        };
        static constexpr Fusion fusions[] = {
            {op::Eq, op::BrEq, op::BrNe}, {op::Ne, op::BrNe, op::BrEq}, {op::Lt, op::BrLt, op::BrGe},
            {op::Le, op::BrLe, op::BrGt}, {op::Gt, op::BrGt, op::BrLe}, {op::Ge, op::BrGe, op::BrLt},
        };
        for (const Fusion &f : fusions) {
            const int vt = int(last.op) - int(f.compare);
            // Reals are left alone: with NaN, "not less" is not "greater or equal".
            if (vt >= 0 && vt < kVtCount && vt != int(VT::F32) && vt != int(VT::F64)) {
                m_module->code.pop_back();
                return instr(static_cast<std::uint16_t>((when ? f.branch : f.inverse) + vt), target, last.b, last.c);
            }
        }
    }
    return instr(when ? op::Jnz : op::Jz, target, materialize(condition));
}

void Codegen::error(SourceLocation at, const QString &message, const QString &hint)
{
    // The same message at the same place once only, however often the code is looked at.
    for (const Diagnostic &d : m_diagnostics.all()) {
        if (d.pou == m_pouName && d.location.line == at.line && d.location.column == at.column && d.message == message)
            return;
    }
    m_diagnostics.error(m_pouName, at, message, hint);
}

bool Codegen::stackExhausted(SourceLocation at)
{
    if (!compilerStackExhausted())
        return false;
    if (!m_stackReported)
        error(at, QCoreApplication::translate("iec::interp::Compiler", "This is nested too deeply to compile."),
              QCoreApplication::translate("iec::interp::Compiler", "split it into simpler steps: constants, types and function blocks defined in fewer steps, expressions with fewer levels"));
    m_stackReported = true;
    return true;
}

void Codegen::warning(SourceLocation at, const QString &message, const QString &hint)
{
    m_diagnostics.warning(m_pouName, at, message, hint);
}

void Codegen::packRungs()
{
    // Runs of rungs on the instance's own variables become one RungBlock over packed records. The
    // instructions stay where they are (jumps into the run still work); the block skips them.
    std::vector<Instr> &code = m_module->code;
    const auto packable = [&](const Instr &i) {
        if (i.op != op::BoolAndNotOrAndRel)
            return false;
        for (const std::uint32_t x : {i.b, i.c, i.d, i.e}) {
            const std::int64_t delta = std::int64_t(x) - std::int64_t(i.a);
            if (delta < INT16_MIN || delta > INT16_MAX)
                return false;
        }
        return true;
    };
    constexpr std::uint32_t kMinRun = 8;
    for (std::uint32_t pc = m_pouCodeStart; pc < here();) {
        std::uint32_t end = pc;
        while (end < here() && packable(code[end]))
            ++end;
        if (end - pc >= kMinRun) {
            const auto first = static_cast<std::uint32_t>(m_module->rungs.size());
            for (std::uint32_t k = pc; k < end; ++k) {
                const Instr &i = code[k];
                const auto delta = [&](std::uint32_t x) { return static_cast<std::int16_t>(std::int64_t(x) - std::int64_t(i.a)); };
                m_module->rungs.push_back({i.a, delta(i.b), delta(i.c), delta(i.d), delta(i.e)});
            }
            code[pc] = {op::RungBlock, 0, 0, first, end - pc, 0};
        }
        pc = std::max(end, pc + 1);
    }
}

void Codegen::finishTemporaries()
{
    // Temporaries were numbered from 0 with kTempMarker; now that their size is known they get
    // their own area in the image and the operands are moved there.
    const std::uint32_t base = allocate(std::max<std::uint32_t>(m_tempMax, 1), 8);
    for (std::uint32_t pc = m_pouCodeStart; pc < here(); ++pc) {
        Instr &i = m_module->code[pc];
        for (std::uint32_t *operand : {&i.a, &i.b, &i.c, &i.d, &i.e}) {
            if ((*operand & kInstanceRelative) == 0 && (*operand & kTempMarker) != 0)
                *operand = base + (*operand & ~kTempMarker);
        }
    }
    // Jump targets are small pc values and never carry the marker; nothing else to fix.
}

void Codegen::compilePouBody(PouInfo &pou)
{
    beginBody(pou, pou.index, pou.ast->location);
    // Function variables and VAR_TEMP start from their initial values on every call.
    if (pou.reinitFrom < pou.frame->size) {
        const std::uint32_t frame = pou.kind == PouKind::Function ? pou.frameBase : kInstanceRelative;
        instr(op::MovN, frame + pou.reinitFrom, pou.templateOffset + pou.reinitFrom, 0, pou.frame->size - pou.reinitFrom);
    }
    for (const VarSection &section : pou.ast->sections) {
        if (section.kind != VarKind::External)
            continue;
        for (const VarDecl &v : section.vars) {
            const GlobalVar g = m_globals.value(key(v.name));
            const Type *declared = resolveType(v.type);
            if (!g.type) {
                error(v.location, QCoreApplication::translate("iec::interp::Compiler", "There is no global variable %1 for this VAR_EXTERNAL.").arg(v.name),
                      QCoreApplication::translate("iec::interp::Compiler", "declare it in VAR_GLOBAL"));
                // Declared here, so that its uses do not each report it again.
                if (declared) {
                    GlobalVar placeholder;
                    placeholder.name = v.name;
                    placeholder.type = declared;
                    placeholder.offset = allocate(declared->size, std::max<std::uint32_t>(declared->align, 1));
                    m_globals.insert(key(v.name), placeholder);
                }
            }
            else if (declared && !sameShape(declared, g.type))
                error(v.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is declared as %2 here but as %3 in VAR_GLOBAL.").arg(v.name, typeName(declared), typeName(g.type)));
        }
    }
    if (pou.ast->body.language == Language::SFC)
        warning(pou.ast->location, QCoreApplication::translate("iec::interp::Compiler", "%1 is a sequential function chart; charts run with the next version of the interpreter.").arg(pou.name));
    endBody(pou.ast->body);
}

// The start of the code of a POU body or of one of its actions (module entry `moduleIndex`),
// which runs on the POU's instance.
void Codegen::beginBody(PouInfo &pou, int moduleIndex, SourceLocation at)
{
    m_pou = &pou;
    m_lineOwner = moduleIndex;
    m_pouName = m_module->pous[size_t(moduleIndex)].name;
    m_tempTop = m_tempMax = 0;
    m_lastLine = -1;
    m_lastLocalId = -1;
    m_pouCodeStart = here();
    m_module->pous[size_t(moduleIndex)].entry = here();
    markLine(at);
}

void Codegen::endBody(const Body &body)
{
    if (body.language == Language::ST) {
        compileStatements(body.statements);
        resolveStJumps();
    }
    else if (body.language == Language::IL)
        compileIl(body.il);
    instr(op::Ret);
    finishTemporaries();
    packRungs();
    m_lineOwner = -1;
    m_pou = nullptr;
}

int Codegen::actionIndex(int pou, const QString &name) const
{
    return m_actions.value(QString::number(pou) + QLatin1Char(':') + key(name), -1);
}

void Codegen::compileActionBody(PouInfo &pou, const SfcAction &action, int moduleIndex)
{
    if (moduleIndex < 0)
        return;
    beginBody(pou, moduleIndex, action.location);
    endBody(action.body);
}

std::shared_ptr<Module> Codegen::run(const std::vector<const CompilationUnit *> &units)
{
    m_units = units;
    const CompilationUnit &library = standardLibrary();
    const bool util = utilNamesUsed(units);
    for (const CompilationUnit *u : units)
        collectTypes(*u, false);
    if (util)
        collectTypes(utilLibrary(), true);
    for (const CompilationUnit *u : units)
        collectPous(*u, false);
    collectPous(library, true);
    if (util)
        collectPous(utilLibrary(), true);
    registerMethods();
    checkImplementations();
    checkOverrides();
    allocate(8, 8); // offset 0 is never a variable
    reserveProcessImage(units);

    for (PouInfo &p : m_pous)
        layoutPou(p);
    for (const PouInfo &p : m_pous)
        m_module->pous.push_back({p.name, p.kind, 0, p.frame});
    // Actions run on their POU's instance: entries after the POUs, named Main.Reset.
    for (const PouInfo &p : m_pous) {
        if (!p.ast || p.kind == PouKind::Function)
            continue;
        for (const SfcAction &action : p.ast->actions) {
            m_actions.insert(QString::number(p.index) + QLatin1Char(':') + key(action.name), static_cast<int>(m_module->pous.size()));
            m_module->pous.push_back({p.name + QLatin1Char('.') + action.name, p.kind, 0, p.frame});
        }
    }

    m_pouName.clear();
    for (const CompilationUnit *u : units)
        declareGlobals(u->globals);
    const ConfigurationDecl *config = nullptr;
    for (const CompilationUnit *u : units) {
        for (const ConfigurationDecl &c : u->configurations) {
            if (!config)
                config = &c;
            else
                warning(c.location, QCoreApplication::translate("iec::interp::Compiler", "Only the first configuration (%1) runs.").arg(config->name));
        }
    }
    if (config) {
        m_pouName = config->name;
        declareGlobals(config->globals);
        for (const ResourceDecl &r : config->resources)
            declareGlobals(r.globals);
        m_pouName.clear();
    }
    m_globalsDeclared = true;

    // Static memory of functions, and the initial values that reset VAR_TEMP and function variables.
    for (PouInfo &p : m_pous) {
        if (!p.frame)
            continue;
        m_pou = &p;
        m_pouName = p.name;
        if (p.kind == PouKind::Function) {
            p.frameBase = allocate(p.frame->size, std::max<std::uint32_t>(p.frame->align, 1));
            writeInitial(p.frameBase, p.frame, nullptr);
        }
        if (p.kind == PouKind::Function || p.reinitFrom < p.frame->size) {
            p.templateOffset = allocate(p.frame->size, std::max<std::uint32_t>(p.frame->align, 1));
            writeInitial(p.templateOffset, p.frame, nullptr);
        }
        m_pou = nullptr;
    }

    // Program instances and tasks.
    struct PlannedProgram {
        QString name;
        int pou;
        int task;
        const ProgramConfig *config;
    };
    std::vector<PlannedProgram> planned;
    if (config) {
        m_pouName = config->name;
        for (const ResourceDecl &r : config->resources) {
            for (const TaskDecl &t : r.tasks) {
                TaskInfo task;
                task.name = t.name;
                if (t.priority) {
                    if (const auto v = evalConstInt(*t.priority))
                        task.priority = static_cast<int>(*v);
                }
                if (t.interval) {
                    if (const auto v = evalConst(*t.interval); v && v->constant.kind == ConstValue::Kind::Int)
                        task.intervalNs = v->constant.i;
                }
                if (t.single) {
                    const Place p = resolvePlace(*t.single);
                    if (p.kind == Place::Kind::Direct && p.type == boolType())
                        task.singleOffset = static_cast<std::int32_t>(p.operand);
                    else if (p.kind != Place::Kind::Invalid)
                        error(t.single->location, QCoreApplication::translate("iec::interp::Compiler", "SINGLE needs a global BOOL variable."));
                }
                m_module->tasks.push_back(task);
            }
            for (const ProgramConfig &pc : r.programs) {
                const int pou = m_pouIndex.value(key(pc.type), -1);
                if (pou < 0 || m_pous[size_t(pou)].kind != PouKind::Program) {
                    error(pc.location, QCoreApplication::translate("iec::interp::Compiler", "There is no PROGRAM called %1.").arg(pc.type));
                    continue;
                }
                int task = -1;
                if (!pc.task.isEmpty()) {
                    for (size_t t = 0; t < m_module->tasks.size(); ++t) {
                        if (m_module->tasks[t].name.compare(pc.task, Qt::CaseInsensitive) == 0)
                            task = static_cast<int>(t);
                    }
                    if (task < 0) {
                        error(pc.location, QCoreApplication::translate("iec::interp::Compiler", "There is no task called %1.").arg(pc.task));
                        continue;
                    }
                }
                planned.push_back({pc.instance, pou, task, &pc});
            }
        }
    } else {
        std::vector<int> programs;
        for (const PouInfo &p : m_pous) {
            if (p.kind == PouKind::Program && !p.fromLibrary)
                programs.push_back(p.index);
        }
        int chosen = -1;
        if (!m_options.program.isEmpty()) {
            chosen = m_pouIndex.value(key(m_options.program), -1);
            if (chosen < 0 || m_pous[size_t(chosen)].kind != PouKind::Program) {
                m_pouName.clear();
                error({}, QCoreApplication::translate("iec::interp::Compiler", "There is no PROGRAM called %1.").arg(m_options.program));
                chosen = -1;
            }
        } else if (programs.size() == 1) {
            chosen = programs.front();
        } else {
            for (const char *preferred : {"PLC_PRG", "MAIN"}) {
                if (chosen < 0)
                    chosen = m_pouIndex.value(QLatin1String(preferred), -1);
            }
            if (chosen >= 0 && m_pous[size_t(chosen)].kind != PouKind::Program)
                chosen = -1;
            if (chosen < 0 && !programs.empty())
                chosen = programs.front();
        }
        if (chosen >= 0)
            planned.push_back({m_pous[size_t(chosen)].name, chosen, -1, nullptr});
    }
    // Programs without a task run every cycle in a task of their own (lowest priority).
    bool needsDefaultTask = false;
    for (const PlannedProgram &p : planned)
        needsDefaultTask = needsDefaultTask || p.task == -1;
    if (needsDefaultTask) {
        TaskInfo task;
        task.name = QStringLiteral("DefaultTask");
        task.priority = 1000;
        m_module->tasks.push_back(task);
    }
    // Every other PROGRAM exists once too (CODESYS), so that other POUs may call it (PRG1();) and
    // read its variables (PRG1.Out); no task runs it unless it is called.
    for (const PouInfo &p : m_pous) {
        const bool inTask = std::any_of(planned.begin(), planned.end(), [&](const PlannedProgram &pp) { return pp.pou == p.index; });
        if (p.kind == PouKind::Program && !p.fromLibrary && p.frame && !inTask)
            planned.push_back({p.name, p.index, -2, nullptr});
    }
    for (const PlannedProgram &p : planned) {
        PouInfo &pou = m_pous[size_t(p.pou)];
        if (!pou.frame)
            continue;
        ProgramInstance instance;
        instance.name = p.name;
        instance.pou = p.pou;
        instance.base = allocate(pou.frame->size, std::max<std::uint32_t>(pou.frame->align, 1));
        m_pou = &pou;
        m_pouName = pou.name;
        writeInitial(instance.base, pou.frame, nullptr);
        m_pou = nullptr;
        // RETAIN variables, as far down as they are declared (VAR RETAIN in nested FBs too).
        std::function<void(std::uint32_t, const Type *, bool)> retain = [&](std::uint32_t base, const Type *type, bool all) {
            if (all) {
                m_module->retain.push_back({base, type->size});
                return;
            }
            for (const Member &m : type->members) {
                if (m.retain || (p.config && p.config->retain))
                    m_module->retain.push_back({base + m.offset, m.byReference ? 4 : m.type->size});
                else if (m.type->kind == TypeKind::FunctionBlock && !m.byReference)
                    retain(base + m.offset, m.type, false);
            }
        };
        retain(instance.base, pou.frame, false);
        m_pouName = pou.name;
        for (const Member &m : pou.frame->members) {
            if (m.address.isEmpty())
                continue;
            locate(m.address, instance.base + m.offset, m.type, m.location);
            if (const auto address = parseImageAddress(m.address))
                initialiseImage(*address, instance.base + m.offset, m.type);
        }
        m_module->symbols.push_back({instance.name, pou.frame, instance.base});
        pou.programBase = ++pou.programInstances == 1 ? instance.base : 0;
        if (p.task != -2) {
            const int taskIndex = p.task >= 0 ? p.task : static_cast<int>(m_module->tasks.size()) - 1;
            m_module->tasks[size_t(taskIndex)].programs.push_back(static_cast<int>(m_module->programs.size()));
        }
        m_module->programs.push_back(instance);
    }

    for (PouInfo &p : m_pous) {
        if (p.frame && !(p.method && !p.method->hasBody)) // prototypes (interfaces, ABSTRACT) have no code
            compilePouBody(p);
    }
    for (PouInfo &p : m_pous) {
        if (!p.frame || !p.ast || p.kind == PouKind::Function)
            continue;
        for (const SfcAction &action : p.ast->actions)
            compileActionBody(p, action, actionIndex(p.index, action.name));
    }

    // Recursion: a cycle in the graph of calls (functions) and instances (function blocks). The
    // search keeps its own path instead of recursing: a chain of calls is as long as the program.
    std::vector<int> state(m_pous.size(), 0); // 0 new, 1 on the path, 2 done
    std::vector<int> path;
    std::vector<size_t> nextCall; // for each POU on the path: the next of its calls to follow
    for (size_t root = 0; root < m_pous.size(); ++root) {
        if (state[root] != 0)
            continue;
        state[root] = 1;
        path.push_back(static_cast<int>(root));
        nextCall.push_back(0);
        while (!path.empty()) {
            const int pou = path.back();
            const auto &calls = m_calls[pou];
            if (nextCall.back() == calls.size()) {
                state[size_t(pou)] = 2;
                path.pop_back();
                nextCall.pop_back();
                continue;
            }
            const auto &[callee, at] = calls[nextCall.back()++];
            if (state[size_t(callee)] == 1) {
                QStringList names;
                bool inCycle = false;
                for (const int p : path) {
                    inCycle = inCycle || p == callee;
                    if (inCycle)
                        names << m_pous[size_t(p)].name;
                }
                names << m_pous[size_t(callee)].name;
                m_pouName = m_pous[size_t(pou)].name;
                error(at, QCoreApplication::translate("iec::interp::Compiler", "Recursion is not allowed in IEC 61131-3: %1 calls itself (%2).")
                              .arg(m_pous[size_t(callee)].name, names.join(QStringLiteral(" -> "))));
            } else if (state[size_t(callee)] == 0) {
                state[size_t(callee)] = 1;
                path.push_back(callee);
                nextCall.push_back(0);
            }
        }
    }

    checkVendorLibrariesReachable();

    // Task code: call each program in order, then halt. Program parameters from the
    // configuration are passed like a function block's.
    m_pouCodeStart = here();
    m_tempTop = m_tempMax = 0;
    for (TaskInfo &task : m_module->tasks) {
        task.entry = here();
        for (const int index : task.programs) {
            const ProgramInstance &instance = m_module->programs[size_t(index)];
            Place place;
            place.kind = Place::Kind::Direct;
            place.type = m_pous[size_t(instance.pou)].frame;
            place.operand = instance.base;
            place.text = instance.name;
            const ProgramConfig *pc = nullptr;
            for (const PlannedProgram &p : planned) {
                if (p.name == instance.name)
                    pc = p.config;
            }
            m_pouName = config ? config->name : QString();
            callFunctionBlock(place, pc ? arguments(pc->args) : std::vector<Argument>{}, pc ? pc->location : SourceLocation{});
        }
        instr(op::Halt);
    }
    for (ProgramInstance &instance : m_module->programs) {
        instance.entry = here();
        instr(op::CallFb, instance.base, 0, 0, 0, static_cast<std::uint16_t>(instance.pou));
        instr(op::Halt);
    }
    finishTemporaries();
    std::stable_sort(m_module->tasks.begin(), m_module->tasks.end(), [](const TaskInfo &a, const TaskInfo &b) { return a.priority < b.priority; });
    if (m_diagnostics.hasErrors())
        return nullptr;
    return m_module;
}

} // namespace detail

std::shared_ptr<const Module> compile(const std::vector<const ast::CompilationUnit *> &units, Diagnostics &diagnostics,
                                      const CompileOptions &options)
{
    if (units.empty())
        return nullptr;
    std::shared_ptr<const Module> module;
    runOnCompilerStack([&] {
        detail::Codegen codegen(diagnostics, options);
        module = codegen.run(units);
    });
    return module;
}

std::shared_ptr<const Module> compileText(QStringView source, Diagnostics &diagnostics, const CompileOptions &options)
{
    std::shared_ptr<const Module> module;
    runOnCompilerStack([&] {
        const ast::CompilationUnit unit = parseUnit(source, diagnostics);
        if (!diagnostics.hasUnrequestedErrors()) // an {error} pragma: the rest is checked too
            module = compile({&unit}, diagnostics, options);
    });
    return module;
}

} // namespace iec::interp
