#pragma once

// Schema of the graphical elements (common, FBD, LD and SFC objects of the XSD) and of bodies.

#include "model/plcopen/schema_base.h"

namespace iec::model::plcopen {

// The attributes every element has, then its <position>.
template<class A, class V> void describeElementStart(A &a, V &element)
{
    a.attr("localId", element.localId);
    a.attr("width", element.width);
    a.attr("height", element.height);
    a.attr("executionOrderId", element.executionOrderId);
    a.attr("globalId", element.globalId);
    a.child("position", element.position);
}

// The children every element ends with, then whatever was unknown.
template<class A, class V> void describeElementEnd(A &a, V &element, bool addDataRequired = false)
{
    a.addData(element.addData, addDataRequired);
    a.child("documentation", element.documentation);
    a.finish(element.extras);
}

// The negated/edge/storage modifiers of variables, coils and contacts.
template<class A, class V> void describeModifiers(A &a, V &element)
{
    a.attr("negated", element.negated, false);
    a.attr("edge", element.edge, EdgeModifier::None);
    a.attr("storage", element.storage, StorageModifier::None);
}

// ---- common objects -----------------------------------------------------------------------

template<> struct Schema<Comment> {
    static constexpr const char *tag = "comment";
    template<class A, class V> static void describe(A &a, V &comment)
    {
        describeElementStart(a, comment);
        a.child("content", comment.content);
        describeElementEnd(a, comment);
    }
};

template<> struct Schema<Error> {
    static constexpr const char *tag = "error";
    template<class A, class V> static void describe(A &a, V &error)
    {
        describeElementStart(a, error);
        a.child("content", error.content);
        describeElementEnd(a, error);
    }
};

template<> struct Schema<Connector> {
    static constexpr const char *tag = "connector";
    template<class A, class V> static void describe(A &a, V &connector)
    {
        a.attr("name", connector.name);
        describeElementStart(a, connector);
        a.child("connectionPointIn", connector.connectionPointIn);
        describeElementEnd(a, connector);
    }
};

template<> struct Schema<Continuation> {
    static constexpr const char *tag = "continuation";
    template<class A, class V> static void describe(A &a, V &continuation)
    {
        a.attr("name", continuation.name);
        describeElementStart(a, continuation);
        a.child("connectionPointOut", continuation.connectionPointOut);
        describeElementEnd(a, continuation);
    }
};

template<> struct Schema<Reference> {
    static constexpr const char *tag = "reference";
    template<class A, class V> static void describe(A &a, V &reference) { a.attr("name", reference.name); }
};

template<> struct Schema<Body> {
    template<class A, class V> static void describe(A &a, V &body);
};

template<> struct Schema<ActionBlockAction> {
    template<class A, class V> static void describe(A &a, V &action)
    {
        a.attr("localId", action.localId);
        a.attr("qualifier", action.qualifier);
        a.attr("width", action.width);
        a.attr("height", action.height);
        a.attr("duration", action.duration);
        a.attr("indicator", action.indicator);
        a.attr("executionOrderId", action.executionOrderId);
        a.attr("globalId", action.globalId);
        a.child("relPosition", action.relPosition);
        a.child("reference", action.reference);
        a.child("inline", action.inlineBody);
        a.child("connectionPointOut", action.connectionPointOut);
        a.addData(action.addData);
        a.child("documentation", action.documentation);
        a.finish(action.extras);
    }
};

template<> struct Schema<ActionBlock> {
    static constexpr const char *tag = "actionBlock";
    template<class A, class V> static void describe(A &a, V &block)
    {
        describeElementStart(a, block);
        a.attr("negated", block.negated, false);
        a.child("connectionPointIn", block.connectionPointIn);
        a.children("action", block.actions);
        describeElementEnd(a, block);
    }
};

template<> struct Schema<BlockVariable> {
    template<class A, class V> static void describe(A &a, V &variable)
    {
        a.attr("formalParameter", variable.formalParameter);
        describeModifiers(a, variable);
        a.attr("hidden", variable.hidden, false);
        a.child("connectionPointIn", variable.connectionPointIn);
        a.child("connectionPointOut", variable.connectionPointOut);
        a.child("documentation", variable.documentation);
        a.finish(variable.extras);
    }
};

template<> struct Schema<VendorElement> {
    static constexpr const char *tag = "vendorElement";
    template<class A, class V> static void describe(A &a, V &element)
    {
        describeElementStart(a, element);
        a.child("alternativeText", element.alternativeText);
        a.children("inputVariables", "variable", element.inputVariables);
        a.children("inOutVariables", "variable", element.inOutVariables);
        a.children("outputVariables", "variable", element.outputVariables);
        describeElementEnd(a, element, true);
    }
};

// ---- FBD objects --------------------------------------------------------------------------

template<> struct Schema<Block> {
    static constexpr const char *tag = "block";
    template<class A, class V> static void describe(A &a, V &block)
    {
        describeElementStart(a, block);
        a.attr("typeName", block.typeName);
        a.attr("instanceName", block.instanceName);
        a.containerList("inputVariables", "variable", block.inputVariables, true);
        a.containerList("inOutVariables", "variable", block.inOutVariables, true);
        a.containerList("outputVariables", "variable", block.outputVariables, true);
        describeElementEnd(a, block);
    }
};

template<> struct Schema<InVariable> {
    static constexpr const char *tag = "inVariable";
    template<class A, class V> static void describe(A &a, V &variable)
    {
        describeElementStart(a, variable);
        describeModifiers(a, variable);
        a.child("connectionPointOut", variable.connectionPointOut);
        a.text("expression", variable.expression);
        describeElementEnd(a, variable);
    }
};

template<> struct Schema<OutVariable> {
    static constexpr const char *tag = "outVariable";
    template<class A, class V> static void describe(A &a, V &variable)
    {
        describeElementStart(a, variable);
        describeModifiers(a, variable);
        a.child("connectionPointIn", variable.connectionPointIn);
        a.text("expression", variable.expression);
        describeElementEnd(a, variable);
    }
};

template<> struct Schema<InOutVariable> {
    static constexpr const char *tag = "inOutVariable";
    template<class A, class V> static void describe(A &a, V &variable)
    {
        describeElementStart(a, variable);
        a.attr("negatedIn", variable.negatedIn, false);
        a.attr("edgeIn", variable.edgeIn, EdgeModifier::None);
        a.attr("storageIn", variable.storageIn, StorageModifier::None);
        a.attr("negatedOut", variable.negatedOut, false);
        a.attr("edgeOut", variable.edgeOut, EdgeModifier::None);
        a.attr("storageOut", variable.storageOut, StorageModifier::None);
        a.child("connectionPointIn", variable.connectionPointIn);
        a.child("connectionPointOut", variable.connectionPointOut);
        a.text("expression", variable.expression);
        describeElementEnd(a, variable);
    }
};

template<> struct Schema<Label> {
    static constexpr const char *tag = "label";
    template<class A, class V> static void describe(A &a, V &label)
    {
        describeElementStart(a, label);
        a.attr("label", label.label);
        describeElementEnd(a, label);
    }
};

template<> struct Schema<Jump> {
    static constexpr const char *tag = "jump";
    template<class A, class V> static void describe(A &a, V &jump)
    {
        describeElementStart(a, jump);
        a.attr("label", jump.label);
        a.child("connectionPointIn", jump.connectionPointIn);
        describeElementEnd(a, jump);
    }
};

template<> struct Schema<Return> {
    static constexpr const char *tag = "return";
    template<class A, class V> static void describe(A &a, V &element)
    {
        describeElementStart(a, element);
        a.child("connectionPointIn", element.connectionPointIn);
        describeElementEnd(a, element);
    }
};

// ---- LD objects ---------------------------------------------------------------------------

// Outputs whose formalParameter the XSD requires (left power rails, steps, divergences): a model
// without a name writes formalParameter="" (as Beremiz does) and reads "" back as no name, so a
// chart drawn in the editor saves valid and reloads equal, and a file with "" saves unchanged.
template<class A, class P> void namedOutput(A &a, const char *name, P &point)
{
    if constexpr (A::reading) {
        a.child(name, point);
        if (point && point->formalParameter && point->formalParameter->isEmpty())
            point->formalParameter.reset();
    } else if (point) {
        ConnectionPointOut named = *point;
        named.formalParameter = named.formalParameter.value_or(QString());
        a.child(name, std::optional<ConnectionPointOut>(std::move(named)));
    }
}

template<class A, class V> void namedOutputs(A &a, const char *name, V &points)
{
    if constexpr (A::reading) {
        a.children(name, points);
        for (ConnectionPointOut &point : points) {
            if (point.formalParameter && point.formalParameter->isEmpty())
                point.formalParameter.reset();
        }
    } else {
        std::vector<ConnectionPointOut> named = points;
        for (ConnectionPointOut &point : named)
            point.formalParameter = point.formalParameter.value_or(QString());
        a.children(name, named);
    }
}

template<> struct Schema<LeftPowerRail> {
    static constexpr const char *tag = "leftPowerRail";
    template<class A, class V> static void describe(A &a, V &rail)
    {
        describeElementStart(a, rail);
        namedOutputs(a, "connectionPointOut", rail.connectionPointOuts);
        describeElementEnd(a, rail);
    }
};

template<> struct Schema<RightPowerRail> {
    static constexpr const char *tag = "rightPowerRail";
    template<class A, class V> static void describe(A &a, V &rail)
    {
        describeElementStart(a, rail);
        a.children("connectionPointIn", rail.connectionPointIns);
        describeElementEnd(a, rail);
    }
};

// Coils and contacts have the same shape.
template<class A, class V> void describeLdVariable(A &a, V &element)
{
    describeElementStart(a, element);
    describeModifiers(a, element);
    a.child("connectionPointIn", element.connectionPointIn);
    a.child("connectionPointOut", element.connectionPointOut);
    a.text("variable", element.variable);
    describeElementEnd(a, element);
}

template<> struct Schema<Coil> {
    static constexpr const char *tag = "coil";
    template<class A, class V> static void describe(A &a, V &coil) { describeLdVariable(a, coil); }
};

template<> struct Schema<Contact> {
    static constexpr const char *tag = "contact";
    template<class A, class V> static void describe(A &a, V &contact) { describeLdVariable(a, contact); }
};

// ---- SFC objects --------------------------------------------------------------------------

template<> struct Schema<Step> {
    static constexpr const char *tag = "step";
    template<class A, class V> static void describe(A &a, V &step)
    {
        describeElementStart(a, step);
        a.attr("name", step.name);
        a.attr("initialStep", step.initialStep, false);
        a.attr("negated", step.negated, false);
        a.child("connectionPointIn", step.connectionPointIn);
        namedOutput(a, "connectionPointOut", step.connectionPointOut);
        namedOutput(a, "connectionPointOutAction", step.connectionPointOutAction);
        describeElementEnd(a, step);
    }
};

template<> struct Schema<MacroStep> {
    static constexpr const char *tag = "macroStep";
    template<class A, class V> static void describe(A &a, V &step)
    {
        describeElementStart(a, step);
        a.attr("name", step.name);
        a.child("connectionPointIn", step.connectionPointIn);
        a.child("connectionPointOut", step.connectionPointOut);
        a.child("body", step.body);
        describeElementEnd(a, step);
    }
};

template<> struct Schema<JumpStep> {
    static constexpr const char *tag = "jumpStep";
    template<class A, class V> static void describe(A &a, V &step)
    {
        describeElementStart(a, step);
        a.attr("targetName", step.targetName);
        a.child("connectionPointIn", step.connectionPointIn);
        describeElementEnd(a, step);
    }
};

template<> struct Schema<InlineCondition> {
    static constexpr const char *tag = "inline";
    template<class A, class V> static void describe(A &a, V &condition)
    {
        a.attr("name", condition.name);
        Schema<Body>::describe(a, *condition.body);
    }
};

template<> struct Schema<Condition> {
    template<class A, class V> static void describe(A &a, V &condition)
    {
        a.attr("negated", condition.negated, false);
        a.choice(condition.kind, "reference");
    }
};

template<> struct Schema<Transition> {
    static constexpr const char *tag = "transition";
    template<class A, class V> static void describe(A &a, V &transition)
    {
        describeElementStart(a, transition);
        a.attr("priority", transition.priority);
        a.child("connectionPointIn", transition.connectionPointIn);
        a.child("connectionPointOut", transition.connectionPointOut);
        a.child("condition", transition.condition);
        describeElementEnd(a, transition);
    }
};

// Divergences: one input, several outputs; convergences: several inputs, one output.
template<class A, class V> void describeDivergence(A &a, V &divergence)
{
    describeElementStart(a, divergence);
    a.child("connectionPointIn", divergence.connectionPointIn);
    namedOutputs(a, "connectionPointOut", divergence.connectionPointOuts);
    describeElementEnd(a, divergence);
}

template<class A, class V> void describeConvergence(A &a, V &convergence)
{
    describeElementStart(a, convergence);
    a.children("connectionPointIn", convergence.connectionPointIns);
    a.child("connectionPointOut", convergence.connectionPointOut);
    describeElementEnd(a, convergence);
}

template<> struct Schema<SelectionDivergence> {
    static constexpr const char *tag = "selectionDivergence";
    template<class A, class V> static void describe(A &a, V &divergence) { describeDivergence(a, divergence); }
};

template<> struct Schema<SelectionConvergence> {
    static constexpr const char *tag = "selectionConvergence";
    template<class A, class V> static void describe(A &a, V &convergence) { describeConvergence(a, convergence); }
};

template<> struct Schema<SimultaneousDivergence> {
    static constexpr const char *tag = "simultaneousDivergence";
    template<class A, class V> static void describe(A &a, V &divergence)
    {
        a.attr("name", divergence.name);
        describeDivergence(a, divergence);
    }
};

template<> struct Schema<SimultaneousConvergence> {
    static constexpr const char *tag = "simultaneousConvergence";
    template<class A, class V> static void describe(A &a, V &convergence) { describeConvergence(a, convergence); }
};

// ---- bodies -------------------------------------------------------------------------------

template<class A, class V> void describeProgramText(A &a, V &body)
{
    if constexpr (A::reading) {
        FormattedText text;
        readFormattedText(a.node(), text);
        body.text = text.text;
    } else {
        writeProgramText(a.node(), body.text);
    }
    a.skipRest();
}

template<> struct Schema<StBody> {
    static constexpr const char *tag = "ST";
    template<class A, class V> static void describe(A &a, V &body) { describeProgramText(a, body); }
};

template<> struct Schema<IlBody> {
    static constexpr const char *tag = "IL";
    template<class A, class V> static void describe(A &a, V &body) { describeProgramText(a, body); }
};

template<class A, class V> void describeGraphicalBody(A &a, V &body)
{
    a.choiceList(body.elements);
    a.finish(body.extras);
}

template<> struct Schema<LdBody> {
    static constexpr const char *tag = "LD";
    template<class A, class V> static void describe(A &a, V &body) { describeGraphicalBody(a, body); }
};

template<> struct Schema<FbdBody> {
    static constexpr const char *tag = "FBD";
    template<class A, class V> static void describe(A &a, V &body) { describeGraphicalBody(a, body); }
};

template<> struct Schema<SfcBody> {
    static constexpr const char *tag = "SFC";
    template<class A, class V> static void describe(A &a, V &body) { describeGraphicalBody(a, body); }
};

// The layout flag travels in our own addData entry; in the model it is Body::layoutGenerated.
bool takeLayoutEntry(AddData &entries);
AddData withLayoutEntry(const AddData &entries);

template<class A, class V> void Schema<Body>::describe(A &a, V &body)
{
    a.attr("WorksheetName", body.worksheetName);
    a.attr("globalId", body.globalId);
    a.choice(body.content, "ST");
    if constexpr (A::reading) {
        a.addData(body.addData);
        body.layoutGenerated = takeLayoutEntry(body.addData);
    } else {
        a.addData(body.layoutGenerated ? withLayoutEntry(body.addData) : body.addData);
    }
    a.child("documentation", body.documentation);
    a.finish(body.extras);
}

} // namespace iec::model::plcopen
