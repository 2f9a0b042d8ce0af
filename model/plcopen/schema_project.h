#pragma once

// Schema of the project level: headers, data types, POUs and instances.

#include "model/plcopen/schema_elements.h"

namespace iec::model::plcopen {

// The element names of the var lists of a POU interface.
inline constexpr std::array<std::pair<VarListKind, const char *>, 8> kVarListTags {{
    {VarListKind::Local, "localVars"},
    {VarListKind::Temp, "tempVars"},
    {VarListKind::Input, "inputVars"},
    {VarListKind::Output, "outputVars"},
    {VarListKind::InOut, "inOutVars"},
    {VarListKind::External, "externalVars"},
    {VarListKind::Global, "globalVars"},
    {VarListKind::Access, "accessVars"},
}};

const char *varListTag(VarListKind kind);

template<> struct Schema<Interface> {
    template<class A, class V> static void describe(A &a, V &declarations)
    {
        a.child("returnType", declarations.returnType);
        if constexpr (A::reading) {
            // The var lists come in any order and number; keep the file's order.
            for (const auto &[kind, tag] : kVarListTags)
                a.markKnown(tag);
            for (pugi::xml_node node = a.node().first_child(); node; node = node.next_sibling()) {
                for (const auto &[kind, tag] : kVarListTags) {
                    if (node.type() == pugi::node_element && hasLocalName(node, tag)) {
                        VarList &list = declarations.varLists.emplace_back();
                        a.read(node, list);
                        list.kind = kind;
                    }
                }
            }
        } else {
            for (const VarList &list : declarations.varLists)
                a.child(varListTag(list.kind), list);
        }
        a.addData(declarations.addData);
        a.child("documentation", declarations.documentation);
        a.finish(declarations.extras);
    }
};

// POU actions and transitions have the same shape.
template<> struct Schema<PouPart> {
    template<class A, class V> static void describe(A &a, V &part)
    {
        a.attr("name", part.name);
        a.attr("globalId", part.globalId);
        a.child("body", part.body);
        a.addData(part.addData);
        a.child("documentation", part.documentation);
        a.finish(part.extras);
    }
};

template<> struct Schema<Pou> {
    template<class A, class V> static void describe(A &a, V &pou)
    {
        a.attr("name", pou.name);
        a.attr("pouType", pou.kind);
        a.attr("globalId", pou.globalId);
        std::optional<QString> outerPou;
        if constexpr (A::reading) {
            outerPou = a.context().pouName;
            a.context().pouName = pou.name;
        }
        a.child("interface", pou.pouInterface);
        a.containerList("actions", "action", pou.actions);
        a.containerList("transitions", "transition", pou.transitions);
        a.children("body", pou.bodies);
        a.addData(pou.addData);
        a.child("documentation", pou.documentation);
        a.finish(pou.extras);
        if constexpr (A::reading)
            a.context().pouName = outerPou;
    }
};

template<> struct Schema<DataTypeDecl> {
    template<class A, class V> static void describe(A &a, V &type)
    {
        a.attr("name", type.name);
        a.child("baseType", type.baseType);
        a.child("initialValue", type.initialValue);
        a.addData(type.addData);
        a.child("documentation", type.documentation);
        a.finish(type.extras);
    }
};

template<> struct Schema<PouInstance> {
    template<class A, class V> static void describe(A &a, V &instance)
    {
        a.attr("name", instance.name);
        a.attr("typeName", instance.typeName);
        a.attr("globalId", instance.globalId);
        a.addData(instance.addData);
        a.child("documentation", instance.documentation);
        a.finish(instance.extras);
    }
};

template<> struct Schema<Task> {
    template<class A, class V> static void describe(A &a, V &task)
    {
        a.attr("name", task.name);
        a.attr("single", task.single);
        a.attr("interval", task.interval);
        a.attr("priority", task.priority);
        a.attr("globalId", task.globalId);
        a.children("pouInstance", task.pouInstances);
        a.addData(task.addData);
        a.child("documentation", task.documentation);
        a.finish(task.extras);
    }
};

// Var lists outside a POU interface are global var lists.
template<class A, class V> void describeGlobalVars(A &a, V &lists)
{
    a.children("globalVars", lists);
    if constexpr (A::reading) {
        for (VarList &list : lists)
            list.kind = VarListKind::Global;
    }
}

template<> struct Schema<Resource> {
    template<class A, class V> static void describe(A &a, V &resource)
    {
        a.attr("name", resource.name);
        a.attr("globalId", resource.globalId);
        a.children("task", resource.tasks);
        describeGlobalVars(a, resource.globalVars);
        a.children("pouInstance", resource.pouInstances);
        a.addData(resource.addData);
        a.child("documentation", resource.documentation);
        a.finish(resource.extras);
    }
};

template<> struct Schema<Configuration> {
    template<class A, class V> static void describe(A &a, V &configuration)
    {
        a.attr("name", configuration.name);
        a.attr("globalId", configuration.globalId);
        a.children("resource", configuration.resources);
        describeGlobalVars(a, configuration.globalVars);
        a.child("accessVars", configuration.accessVars);
        a.child("configVars", configuration.configVars);
        a.addData(configuration.addData);
        a.child("documentation", configuration.documentation);
        a.finish(configuration.extras);
    }
};

template<> struct Schema<FileHeader> {
    template<class A, class V> static void describe(A &a, V &header)
    {
        a.attr("companyName", header.companyName);
        a.attr("companyURL", header.companyURL);
        a.attr("productName", header.productName);
        a.attr("productVersion", header.productVersion);
        a.attr("productRelease", header.productRelease);
        a.attr("creationDateTime", header.creationDateTime);
        a.attr("contentDescription", header.contentDescription);
        a.finish(header.extras);
    }
};

template<> struct Schema<AddDataInfo> {
    template<class A, class V> static void describe(A &a, V &info)
    {
        a.attr("name", info.name);
        a.attr("version", info.version);
        a.attr("vendor", info.vendor);
        a.child("description", info.description);
    }
};

template<> struct Schema<CoordinateInfo> {
    template<class A, class V> static void describe(A &a, V &info)
    {
        a.child("pageSize", info.pageSize);
        a.nested("fbd", "scaling", info.fbd);
        a.nested("ld", "scaling", info.ld);
        a.nested("sfc", "scaling", info.sfc);
    }
};

template<> struct Schema<ContentHeader> {
    template<class A, class V> static void describe(A &a, V &header)
    {
        a.attr("name", header.name);
        a.attr("version", header.version);
        a.attr("modificationDateTime", header.modificationDateTime);
        a.attr("organization", header.organization);
        a.attr("author", header.author);
        a.attr("language", header.language);
        a.text("Comment", header.comment);
        a.child("coordinateInfo", header.coordinateInfo);
        a.children("addDataInfo", "info", header.addDataInfo);
        a.addData(header.addData);
        a.finish(header.extras);
    }
};

template<> struct Schema<Types> {
    template<class A, class V> static void describe(A &a, V &types)
    {
        if constexpr (A::reading) {
            a.containerList("dataTypes", "dataType", types.dataTypes);
            a.containerList("pous", "pou", types.pous);
        } else {
            // POUs and data types that came from a vendor addData entry are written there (writer.cpp
            // appends any whose entry is gone).
            XmlOut dataTypes(a.node().append_child("dataTypes"), a.context());
            for (const DataTypeDecl &type : types.dataTypes) {
                if (type.addDataSlot == 0)
                    dataTypes.child("dataType", type);
            }
            XmlOut pous(a.node().append_child("pous"), a.context());
            for (const Pou &pou : types.pous) {
                if (pou.addDataSlot == 0)
                    pous.child("pou", pou);
            }
        }
    }
};

template<> struct Schema<Instances> {
    template<class A, class V> static void describe(A &a, V &instances)
    {
        a.containerList("configurations", "configuration", instances.configurations, true);
    }
};

template<> struct Schema<Project> {
    template<class A, class V> static void describe(A &a, V &project)
    {
        a.child("fileHeader", project.fileHeader);
        a.child("contentHeader", project.contentHeader);
        a.child("types", project.types);
        a.child("instances", project.instances);
        a.addData(project.addData);
        a.child("documentation", project.documentation);
        a.finish(project.extras);
    }
};

} // namespace iec::model::plcopen
