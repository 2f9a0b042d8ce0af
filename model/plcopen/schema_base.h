#pragma once

// Schema of the XSD's shared types: positions, connection points, formatted text, values, data
// types and variable lists. One describe() per element serves both archives (xmlarchive.h).

#include "model/plcopen/xmlarchive.h"

#include <algorithm>
#include <array>

namespace iec::model::plcopen {

// A boxed value is described like the value itself.
template<class T> struct Schema<Box<T>> {
    template<class A, class V> static void describe(A &a, V &box) { Schema<T>::describe(a, *box); }
};

template<> struct Schema<Position> {
    template<class A, class V> static void describe(A &a, V &position)
    {
        a.attr("x", position.x);
        a.attr("y", position.y);
    }
};

template<> struct Schema<Scaling> {
    template<class A, class V> static void describe(A &a, V &scaling)
    {
        a.attr("x", scaling.x);
        a.attr("y", scaling.y);
    }
};

template<> struct Schema<Connection> {
    template<class A, class V> static void describe(A &a, V &connection)
    {
        a.attr("globalId", connection.globalId);
        a.attr("refLocalId", connection.refLocalId);
        a.attr("formalParameter", connection.formalParameter);
        a.children("position", connection.waypoints);
        a.addData(connection.addData);
        a.finish(connection.extras);
    }
};

template<> struct Schema<ConnectionPointIn> {
    static constexpr const char *tag = "connectionPointIn";
    template<class A, class V> static void describe(A &a, V &point)
    {
        a.attr("globalId", point.globalId);
        a.child("relPosition", point.relPosition);
        a.children("connection", point.connections);
        a.text("expression", point.expression);
        a.addData(point.addData);
        a.finish(point.extras);
    }
};

template<> struct Schema<ConnectionPointOut> {
    template<class A, class V> static void describe(A &a, V &point)
    {
        a.attr("globalId", point.globalId);
        a.attr("formalParameter", point.formalParameter);
        a.child("relPosition", point.relPosition);
        a.text("expression", point.expression);
        a.addData(point.addData);
        a.finish(point.extras);
    }
};

// ppx:formattedText. See FormattedText for what is kept.
void readFormattedText(pugi::xml_node node, FormattedText &text);
void writeFormattedText(pugi::xml_node node, const FormattedText &text);
// Program text: ST and IL bodies are always written as one <xhtml:p> with CDATA.
void writeProgramText(pugi::xml_node node, const QString &text);

template<> struct Schema<FormattedText> {
    template<class A, class V> static void describe(A &a, V &text)
    {
        if constexpr (A::reading)
            readFormattedText(a.node(), text);
        else
            writeFormattedText(a.node(), text);
        a.skipRest();
    }
};

// ---- values -------------------------------------------------------------------------------

template<> struct Schema<SimpleValue> {
    static constexpr const char *tag = "simpleValue";
    template<class A, class V> static void describe(A &a, V &value) { a.attr("value", value.value); }
};

template<> struct Schema<Value> {
    template<class A, class V> static void describe(A &a, V &value) { a.choice(value.kind, "simpleValue"); }
};

template<> struct Schema<ArrayValueItem> {
    template<class A, class V> static void describe(A &a, V &item)
    {
        a.attr("repetitionValue", item.repetitionValue);
        Schema<Value>::describe(a, *item.value);
    }
};

template<> struct Schema<ArrayValue> {
    static constexpr const char *tag = "arrayValue";
    template<class A, class V> static void describe(A &a, V &value) { a.children("value", value.values); }
};

template<> struct Schema<StructValueItem> {
    template<class A, class V> static void describe(A &a, V &item)
    {
        a.attr("member", item.member);
        Schema<Value>::describe(a, *item.value);
    }
};

template<> struct Schema<StructValue> {
    static constexpr const char *tag = "structValue";
    template<class A, class V> static void describe(A &a, V &value) { a.children("value", value.values); }
};

// ---- data types ---------------------------------------------------------------------------

// The elementary types of the XSD; the element name is the type name.
inline constexpr std::array<const char *, 29> kElementaryTypeNames {"BOOL", "BYTE", "WORD", "DWORD", "LWORD", "SINT",
    "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL", "TIME", "DATE", "DT", "TOD", "ANY",
    "ANY_DERIVED", "ANY_ELEMENTARY", "ANY_MAGNITUDE", "ANY_NUM", "ANY_REAL", "ANY_INT", "ANY_BIT", "ANY_STRING",
    "ANY_DATE"};

template<> struct Schema<Range> {
    template<class A, class V> static void describe(A &a, V &range)
    {
        a.attr("lower", range.lower);
        a.attr("upper", range.upper);
    }
};

template<> struct Schema<StringType> {
    template<class A, class V> static void describe(A &a, V &type) { a.attr("length", type.length); }
};

template<> struct Schema<ElementaryType> {
    template<class A, class V> static void describe(A &, V &) { }
};

template<> struct Schema<DataType> {
    template<class A, class V> static void describe(A &a, V &type);
};

template<> struct Schema<ArrayType> {
    template<class A, class V> static void describe(A &a, V &type)
    {
        a.children("dimension", type.dimensions);
        a.child("baseType", type.baseType);
    }
};

template<> struct Schema<DerivedType> {
    template<class A, class V> static void describe(A &a, V &type)
    {
        a.attr("name", type.name);
        a.addData(type.addData);
        a.finish(type.extras);
    }
};

template<> struct Schema<EnumValue> {
    template<class A, class V> static void describe(A &a, V &value)
    {
        a.attr("name", value.name);
        a.attr("value", value.value);
    }
};

template<> struct Schema<EnumType> {
    template<class A, class V> static void describe(A &a, V &type)
    {
        a.containerList("values", "value", type.values, true);
        a.child("baseType", type.baseType);
    }
};

template<> struct Schema<Variable> {
    template<class A, class V> static void describe(A &a, V &variable)
    {
        a.attr("name", variable.name);
        a.attr("address", variable.address);
        a.attr("globalId", variable.globalId);
        a.child("type", variable.type);
        a.child("initialValue", variable.initialValue);
        a.addData(variable.addData);
        a.child("documentation", variable.documentation);
        a.finish(variable.extras);
    }
};

template<> struct Schema<StructType> {
    template<class A, class V> static void describe(A &a, V &type)
    {
        a.children("variable", type.members);
        a.addData(type.addData);
        a.child("documentation", type.documentation);
        a.finish(type.extras);
    }
};

template<> struct Schema<SubrangeType> {
    template<class A, class V> static void describe(A &a, V &type)
    {
        a.child("range", type.range);
        a.child("baseType", type.baseType);
    }
};

template<> struct Schema<PointerType> {
    template<class A, class V> static void describe(A &a, V &type) { a.child("baseType", type.baseType); }
};

// The element name a data type is written as.
std::string dataTypeTag(const DataType &type);

template<class A, class V> void Schema<DataType>::describe(A &a, V &type)
{
    if constexpr (A::reading) {
        pugi::xml_node node = a.node().find_child([](pugi::xml_node n) { return n.type() == pugi::node_element; });
        if (!node) {
            a.context().report(Diagnostic::Severity::Error, a.node(),
                QCoreApplication::translate("iec::model::plcopen::Reader", "<%1> names no data type.")
                    .arg(QString::fromUtf8(localName(a.node()))));
            return;
        }
        const char *name = localName(node);
        a.markKnown(name);
        a.markRead(node);
        auto is = [name](const char *candidate) { return std::strcmp(name, candidate) == 0; };
        if (std::ranges::any_of(kElementaryTypeNames, is)) {
            type.kind = ElementaryType {QString::fromUtf8(name)};
        } else if (is("string") || is("wstring")) {
            a.read(node, type.kind.template emplace<StringType>());
            std::get<StringType>(type.kind).wide = is("wstring");
        } else if (is("array")) {
            a.read(node, type.kind.template emplace<ArrayType>());
        } else if (is("derived")) {
            a.read(node, type.kind.template emplace<DerivedType>());
        } else if (is("enum")) {
            a.read(node, type.kind.template emplace<EnumType>());
        } else if (is("struct")) {
            a.read(node, type.kind.template emplace<StructType>());
        } else if (is("subrangeSigned") || is("subrangeUnsigned")) {
            a.read(node, type.kind.template emplace<SubrangeType>());
            std::get<SubrangeType>(type.kind).isUnsigned = is("subrangeUnsigned");
        } else if (is("pointer")) {
            a.read(node, type.kind.template emplace<PointerType>());
        } else {
            // A type name the XSD does not know (LTIME, vendor types): keep it as an elementary name,
            // without its namespace prefix. A local name that is empty or has a ':' itself (<IN:/>,
            // <a::B/>) is kept whole, else each round would lose a part (found by fuzz_plcopen).
            const char *kept = *name && !std::strchr(name, ':') ? name : node.name();
            type.kind = ElementaryType {QString::fromUtf8(kept)};
            a.context().report(Diagnostic::Severity::Warning, node,
                QCoreApplication::translate("iec::model::plcopen::Reader",
                    "The data type <%1> is not in the PLCopen schema; it is kept by name.")
                    .arg(QString::fromUtf8(kept)));
        }
    } else {
        std::visit(
            [&](const auto &kind) { a.write(a.node().append_child(dataTypeTag(type).c_str()), kind); }, type.kind);
    }
}

// ---- variable lists -----------------------------------------------------------------------

template<> struct Schema<VarList> {
    template<class A, class V> static void describe(A &a, V &list)
    {
        a.attr("name", list.name);
        a.attr("constant", list.constant, false);
        a.attr("retain", list.retain, false);
        a.attr("nonretain", list.nonretain, false);
        a.attr("persistent", list.persistent, false);
        a.attr("nonpersistent", list.nonpersistent, false);
        a.children("variable", list.variables);
        a.addData(list.addData);
        a.child("documentation", list.documentation);
        a.finish(list.extras);
    }
};

template<> struct Schema<AccessVariable> {
    template<class A, class V> static void describe(A &a, V &variable)
    {
        a.attr("alias", variable.alias);
        a.attr("instancePathAndName", variable.instancePathAndName);
        a.attr("direction", variable.direction);
        a.child("type", variable.type);
        a.addData(variable.addData);
        a.child("documentation", variable.documentation);
        a.finish(variable.extras);
    }
};

template<> struct Schema<AccessVarList> {
    template<class A, class V> static void describe(A &a, V &list)
    {
        a.children("accessVariable", list.variables);
        a.addData(list.addData);
        a.child("documentation", list.documentation);
        a.finish(list.extras);
    }
};

template<> struct Schema<ConfigVariable> {
    template<class A, class V> static void describe(A &a, V &variable)
    {
        a.attr("instancePathAndName", variable.instancePathAndName);
        a.attr("address", variable.address);
        a.child("type", variable.type);
        a.child("initialValue", variable.initialValue);
        a.addData(variable.addData);
        a.child("documentation", variable.documentation);
        a.finish(variable.extras);
    }
};

template<> struct Schema<ConfigVarList> {
    template<class A, class V> static void describe(A &a, V &list)
    {
        a.children("configVariable", list.variables);
        a.addData(list.addData);
        a.child("documentation", list.documentation);
        a.finish(list.extras);
    }
};

} // namespace iec::model::plcopen
