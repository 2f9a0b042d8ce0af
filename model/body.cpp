#include "model/body.h"

namespace iec::model {

namespace {

template<class Elements, class B> Elements *elementsOf(B &body)
{
    return std::visit(
        [](auto &content) -> Elements * {
            if constexpr (requires { content.elements; })
                return &content.elements;
            else
                return nullptr;
        },
        body.content);
}

} // namespace

const std::vector<Element> *Body::elements() const
{
    return elementsOf<const std::vector<Element>>(*this);
}

std::vector<Element> *Body::elements()
{
    return elementsOf<std::vector<Element>>(*this);
}

QString Body::text() const
{
    if (const auto *st = std::get_if<StBody>(&content))
        return st->text;
    if (const auto *il = std::get_if<IlBody>(&content))
        return il->text;
    return {};
}

void Body::setText(const QString &text)
{
    if (auto *st = std::get_if<StBody>(&content))
        st->text = text;
    else if (auto *il = std::get_if<IlBody>(&content))
        il->text = text;
}

Body Body::withLanguage(BodyLanguage language)
{
    Body body;
    switch (language) {
    case BodyLanguage::ST:
        body.content = StBody {};
        break;
    case BodyLanguage::IL:
        body.content = IlBody {};
        break;
    case BodyLanguage::LD:
        body.content = LdBody {};
        break;
    case BodyLanguage::FBD:
        body.content = FbdBody {};
        break;
    case BodyLanguage::SFC:
        body.content = SfcBody {};
        break;
    }
    return body;
}

} // namespace iec::model
