#pragma once

#include <QByteArray>
#include <QString>

namespace iec::interp::frontend {

// The text of an IEC source file (.st, .exp). UTF-8, with or without a byte order mark (UTF-16 and
// UTF-32 with theirs); bytes that are not UTF-8 mean the file is in Windows-1252, the code page
// CoDeSys 2.3 and TwinCAT 2 write their exports in (read as UTF-8, its umlauts would become U+FFFD
// and be lost on saving; a file mixing both is read as Windows-1252 throughout). Lines
// end in \n (a project file keeps no \r). The lines of CoDeSys 2.3's export markers, such as
// (* @END_DECLARATION := '0' *), are left empty: they say where the export's parts are, not what
// the program does, and would otherwise start each body (lines keep their numbers). A body CoDeSys 2.3
// exported in its graphical form (_LD_BODY, _FBD_BODY, ...) becomes a comment headed by an
// {error '...'} pragma, so that compiling it says why instead of failing on its first line.
struct SourceText {
    QString text;
    int windows1252Line = 0; // the first line that is not UTF-8 (1-based); 0: the file is UTF-8
};

[[nodiscard]] SourceText decodeSourceFile(const QByteArray &bytes);

// CR LF and a lone CR become LF (an XML file keeps no CR either).
void useLfLineEnds(QString &text);

// What to tell the user about a file read as Windows-1252 (translated).
[[nodiscard]] QString windows1252Note();

} // namespace iec::interp::frontend
