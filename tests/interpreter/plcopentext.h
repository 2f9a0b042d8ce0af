#pragma once

// Test-only: turns the ST POUs of a PLCopen TC6 file into IEC textual source, so the corpus can
// be compiled before the model -> AST step exists. It knows the parts of the format the corpus
// uses: interface sections, elementary/string/derived/array types, simple initial values.

#include <QFile>
#include <QStringList>
#include <QXmlStreamReader>

namespace iec::interp::testing {

struct PlcopenPou {
    QString name;
    QString kind;     // program, functionBlock, function
    QString language; // ST, IL, FBD, LD, SFC
    QString source;   // IEC text of the whole POU
};

inline QString plcopenType(QXmlStreamReader &xml)
{
    // At <type> or <baseType>; reads up to its end.
    QString type;
    while (xml.readNextStartElement()) {
        const QString tag = xml.name().toString();
        if (tag == QLatin1String("derived")) {
            type = xml.attributes().value(QLatin1String("name")).toString();
            xml.skipCurrentElement();
        } else if (tag == QLatin1String("string") || tag == QLatin1String("wstring")) {
            const QString length = xml.attributes().value(QLatin1String("length")).toString();
            type = tag.toUpper() + (length.isEmpty() ? QString() : QLatin1Char('[') + length + QLatin1Char(']'));
            xml.skipCurrentElement();
        } else if (tag == QLatin1String("array")) {
            QStringList dims;
            QString base;
            while (xml.readNextStartElement()) {
                if (xml.name() == QLatin1String("dimension")) {
                    dims << xml.attributes().value(QLatin1String("lower")).toString() + QStringLiteral("..")
                                + xml.attributes().value(QLatin1String("upper")).toString();
                    xml.skipCurrentElement();
                } else if (xml.name() == QLatin1String("baseType")) {
                    base = plcopenType(xml);
                } else {
                    xml.skipCurrentElement();
                }
            }
            type = QStringLiteral("ARRAY[") + dims.join(QLatin1Char(',')) + QStringLiteral("] OF ") + base;
        } else {
            type = tag;
            xml.skipCurrentElement();
        }
    }
    return type;
}

inline std::vector<PlcopenPou> readPlcopenPous(const QString &path)
{
    std::vector<PlcopenPou> pous;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return pous;
    QXmlStreamReader xml(&file);
    static const std::pair<const char *, const char *> sections[] = {
        {"inputVars", "VAR_INPUT"}, {"outputVars", "VAR_OUTPUT"}, {"inOutVars", "VAR_IN_OUT"}, {"localVars", "VAR"},
        {"tempVars", "VAR_TEMP"}, {"externalVars", "VAR_EXTERNAL"}, {"globalVars", "VAR_GLOBAL"},
    };
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement() || xml.name() != QLatin1String("pou"))
            continue;
        PlcopenPou pou;
        pou.name = xml.attributes().value(QLatin1String("name")).toString();
        pou.kind = xml.attributes().value(QLatin1String("pouType")).toString();
        QString declarations, body, returnType;
        while (xml.readNextStartElement()) {
            if (xml.name() == QLatin1String("interface")) {
                while (xml.readNextStartElement()) {
                    const QString tag = xml.name().toString();
                    if (tag == QLatin1String("returnType")) {
                        returnType = plcopenType(xml);
                        continue;
                    }
                    const char *keyword = nullptr;
                    for (const auto &[name, word] : sections) {
                        if (tag == QLatin1String(name))
                            keyword = word;
                    }
                    if (!keyword) {
                        xml.skipCurrentElement();
                        continue;
                    }
                    QString section = QLatin1String(keyword);
                    if (xml.attributes().value(QLatin1String("constant")) == QLatin1String("true"))
                        section += QStringLiteral(" CONSTANT");
                    if (xml.attributes().value(QLatin1String("retain")) == QLatin1String("true"))
                        section += QStringLiteral(" RETAIN");
                    section += QLatin1Char('\n');
                    while (xml.readNextStartElement()) {
                        if (xml.name() != QLatin1String("variable")) {
                            xml.skipCurrentElement();
                            continue;
                        }
                        const QString name = xml.attributes().value(QLatin1String("name")).toString();
                        const QString address = xml.attributes().value(QLatin1String("address")).toString();
                        QString type, init;
                        while (xml.readNextStartElement()) {
                            if (xml.name() == QLatin1String("type")) {
                                type = plcopenType(xml);
                            } else if (xml.name() == QLatin1String("initialValue")) {
                                while (xml.readNextStartElement()) {
                                    if (xml.name() == QLatin1String("simpleValue"))
                                        init = xml.attributes().value(QLatin1String("value")).toString();
                                    xml.skipCurrentElement();
                                }
                            } else {
                                xml.skipCurrentElement();
                            }
                        }
                        section += QStringLiteral("  ") + name + (address.isEmpty() ? QString() : QStringLiteral(" AT ") + address)
                            + QStringLiteral(" : ") + type + (init.isEmpty() ? QString() : QStringLiteral(" := ") + init) + QStringLiteral(";\n");
                    }
                    declarations += section + QStringLiteral("END_VAR\n");
                }
            } else if (xml.name() == QLatin1String("body")) {
                while (xml.readNextStartElement()) {
                    pou.language = xml.name().toString();
                    if (pou.language == QLatin1String("ST") || pou.language == QLatin1String("IL")) {
                        while (xml.readNextStartElement()) {
                            body += xml.readElementText(QXmlStreamReader::IncludeChildElements);
                        }
                    } else {
                        xml.skipCurrentElement();
                    }
                }
            } else {
                xml.skipCurrentElement();
            }
        }
        const QString keyword = pou.kind == QLatin1String("program") ? QStringLiteral("PROGRAM")
            : pou.kind == QLatin1String("function")                  ? QStringLiteral("FUNCTION")
                                                                     : QStringLiteral("FUNCTION_BLOCK");
        pou.source = keyword + QLatin1Char(' ') + pou.name + (returnType.isEmpty() ? QString() : QStringLiteral(" : ") + returnType)
            + QLatin1Char('\n') + declarations + body + QStringLiteral("\nEND_") + keyword + QLatin1Char('\n');
        pous.push_back(pou);
    }
    return pous;
}

} // namespace iec::interp::testing
