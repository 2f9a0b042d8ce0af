#pragma once

#include <QByteArray>
#include <QString>
#include <QStringView>

#include <algorithm>

// What text a project file can keep. XML 1.0 has no way to hold NUL and the other control
// characters but tab and line breaks, nor U+FFFE and U+FFFF, not even as character references: a
// text with one would be cut short or refused when the file is read again.
namespace iec::model {

[[nodiscard]] constexpr bool fileCanKeep(char16_t c)
{
    return (c >= 0x20 || c == u'\t' || c == u'\n' || c == u'\r') && c != 0xFFFE && c != 0xFFFF;
}

// `text` without the characters a file cannot keep (pasted text: a stray control character from
// another program is dropped rather than kept where the save would lose it).
[[nodiscard]] inline QString withoutCharactersAFileCannotKeep(QStringView text)
{
    QString kept;
    kept.reserve(text.size());
    for (const QChar c : text) {
        if (fileCanKeep(c.unicode()))
            kept.append(c);
    }
    return kept;
}

// The UTF-8 the PLCopen writer hands to the XML: what a model text would make invalid (or, for a
// NUL, cut short) is left out, whichever way it entered the model.
[[nodiscard]] inline QByteArray toFileUtf8(QStringView text)
{
    if (std::ranges::all_of(text, [](QChar c) { return fileCanKeep(c.unicode()); }))
        return text.toUtf8();
    return withoutCharactersAFileCannotKeep(text).toUtf8();
}

} // namespace iec::model
