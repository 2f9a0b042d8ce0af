#include "model/plcopen/repair.h"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace iec::model::plcopen {

namespace {

quint64 largestLocalId(pugi::xml_node root)
{
    quint64 largest = 0;
    walkDescendants(root, [&](pugi::xml_node node) {
        if (node.type() != pugi::node_element)
            return false;
        if (const pugi::xml_attribute id = node.attribute("localId"))
            largest = std::max<quint64>(largest, std::strtoull(id.value(), nullptr, 10));
        return true;
    });
    return largest;
}

// nextId: 0 until a fresh localId is first needed (most files need none, so the whole document
// is not searched for the largest one).
void repairAction(pugi::xml_node action, pugi::xml_node root, quint64 &nextId, ReadContext &context)
{
    if (!action.attribute("localId")) {
        if (nextId == 0)
            nextId = largestLocalId(root);
        const quint64 id = ++nextId;
        action.append_attribute("localId").set_value(std::to_string(id).c_str());
        context.report(Diagnostic::Severity::Warning, action,
            QCoreApplication::translate("iec::model::plcopen::Reader", "This <action> has no localId; it was given %1.").arg(id), id);
    }
    bool placed = false;
    for (pugi::xml_node child = action.first_child(); child && !placed; child = child.next_sibling())
        placed = child.type() == pugi::node_element && hasLocalName(child, "relPosition");
    if (!placed) {
        // The XSD puts relPosition before reference/inline.
        pugi::xml_node position = action.prepend_child("relPosition");
        position.append_attribute("x").set_value("0");
        position.append_attribute("y").set_value("0");
        context.report(Diagnostic::Severity::Warning, action, QCoreApplication::translate("iec::model::plcopen::Reader", "This <action> has no position; it is placed at (0, 0)."));
    }
}

void repairPouInstance(pugi::xml_node instance, ReadContext &context)
{
    const pugi::xml_attribute type = instance.attribute("type");
    if (!type || instance.attribute("typeName"))
        return;
    instance.append_attribute("typeName").set_value(type.value());
    instance.remove_attribute(type);
    context.report(Diagnostic::Severity::Warning, instance,
        QCoreApplication::translate("iec::model::plcopen::Reader", "<pouInstance> names its POU with 'type'; PLCopen calls it 'typeName', which it is written as."));
}

void repairDateTime(pugi::xml_node header, ReadContext &context)
{
    pugi::xml_attribute created = header.attribute("creationDateTime");
    const std::string value = created.value();
    const auto space = value.find(' ');
    if (!created || space != 10) // 2024-01-31 12:00:00
        return;
    std::string mended = value;
    mended[space] = 'T';
    created.set_value(mended.c_str());
    context.report(Diagnostic::Severity::Warning, header,
        QCoreApplication::translate("iec::model::plcopen::Reader", "creationDateTime '%1' has a space where XML wants a 'T'; it is written as '%2'.")
            .arg(QString::fromStdString(value), QString::fromStdString(mended)));
}

} // namespace

void repairOldForms(pugi::xml_node root, ReadContext &context)
{
    quint64 nextId = 0;
    walkDescendants(root, [&](pugi::xml_node node) {
        if (node.type() != pugi::node_element)
            return false;
        if (hasLocalName(node, "action") && hasLocalName(node.parent(), "actionBlock"))
            repairAction(node, root, nextId, context);
        else if (hasLocalName(node, "pouInstance"))
            repairPouInstance(node, context);
        else if (hasLocalName(node, "fileHeader"))
            repairDateTime(node, context);
        return !hasLocalName(node, "addData"); // vendor content is kept as written
    });
}

} // namespace iec::model::plcopen
