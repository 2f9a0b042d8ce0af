#include "model/plcopen/codesysoop.h"

#include "model/plcopen/schema_project.h"

#include <QRegularExpression>

#include <algorithm>
#include <cstring>

namespace iec::model::plcopen {

namespace {

constexpr const char *kMethod = "http://www.3s-software.com/plcopenxml/method";
constexpr const char *kProperty = "http://www.3s-software.com/plcopenxml/property";
constexpr const char *kInheritance = "http://www.3s-software.com/plcopenxml/pouinheritance";
constexpr const char *kInterface = "http://www.3s-software.com/plcopenxml/interface";
constexpr const char *kPlainText = "http://www.3s-software.com/plcopenxml/interfaceasplaintext";

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

// ---- writing members ------------------------------------------------------------------------

bool isMemberEntry(const AddDataEntry &e)
{
    return e.name == QLatin1String(kMethod) || e.name == QLatin1String(kProperty);
}

bool isMemberNode(pugi::xml_node n)
{
    return n.type() == pugi::node_element && (hasLocalName(n, "Method") || hasLocalName(n, "Property"));
}

// Text inside `node`; none when empty, so that the element reads back as it was written (an empty
// text node is written as <x></x> but read as <x/>; found by the monkey test).
void appendText(pugi::xml_node node, const QString &text)
{
    if (!text.isEmpty())
        node.append_child(pugi::node_pcdata).set_value(toFileUtf8(text).constData());
}

// CODESYS's form of program text: <ST><xhtml xmlns="...">text</xhtml></ST>.
void appendBody(pugi::xml_node parent, const Body &body)
{
    const char *language = body.language() == BodyLanguage::IL ? "IL" : "ST";
    pugi::xml_node xhtml = parent.append_child("body").append_child(language).append_child("xhtml");
    xhtml.append_attribute("xmlns").set_value(kXhtmlNamespace);
    appendText(xhtml, body.text());
}

void appendInterface(pugi::xml_node parent, const Interface &interface)
{
    WriteContext context;
    XmlOut out(parent, context);
    out.child("interface", interface);
}

// The member's own addData: what it had, with its InterfaceAsPlainText set to `declaration`.
void appendOwnAddData(pugi::xml_node parent, pugi::xml_node old, const QString &declaration)
{
    pugi::xml_node addData = old ? parent.append_copy(old) : parent.append_child("addData");
    pugi::xml_node entry;
    for (pugi::xml_node d = addData.first_child(); d; d = d.next_sibling()) {
        if (d.type() == pugi::node_element && QString::fromUtf8(d.attribute("name").value()) == QLatin1String(kPlainText))
            entry = d;
    }
    if (!entry) {
        entry = addData.append_child("data");
        entry.append_attribute("name").set_value(kPlainText);
        entry.append_attribute("handleUnknown").set_value("implementation");
    }
    while (entry.first_child())
        entry.remove_child(entry.first_child());
    pugi::xml_node xhtml = entry.append_child("InterfaceAsPlainText").append_child("xhtml");
    xhtml.append_attribute("xmlns").set_value(kXhtmlNamespace);
    appendText(xhtml, declaration);
}

void appendAccessor(pugi::xml_node parent, const char *tag, const CodesysMemberDefinition::Accessor &accessor, pugi::xml_node old)
{
    pugi::xml_node node = parent.append_child(tag);
    appendInterface(node, accessor.interface);
    if (accessor.body)
        appendBody(node, *accessor.body);
    if (const pugi::xml_node oldAddData = child(old, "addData"))
        node.append_copy(oldAddData);
    else
        node.append_child("addData");
}

// The member's element, built before `before` (the element it replaces, or none).
void insertMember(pugi::xml_node parent, pugi::xml_node before, const CodesysMemberDefinition &member)
{
    pugi::xml_node node = before ? parent.insert_child_before(member.property ? "Property" : "Method", before)
                                 : parent.append_child(member.property ? "Property" : "Method");
    node.append_attribute("name").set_value(toFileUtf8(member.name).constData());
    for (pugi::xml_attribute a = before.first_attribute(); a; a = a.next_attribute()) {
        if (std::strcmp(a.name(), "name") != 0)
            node.append_attribute(a.name()).set_value(a.value()); // ObjectId and what else CODESYS wrote
    }
    appendInterface(node, member.interface);
    if (!member.property) {
        if (member.body)
            appendBody(node, *member.body);
    } else {
        // The accessors in the order they stood (CODESYS writes Set before Get), new ones Get first.
        std::vector<std::pair<const char *, const CodesysMemberDefinition::Accessor *>> accessors;
        for (pugi::xml_node c = before.first_child(); c; c = c.next_sibling()) {
            if (c.type() == pugi::node_element && hasLocalName(c, "SetAccessor") && member.setter)
                accessors.emplace_back("SetAccessor", &*member.setter);
            else if (c.type() == pugi::node_element && hasLocalName(c, "GetAccessor") && member.getter)
                accessors.emplace_back("GetAccessor", &*member.getter);
        }
        const auto addNew = [&](const char *tag, const CodesysMemberDefinition::Accessor *accessor) {
            if (accessor && std::ranges::none_of(accessors, [&](const auto &a) { return !std::strcmp(a.first, tag); }))
                accessors.emplace_back(tag, accessor);
        };
        addNew("GetAccessor", member.getter ? &*member.getter : nullptr);
        addNew("SetAccessor", member.setter ? &*member.setter : nullptr);
        for (const auto &[tag, accessor] : accessors)
            appendAccessor(node, tag, *accessor, child(before, tag));
    }
    appendOwnAddData(node, child(before, "addData"), member.declarationText);
}

QString contentOf(pugi::xml_node root)
{
    QString content;
    for (pugi::xml_node n = root.first_child(); n; n = n.next_sibling())
        content += rawXml(n);
    return content;
}

bool isInterfaceEntry(const AddDataEntry &e)
{
    return e.name == QLatin1String(kInterface);
}

bool isInterfaceNode(pugi::xml_node n)
{
    return n.type() == pugi::node_element && hasLocalName(n, "Interface");
}

// Calls `edit(entry, root, element)` for the first entry where `isEntry` holds that has an
// element called `name` (case-insensitive) where `isNode` holds, its content parsed under `root`;
// false when there is none.
template<class Data, class Edit> bool editNamedElement(Data &addData, const QString &name, bool (*isEntry)(const AddDataEntry &),
    bool (*isNode)(pugi::xml_node), Edit edit)
{
    for (auto &e : addData) {
        if (!isEntry(e))
            continue;
        pugi::xml_document document;
        const QByteArray wrapped = "<r>" + e.content.toUtf8() + "</r>";
        if (!document.load_buffer(wrapped.constData(), std::size_t(wrapped.size()), pugi::parse_default | pugi::parse_ws_pcdata_single))
            continue;
        const pugi::xml_node root = document.first_child();
        for (pugi::xml_node n = root.first_child(); n; n = n.next_sibling()) {
            if (isNode(n) && QString::fromUtf8(n.attribute("name").value()).compare(name, Qt::CaseInsensitive) == 0) {
                edit(e, root, n);
                return true;
            }
        }
    }
    return false;
}

template<class Edit> bool editMemberEntry(AddData &addData, const QString &name, Edit edit)
{
    return editNamedElement(addData, name, isMemberEntry, isMemberNode, edit);
}

template<class Edit> bool editInterfaceEntry(AddData &addData, const QString &name, Edit edit)
{
    return editNamedElement(addData, name, isInterfaceEntry, isInterfaceNode, edit);
}

// `addData` without the element called `name`; an entry left with no element goes too (CODESYS
// writes one member or interface per entry).
AddData withoutNamedElement(const AddData &addData, const QString &name, bool (*isEntry)(const AddDataEntry &),
    bool (*isNode)(pugi::xml_node))
{
    AddData result = addData;
    editNamedElement(result, name, isEntry, isNode, [&](AddDataEntry &e, pugi::xml_node root, pugi::xml_node old) {
        root.remove_child(old);
        e.content = contentOf(root);
    });
    std::erase_if(result, [&](const AddDataEntry &e) { return isEntry(e) && e.content.trimmed().isEmpty(); });
    return result;
}

// An interface's content: its own addData with the interfaces it extends and its prototypes.
void appendInterfaceContent(pugi::xml_node itf, const CodesysInterfaceDefinition &definition)
{
    pugi::xml_node own = itf.append_child("addData");
    if (!definition.extends.isEmpty()) {
        pugi::xml_node entry = own.append_child("data");
        entry.append_attribute("name").set_value(kInheritance);
        entry.append_attribute("handleUnknown").set_value("implementation");
        pugi::xml_node inheritance = entry.append_child("Inheritance");
        for (const QString &base : definition.extends)
            appendText(inheritance.append_child("Extends"), base);
    }
    for (CodesysMemberDefinition prototype : definition.members) {
        prototype.body.reset();
        for (std::optional<CodesysMemberDefinition::Accessor> *accessor : {&prototype.getter, &prototype.setter}) {
            if (*accessor)
                (*accessor)->body.reset();
        }
        pugi::xml_node entry = own.append_child("data");
        entry.append_attribute("name").set_value(prototype.property ? kProperty : kMethod);
        entry.append_attribute("handleUnknown").set_value("implementation");
        insertMember(entry, {}, prototype);
    }
}

} // namespace

AddData addDataWithMember(const AddData &addData, const QString &name, const CodesysMemberDefinition &member)
{
    AddData result = addData;
    const bool replaced = !name.isEmpty() && editMemberEntry(result, name, [&](AddDataEntry &e, pugi::xml_node root, pugi::xml_node old) {
        insertMember(root, old, member);
        root.remove_child(old);
        e.content = contentOf(root);
        e.name = QLatin1String(member.property ? kProperty : kMethod);
    });
    if (replaced)
        return result;
    pugi::xml_document document;
    const pugi::xml_node root = document.append_child("r");
    insertMember(root, {}, member);
    result.push_back({QLatin1String(member.property ? kProperty : kMethod), QStringLiteral("implementation"), contentOf(root)});
    return result;
}

AddData addDataWithoutMember(const AddData &addData, const QString &name)
{
    return withoutNamedElement(addData, name, isMemberEntry, isMemberNode);
}

AddData addDataWithInheritance(const AddData &addData, const QString &extends, const QStringList &implements)
{
    AddData result = addData;
    std::erase_if(result, [](const AddDataEntry &e) { return e.name == QLatin1String(kInheritance); });
    if (extends.isEmpty() && implements.isEmpty())
        return result;
    pugi::xml_document document;
    pugi::xml_node inheritance = document.append_child("Inheritance");
    if (!extends.isEmpty())
        appendText(inheritance.append_child("Extends"), extends);
    for (const QString &name : implements)
        appendText(inheritance.append_child("Implements"), name);
    result.push_back({QLatin1String(kInheritance), QStringLiteral("implementation"), rawXml(inheritance)});
    return result;
}

AddData addDataWithInterface(const AddData &addData, const QString &replacing, const CodesysInterfaceDefinition &definition)
{
    AddData result = addData;
    const auto build = [&](pugi::xml_node parent, pugi::xml_node before) {
        pugi::xml_node itf = before ? parent.insert_child_before("Interface", before) : parent.append_child("Interface");
        itf.append_attribute("name").set_value(toFileUtf8(definition.name).constData());
        for (pugi::xml_attribute a = before.first_attribute(); a; a = a.next_attribute()) {
            if (std::strcmp(a.name(), "name") != 0)
                itf.append_attribute(a.name()).set_value(a.value()); // ObjectId and what else CODESYS wrote
        }
        appendInterfaceContent(itf, definition);
    };
    const bool replaced = !replacing.isEmpty()
        && editInterfaceEntry(result, replacing, [&](AddDataEntry &e, pugi::xml_node root, pugi::xml_node old) {
               build(root, old);
               root.remove_child(old);
               e.content = contentOf(root);
           });
    if (replaced)
        return result;
    pugi::xml_document document;
    const pugi::xml_node root = document.append_child("r");
    build(root, {});
    result.push_back({QLatin1String(kInterface), QStringLiteral("implementation"), contentOf(root)});
    return result;
}

AddData addDataWithoutInterface(const AddData &addData, const QString &name)
{
    return withoutNamedElement(addData, name, isInterfaceEntry, isInterfaceNode);
}

bool keepsInterface(const AddData &addData, const QString &name)
{
    return editNamedElement(addData, name, isInterfaceEntry, isInterfaceNode, [](const AddDataEntry &, pugi::xml_node, pugi::xml_node) { });
}

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
