#include "editors/common/editorregistry.h"

#include "model/body.h"

namespace iec::editors {

EditorRegistry &EditorRegistry::instance()
{
    static EditorRegistry registry;
    return registry;
}

void EditorRegistry::add(EditorFactory factory)
{
    m_factories[factory.language] = std::move(factory);
}

const EditorFactory *EditorRegistry::find(EditorLanguage language) const
{
    const auto it = m_factories.find(language);
    return it == m_factories.end() ? nullptr : &it->second;
}

const EditorFactory *EditorRegistry::forBody(const model::Body &body) const
{
    return find(editorLanguage(body));
}

std::vector<EditorLanguage> EditorRegistry::languages() const
{
    std::vector<EditorLanguage> result;
    for (const auto &[language, factory] : m_factories)
        result.push_back(language);
    return result;
}

} // namespace iec::editors
