#pragma once

#include "editors/common/editorlanguage.h"
#include "model/ids.h"

#include <functional>
#include <map>
#include <memory>
#include <vector>

class QUndoStack;

namespace iec::model {
class ProjectModel;
struct Body;
}

namespace iec::editors {

class DiagramEditor;
class DiagramPolicy;

// How the app gets the editor of a graphical language, without knowing any editor by name
// (DESIGN.md): the document area opens bodies through it, the window's Insert menu takes the
// current editor's insertActions(), the online controller asks the editor (OnlineView) whether it
// wants chart state, and `iecstudio-cli render` draws a body through createPolicy.
struct EditorFactory {
    EditorLanguage language = EditorLanguage::SFC;
    // The editor widget of one body; its commands go on `undoStack`.
    std::function<DiagramEditor *(model::ProjectModel &model, const model::BodyRef &ref, QUndoStack *undoStack)> createEditor;
    // A policy that draws the body without an editor (a DiagramScene on it renders offscreen).
    std::function<std::unique_ptr<DiagramPolicy>()> createPolicy;
    // What a new body of this language (a new POU, action or transition) starts with, so that it
    // opens on something valid to build on (SFC: an initial step); empty: an empty body.
    std::function<model::Body()> newBody = {};
};

class EditorRegistry
{
public:
    static EditorRegistry &instance();

    // Adds or replaces the entry of factory.language.
    void add(EditorFactory factory);
    [[nodiscard]] const EditorFactory *find(EditorLanguage language) const;
    [[nodiscard]] const EditorFactory *forBody(const model::Body &body) const;
    // The languages that have an editor, in EditorLanguage order.
    [[nodiscard]] std::vector<EditorLanguage> languages() const;

private:
    std::map<EditorLanguage, EditorFactory> m_factories;
};

} // namespace iec::editors
