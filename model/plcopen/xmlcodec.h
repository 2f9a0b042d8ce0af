#pragma once

// Conversions between attribute text and model values, shared by the reader and the writer.

#include "model/filetext.h"
#include "model/graphics.h"
#include "model/pou.h"
#include "model/variables.h"

#include <QString>

#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

namespace iec::model::plcopen {

template<class T> struct Codec;

template<> struct Codec<QString> {
    static bool parse(const char *text, QString &value)
    {
        value = QString::fromUtf8(text);
        return true;
    }
    static std::string format(const QString &value) { return toFileUtf8(value).toStdString(); }
};

template<> struct Codec<bool> {
    static bool parse(const char *text, bool &value)
    {
        // xsd:boolean: true, false, 1, 0
        if (!std::strcmp(text, "true") || !std::strcmp(text, "1"))
            value = true;
        else if (!std::strcmp(text, "false") || !std::strcmp(text, "0"))
            value = false;
        else
            return false;
        return true;
    }
    static std::string format(bool value) { return value ? "true" : "false"; }
};

template<class N>
requires std::is_arithmetic_v<N>
struct NumberCodec {
    static bool parse(const char *text, N &value)
    {
        while (*text == ' ' || *text == '\t' || *text == '\n' || *text == '\r')
            ++text;
        if constexpr (std::is_floating_point_v<N>) {
            if (*text == '+')
                ++text;
        }
        const char *end = text + std::strlen(text);
        while (end > text && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\n' || end[-1] == '\r'))
            --end;
        const auto [ptr, ec] = std::from_chars(text, end, value);
        if constexpr (std::is_floating_point_v<N>) {
            if (!std::isfinite(value)) // xsd:decimal has no NaN or infinity
                return false;
        }
        return ec == std::errc() && ptr == end && ptr != text;
    }
    static std::string format(N value)
    {
        // The shortest text that reads back as the same value, in fixed notation because xsd:decimal
        // has no exponent (the largest double has 309 digits).
        std::array<char, 512> buffer {};
        std::to_chars_result result;
        if constexpr (std::is_floating_point_v<N>)
            result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::fixed);
        else
            result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
        return result.ec == std::errc() ? std::string(buffer.data(), result.ptr) : std::string("0");
    }
};

template<> struct Codec<double> : NumberCodec<double> { };
template<> struct Codec<quint64> : NumberCodec<quint64> { };
template<> struct Codec<quint32> : NumberCodec<quint32> { };

// Enumerations: one table per enum, in the XSD's spelling.
template<class E> struct EnumNames;

template<> struct EnumNames<EdgeModifier> {
    static constexpr std::array<std::pair<EdgeModifier, const char *>, 3> table {
        {{EdgeModifier::None, "none"}, {EdgeModifier::Falling, "falling"}, {EdgeModifier::Rising, "rising"}}};
};

template<> struct EnumNames<StorageModifier> {
    static constexpr std::array<std::pair<StorageModifier, const char *>, 3> table {
        {{StorageModifier::None, "none"}, {StorageModifier::Set, "set"}, {StorageModifier::Reset, "reset"}}};
};

template<> struct EnumNames<PouKind> {
    static constexpr std::array<std::pair<PouKind, const char *>, 3> table {
        {{PouKind::Program, "program"}, {PouKind::FunctionBlock, "functionBlock"}, {PouKind::Function, "function"}}};
};

template<> struct EnumNames<AccessDirection> {
    static constexpr std::array<std::pair<AccessDirection, const char *>, 2> table {
        {{AccessDirection::ReadOnly, "readOnly"}, {AccessDirection::ReadWrite, "readWrite"}}};
};

template<class E>
requires std::is_enum_v<E>
struct Codec<E> {
    static bool parse(const char *text, E &value)
    {
        for (const auto &[candidate, name] : EnumNames<E>::table) {
            if (!std::strcmp(text, name)) {
                value = candidate;
                return true;
            }
        }
        return false;
    }
    static std::string format(E value)
    {
        for (const auto &[candidate, name] : EnumNames<E>::table) {
            if (candidate == value)
                return name;
        }
        return {};
    }
};

} // namespace iec::model::plcopen
