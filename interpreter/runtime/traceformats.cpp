#include "interpreter/runtime/traceformats.h"

#include "interpreter/compiler/types.h"

#include <cstring>

namespace iec::interp {

namespace {

class CsvWriter : public TraceWriter
{
public:
    CsvWriter(QTextStream &out, std::vector<TraceVariable> variables)
        : m_out(out)
        , m_variables(std::move(variables))
    { }

    void begin(const TraceRow &initial) override
    {
        m_out << "cycle,time_ms";
        for (const TraceVariable &variable : m_variables)
            m_out << ',' << csvField(variable.name);
        m_out << '\n';
        if (initial.cycle > 0)
            write(initial);
    }

    void write(const TraceRow &row) override
    {
        m_out << row.cycle << ',' << formatMilliseconds(row.timeNs);
        for (std::size_t i = 0; i < m_variables.size(); ++i)
            m_out << ',' << csvField(rowLiteral(row, i, m_variables[i].ref));
        m_out << '\n';
    }

private:
    QTextStream &m_out;
    std::vector<TraceVariable> m_variables;
};

enum class VcdKind { Bit, Vector, Real, None };

VcdKind kindOf(const VariableRef &ref)
{
    const Type *type = ref.type;
    if (ref.bit >= 0)
        return VcdKind::Bit;
    if (!type || !type->isElementary())
        return VcdKind::None;
    if (type->kind == TypeKind::Elementary && type->elem == Elem::Bool)
        return VcdKind::Bit;
    return info(type->elem).isReal && type->kind == TypeKind::Elementary ? VcdKind::Real : VcdKind::Vector;
}

// Identifier codes: printable ASCII from '!' to '~', as short as possible.
QString identifier(size_t index)
{
    QString code;
    do {
        code += QChar(char('!' + index % 94));
        index /= 94;
    } while (index > 0);
    return code;
}

QString vcdValue(const TraceRow &row, std::size_t index, const VariableRef &ref)
{
    const std::uint64_t bits = rowBits(row, index, ref);
    switch (kindOf(ref)) {
    case VcdKind::Bit:
        return QString::number(bits);
    case VcdKind::Vector:
        return QLatin1Char('b') + QString::number(bits, 2) + QLatin1Char(' ');
    case VcdKind::Real:
        return QLatin1Char('r') + QString::number(rowNumber(row, index, ref), 'g', 17) + QLatin1Char(' ');
    case VcdKind::None:
        break;
    }
    return QString();
}

QString declaration(const TraceVariable &variable, size_t index)
{
    const VcdKind kind = kindOf(variable.ref);
    const QString type = kind == VcdKind::Real ? QStringLiteral("real") : QStringLiteral("wire");
    // Reals are written as doubles whatever their IEC size; GTKWave expects `real 64`.
    const unsigned width = kind == VcdKind::Bit ? 1 : kind == VcdKind::Real ? 64 : variable.ref.type->size * 8;
    QString reference = variable.name;
    reference.replace(QLatin1Char(' '), QLatin1Char('_'));
    // Main.a[2] would read as bit 2 of a vector Main.a: an escaped identifier (IEEE 1364) keeps
    // the brackets part of the name, which GTKWave then shows as written.
    if (reference.contains(QLatin1Char('[')))
        reference.prepend(QLatin1Char('\\'));
    return QStringLiteral("$var %1 %2 %3 %4 $end\n").arg(type).arg(width).arg(identifier(index), reference);
}

class VcdWriter : public TraceWriter
{
public:
    VcdWriter(QTextStream &out, std::vector<TraceVariable> variables, std::int64_t cycleNs, QString generator)
        : m_out(out)
        , m_variables(std::move(variables))
        , m_nsPerUnit(cycleNs % 1000 == 0 ? 1000 : 1)
        , m_generator(std::move(generator))
    { }

    void begin(const TraceRow &initial) override
    {
        m_out << "$version " << m_generator << " $end\n";
        m_out << "$timescale 1 " << (m_nsPerUnit == 1000 ? "us" : "ns") << " $end\n";
        m_out << "$scope module iecstudio $end\n";
        for (size_t i = 0; i < m_variables.size(); ++i)
            m_out << declaration(m_variables[i], i);
        m_out << "$upscope $end\n$enddefinitions $end\n#" << initial.timeNs / m_nsPerUnit << "\n$dumpvars\n";
        m_last.assign(m_variables.size(), QString());
        writeChanges(initial);
        m_out << "$end\n";
    }

    void write(const TraceRow &row) override
    {
        m_out << '#' << row.timeNs / m_nsPerUnit << '\n';
        writeChanges(row);
    }

private:
    void writeChanges(const TraceRow &row)
    {
        for (size_t i = 0; i < m_variables.size(); ++i) {
            const QString value = vcdValue(row, i, m_variables[i].ref);
            if (value == m_last[i])
                continue;
            m_last[i] = value;
            m_out << value << identifier(i) << '\n';
        }
    }

    QTextStream &m_out;
    std::vector<TraceVariable> m_variables;
    std::int64_t m_nsPerUnit;
    QString m_generator;
    std::vector<QString> m_last; // the last value written per variable
};

} // namespace

std::unique_ptr<TraceWriter> makeCsvWriter(QTextStream &out, std::vector<TraceVariable> variables)
{
    return std::make_unique<CsvWriter>(out, std::move(variables));
}

std::unique_ptr<TraceWriter> makeVcdWriter(QTextStream &out, std::vector<TraceVariable> variables, std::int64_t cycleNs,
                                           const QString &generator)
{
    return std::make_unique<VcdWriter>(out, std::move(variables), cycleNs, generator);
}

bool vcdCanHold(const std::vector<TraceVariable> &variables, QString &error)
{
    for (const TraceVariable &variable : variables) {
        if (kindOf(variable.ref) == VcdKind::None) {
            error = QStringLiteral("%1 is a %2, which a VCD trace cannot show; trace it to a .csv file instead.")
                        .arg(variable.name, typeName(variable.ref.type));
            return false;
        }
    }
    return true;
}

QString csvField(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QString formatMilliseconds(std::int64_t ns)
{
    if (ns % 1'000'000 == 0)
        return QString::number(ns / 1'000'000);
    QString text = QString::number(static_cast<double>(ns) / 1e6, 'f', 6);
    while (text.endsWith(QLatin1Char('0')))
        text.chop(1);
    return text;
}

} // namespace iec::interp
