#include "editors/common/editorlanguage.h"

#include "model/body.h"

namespace iec::editors {

namespace {

bool hasCfcDiagram(const model::Body &body)
{
    for (const model::AddDataEntry &entry : body.addData) {
        if (entry.name.endsWith(QLatin1String(kCodesysCfcAddDataSuffix), Qt::CaseInsensitive)
            || entry.name == QLatin1String(kIecStudioCfcAddDataName))
            return true;
    }
    return false;
}

} // namespace

EditorLanguage editorLanguage(const model::Body &body)
{
    switch (body.language()) {
    case model::BodyLanguage::ST:
        // CODESYS writes a CFC diagram as an empty ST body that carries the diagram in addData.
        return body.text().trimmed().isEmpty() && hasCfcDiagram(body) ? EditorLanguage::CFC : EditorLanguage::ST;
    case model::BodyLanguage::IL:
        return EditorLanguage::IL;
    case model::BodyLanguage::LD:
        return EditorLanguage::LD;
    case model::BodyLanguage::FBD:
        return hasCfcDiagram(body) ? EditorLanguage::CFC : EditorLanguage::FBD;
    case model::BodyLanguage::SFC:
        return EditorLanguage::SFC;
    }
    return EditorLanguage::ST;
}

model::BodyLanguage storedLanguage(EditorLanguage language)
{
    switch (language) {
    case EditorLanguage::ST:
        return model::BodyLanguage::ST;
    case EditorLanguage::IL:
        return model::BodyLanguage::IL;
    case EditorLanguage::LD:
        return model::BodyLanguage::LD;
    case EditorLanguage::FBD:
    case EditorLanguage::CFC:
        return model::BodyLanguage::FBD;
    case EditorLanguage::SFC:
        return model::BodyLanguage::SFC;
    }
    return model::BodyLanguage::ST;
}

QString editorLanguageName(EditorLanguage language)
{
    switch (language) {
    case EditorLanguage::ST: return QStringLiteral("ST");
    case EditorLanguage::IL: return QStringLiteral("IL");
    case EditorLanguage::LD: return QStringLiteral("LD");
    case EditorLanguage::FBD: return QStringLiteral("FBD");
    case EditorLanguage::CFC: return QStringLiteral("CFC");
    case EditorLanguage::SFC: return QStringLiteral("SFC");
    }
    return {};
}

} // namespace iec::editors
