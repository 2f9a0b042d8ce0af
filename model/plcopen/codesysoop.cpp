#include "model/plcopen/codesysoop.h"

#include "model/plcopen/schema_project.h"

#include <QRegularExpression>

namespace iec::model::plcopen {

namespace {

constexpr const char *kMethod = "http://www.3s-software.com/plcopenxml/method";
constexpr const char *kProperty = "http://www.3s-software.com/plcopenxml/property";
constexpr const char *kInheritance = "http://www.3s-software.com/plcopenxml/pouinheritance";
constexpr const char *kInterface = "http://www.3s-software.com/plcopenxml/interface";

pugi::xml_node child(pugi::xml_node node, const char *name)
{
    for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling()) {
        if (c.type() == pugi::node_element && hasLocalName(c, name))
            return c;
    }
    return {};
}

QString text(pugi::xml_node node)
{
    return QString::fromUtf8(node.text().get()).trimmed();
}

// The qualifiers of a method or property: from CODESYS's plain-text declaration when it wrote
// one (METHOD PRIVATE ABSTRACT M : INT), else from its AccessModifiers entry.
QStringList qualifiersOf(pugi::xml_node member)
{
    static const QStringList known {QStringLiteral("PUBLIC"), QStringLiteral("PRIVATE"), QStringLiteral("PROTECTED"),
                                    QStringLiteral("INTERNAL"), QStringLiteral("ABSTRACT"), QStringLiteral("FINAL")};
    QString declaration;
    walkDescendants(member, [&](pugi::xml_node n) {
        if (n.type() != pugi::node_element)
            return false;
        if (hasLocalName(n, "InterfaceAsPlainText") || hasLocalName(n, "AccessModifiers")) {
            declaration += QString::fromUtf8(rawXml(n).toUtf8()).section(QLatin1Char('\n'), 0, 0) + QLatin1Char(' ');
            return false;
        }
        return !hasLocalName(n, "body");
    });
    QStringList found;
    const QString upper = declaration.toUpper();
    for (const QString &q : known) {
        if (upper.contains(QRegularExpression(QStringLiteral("\\b%1\\b").arg(q))))
            found << q;
    }
    return found;
}

struct Reader {
    ReadContext context;

    Interface interfaceOf(pugi::xml_node node)
    {
        Interface result;
        if (const pugi::xml_node i = child(node, "interface")) {
            XmlIn in(node, context);
            in.read(i, result);
        }
        return result;
    }
    std::optional<Body> bodyOf(pugi::xml_node node)
    {
        const pugi::xml_node b = child(node, "body");
        if (!b)
            return std::nullopt;
        Body body;
        XmlIn in(node, context);
        in.read(b, body);
        return body;
    }
    void member(pugi::xml_node node, CodesysClass &into)
    {
        CodesysMember m;
        m.name = QString::fromUtf8(node.attribute("name").value());
        m.qualifiers = qualifiersOf(node);
        if (hasLocalName(node, "Method")) {
            m.interface = interfaceOf(node);
            m.body = bodyOf(node);
            into.members.push_back(std::move(m));
            return;
        }
        // A property: its type in its interface, a Get and a Set accessor with their own.
        const Interface declared = interfaceOf(node);
        m.type = declared.returnType;
        for (const char *accessor : {"GetAccessor", "SetAccessor"}) {
            const pugi::xml_node a = child(node, accessor);
            if (!a)
                continue;
            CodesysMember part = m;
            part.kind = !std::strcmp(accessor, "GetAccessor") ? CodesysMember::Kind::Getter : CodesysMember::Kind::Setter;
            part.interface = interfaceOf(a);
            part.body = bodyOf(a);
            into.members.push_back(std::move(part));
        }
    }
    // The Method and Property elements (and interfaces' Inheritance) of one addData entry.
    void entry(const AddDataEntry &e, CodesysClass &into)
    {
        pugi::xml_document document;
        const QByteArray wrapped = "<r>" + e.content.toUtf8() + "</r>";
        if (!document.load_buffer(wrapped.constData(), std::size_t(wrapped.size())))
            return;
        for (pugi::xml_node n = document.first_child().first_child(); n; n = n.next_sibling()) {
            if (n.type() != pugi::node_element)
                continue;
            if (hasLocalName(n, "Method") || hasLocalName(n, "Property"))
                member(n, into);
            else if (hasLocalName(n, "Inheritance"))
                inheritance(n, into);
        }
    }
    void inheritance(pugi::xml_node n, CodesysClass &into)
    {
        for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling()) {
            if (hasLocalName(c, "Extends") && into.extends.isEmpty())
                into.extends = text(c);
            else if (hasLocalName(c, "Implements") || hasLocalName(c, "Extends"))
                into.implements << text(c);
        }
    }
};

} // namespace

CodesysClass readCodesysClass(const Pou &pou)
{
    Reader reader;
    CodesysClass result;
    for (const AddDataEntry &e : pou.addData) {
        if (e.name == QLatin1String(kMethod) || e.name == QLatin1String(kProperty))
            reader.entry(e, result);
    }
    if (pou.pouInterface) {
        for (const AddDataEntry &e : pou.pouInterface->addData) {
            if (e.name == QLatin1String(kInheritance))
                reader.entry(e, result);
        }
    }
    return result;
}

std::vector<CodesysInterface> readCodesysInterfaces(const Project &project)
{
    std::vector<CodesysInterface> found;
    const auto scan = [&](const AddData &data) {
        for (const AddDataEntry &e : data) {
            if (e.name != QLatin1String(kInterface))
                continue;
            pugi::xml_document document;
            const QByteArray wrapped = "<r>" + e.content.toUtf8() + "</r>";
            if (!document.load_buffer(wrapped.constData(), std::size_t(wrapped.size())))
                continue;
            for (pugi::xml_node n = document.first_child().first_child(); n; n = n.next_sibling()) {
                if (n.type() != pugi::node_element || !hasLocalName(n, "Interface"))
                    continue;
                CodesysInterface itf;
                itf.name = QString::fromUtf8(n.attribute("name").value());
                Reader reader;
                // Its methods and properties, and the interfaces it extends, in its own addData.
                walkDescendants(n, [&](pugi::xml_node c) {
                    if (c.type() != pugi::node_element)
                        return false;
                    if (hasLocalName(c, "Method") || hasLocalName(c, "Property")) {
                        reader.member(c, itf.definition);
                        return false;
                    }
                    if (hasLocalName(c, "Inheritance")) {
                        reader.inheritance(c, itf.definition);
                        return false;
                    }
                    return true;
                });
                found.push_back(std::move(itf));
            }
        }
    };
    scan(project.addData);
    for (const Configuration &c : project.instances.configurations) {
        scan(c.addData);
        for (const Resource &r : c.resources)
            scan(r.addData);
    }
    return found;
}

} // namespace iec::model::plcopen
