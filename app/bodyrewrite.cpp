#include "app/bodyrewrite.h"

#include "model/projectmodel.h"
#include "model/undo/elementcommands.h"
#include "model/undo/poucommands.h"

#include <QUndoCommand>

#include <algorithm>

namespace iec::app {

using model::BodyRef;

namespace {

bool sameName(QStringView a, QStringView b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

TextDialect dialectOf(const model::Body &body)
{
    return body.language() == model::BodyLanguage::IL ? TextDialect::IL : TextDialect::ST;
}

bool rewriteBodyValue(model::Body &body, const BodyRewrite &rewrite);

bool rewriteText(QString &text, const BodyRewrite &rewrite)
{
    if (!rewrite.text || !rewrite.inGraphics)
        return false;
    const QString renamed = rewrite.text(text, TextDialect::ST);
    if (renamed == text)
        return false;
    text = renamed;
    return true;
}

bool rewriteText(std::optional<QString> &text, const BodyRewrite &rewrite)
{
    return text && rewriteText(*text, rewrite);
}

bool rewriteInline(std::optional<model::Box<model::Body>> &body, const BodyRewrite &rewrite)
{
    return body && rewrite.inGraphics && rewriteBodyValue(**body, rewrite);
}

bool rewriteElement(model::Element &element, const std::vector<model::Element> &siblings, const BodyRewrite &rewrite)
{
    bool changed = false;
    if (auto *in = std::get_if<model::InVariable>(&element))
        changed |= rewriteText(in->expression, rewrite);
    else if (auto *out = std::get_if<model::OutVariable>(&element))
        changed |= rewriteText(out->expression, rewrite);
    else if (auto *inOut = std::get_if<model::InOutVariable>(&element))
        changed |= rewriteText(inOut->expression, rewrite);
    else if (auto *contact = std::get_if<model::Contact>(&element))
        changed |= rewriteText(contact->variable, rewrite);
    else if (auto *coil = std::get_if<model::Coil>(&element))
        changed |= rewriteText(coil->variable, rewrite);
    else if (auto *macro = std::get_if<model::MacroStep>(&element))
        changed |= rewriteInline(macro->body, rewrite);
    if (auto *block = std::get_if<model::ActionBlock>(&element)) {
        for (model::ActionBlockAction &action : block->actions) {
            changed |= rewriteText(action.indicator, rewrite);
            changed |= rewriteInline(action.inlineBody, rewrite);
        }
    }
    if (auto *transition = std::get_if<model::Transition>(&element); transition && transition->condition) {
        if (auto *inlined = std::get_if<model::InlineCondition>(&transition->condition->kind); inlined && rewrite.inGraphics)
            changed |= rewriteBodyValue(*inlined->body, rewrite);
    }
    for (model::ConnectionPointIn *point : model::inputPoints(element))
        changed |= rewriteText(point->expression, rewrite);
    if (rewrite.element)
        changed |= rewrite.element(element, siblings);
    return changed;
}

bool rewriteBodyValue(model::Body &body, const BodyRewrite &rewrite)
{
    if (std::vector<model::Element> *elements = body.elements()) {
        const std::vector<model::Element> siblings = *elements;
        bool changed = false;
        for (model::Element &element : *elements)
            changed |= rewriteElement(element, siblings, rewrite);
        return changed;
    }
    if (!rewrite.text)
        return false;
    const QString text = body.text();
    const QString renamed = rewrite.text(text, dialectOf(body));
    if (renamed == text)
        return false;
    body.setText(renamed);
    return true;
}

// One command per changed element or text body, under `parent`.
void addBodyRewrite(model::ProjectModel &model, const BodyRef &ref, const model::Body &body,
    const BodyRewrite &rewrite, QUndoCommand *parent)
{
    if (const std::vector<model::Element> *elements = body.elements()) {
        for (const model::Element &element : *elements) {
            model::Element changed = element;
            if (rewriteElement(changed, *elements, rewrite))
                new model::ChangeElementCommand(model, ref, std::move(changed), parent);
        }
        return;
    }
    if (!rewrite.text)
        return;
    const QString text = body.text();
    if (const QString renamed = rewrite.text(text, dialectOf(body)); renamed != text)
        new model::SetBodyTextCommand(model, ref, renamed, parent);
}

} // namespace

void addPouRewrite(model::ProjectModel &model, const model::Pou &pou, const BodyRewrite &rewrite,
    QUndoCommand *parent, const std::optional<BodyRef> &skip)
{
    const auto visit = [&](const BodyRef &ref, const model::Body &body) {
        if (!(skip && skip->part == ref.part && sameName(skip->name, ref.name)))
            addBodyRewrite(model, ref, body, rewrite, parent);
    };
    if (const model::Body *body = pou.body())
        visit({pou.id, BodyRef::Part::Pou, {}}, *body);
    for (const model::PouPart &action : pou.actions)
        visit({pou.id, BodyRef::Part::Action, action.name}, action.body);
    for (const model::PouPart &transition : pou.transitions)
        visit({pou.id, BodyRef::Part::Transition, transition.name}, transition.body);
}

BodyRewrite composed(std::vector<BodyRewrite> rewrites)
{
    BodyRewrite result;
    result.inGraphics = std::ranges::any_of(rewrites, &BodyRewrite::inGraphics);
    result.text = [rewrites](const QString &text, TextDialect dialect) {
        QString out = text;
        for (const BodyRewrite &rewrite : rewrites) {
            if (rewrite.text)
                out = rewrite.text(out, dialect);
        }
        return out;
    };
    result.element = [rewrites](model::Element &element, const std::vector<model::Element> &siblings) {
        bool changed = false;
        for (const BodyRewrite &rewrite : rewrites) {
            if (rewrite.element)
                changed |= rewrite.element(element, siblings);
        }
        return changed;
    };
    return result;
}

} // namespace iec::app
