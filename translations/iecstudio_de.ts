<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>NameRules</name>
    <message>
        <source>Enter a name.</source>
        <translation>Geben Sie einen Namen ein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
        <translation>&quot;%1&quot; ist kein IEC-Bezeichner: verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche; am Anfang ein Buchstabe oder Unterstrich, am Ende kein Unterstrich.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a reserved word of IEC 61131-3.</source>
        <translation>&quot;%1&quot; ist ein reserviertes Wort der IEC 61131-3.</translation>
    </message>
    <message>
        <source>A POU or data type named &quot;%1&quot; exists already.</source>
        <translation>Ein Baustein oder Datentyp namens &quot;%1&quot; existiert bereits.</translation>
    </message>
    <message>
        <source>This POU has an action or transition named &quot;%1&quot; already.</source>
        <translation>Dieser Baustein hat bereits eine Aktion oder Transition namens &quot;%1&quot;.</translation>
    </message>
</context>
<context>
    <name>ProjectCommands</name>
    <message>
        <source>A function needs a return type.</source>
        <translation>Eine Funktion braucht einen Rückgabetyp.</translation>
    </message>
    <message>
        <source>The POU does not exist any more.</source>
        <translation>Der Baustein existiert nicht mehr.</translation>
    </message>
    <message>
        <source>The item does not exist any more.</source>
        <translation>Das Element existiert nicht mehr.</translation>
    </message>
</context>
<context>
    <name>iec::app::AddPouDialog</name>
    <message>
        <source>Add POU</source>
        <translation>Baustein hinzufügen</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>Function Block</source>
        <translation>Funktionsbaustein</translation>
    </message>
    <message>
        <source>Function</source>
        <translation>Funktion</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Kind:</source>
        <translation>&amp;Typ:</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>&amp;Return type:</source>
        <translation>&amp;Rückgabetyp:</translation>
    </message>
    <message>
        <source>A function needs a return type.</source>
        <translation>Eine Funktion braucht einen Rückgabetyp.</translation>
    </message>
</context>
<context>
    <name>iec::app::AddPouPartDialog</name>
    <message>
        <source>Add Action</source>
        <translation>Aktion hinzufügen</translation>
    </message>
    <message>
        <source>Add Transition</source>
        <translation>Transition hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
</context>
<context>
    <name>iec::app::BuildController</name>
    <message>
        <source>%1 Hint: %2</source>
        <translation>%1 Hinweis: %2</translation>
    </message>
</context>
<context>
    <name>iec::app::DocumentArea</name>
    <message>
        <source>This body is written in %1. Its editor is not available in this version; the body is kept unchanged when the project is saved.</source>
        <translation>Dieser Rumpf ist in %1 geschrieben. Sein Editor ist in dieser Version noch nicht verfügbar; der Rumpf bleibt beim Speichern unverändert erhalten.</translation>
    </message>
</context>
<context>
    <name>iec::app::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Project</source>
        <translation>&amp;Projekt</translation>
    </message>
    <message>
        <source>&amp;Online</source>
        <translation>&amp;Online</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Build</source>
        <translation>&amp;Übersetzen</translation>
    </message>
    <message>
        <source>Login and &amp;Run</source>
        <translation>Einloggen und &amp;Starten</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>S&amp;toppen</translation>
    </message>
    <message>
        <source>Single &amp;Cycle</source>
        <translation>&amp;Einzelzyklus</translation>
    </message>
    <message>
        <source>&amp;About IEC Studio</source>
        <translation>Ü&amp;ber IEC Studio</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <source>Messages</source>
        <translation>Meldungen</translation>
    </message>
    <message>
        <source>About IEC Studio</source>
        <translation>Über IEC Studio</translation>
    </message>
    <message>
        <source>&lt;h3&gt;IEC Studio %1&lt;/h3&gt;&lt;p&gt;An IDE for the five IEC 61131-3 languages: Ladder Diagram, Function Block Diagram with CFC, Sequential Function Chart, Instruction List and Structured Text.&lt;/p&gt;&lt;p&gt;Projects are stored as PLCopen TC6 XML v2.01.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;IEC Studio %1&lt;/h3&gt;&lt;p&gt;Eine Entwicklungsumgebung für die fünf Sprachen der IEC 61131-3: Kontaktplan, Funktionsbausteinsprache mit CFC, Ablaufsprache, Anweisungsliste und Strukturierter Text.&lt;/p&gt;&lt;p&gt;Projekte werden als PLCopen TC6 XML v2.01 gespeichert.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Settings...</source>
        <translation>&amp;Einstellungen...</translation>
    </message>
    <message>
        <source>&amp;New Project</source>
        <translation>&amp;Neues Projekt</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter...</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>%1[*] - IEC Studio</source>
        <translation>%1[*] - IEC Studio</translation>
    </message>
    <message>
        <source>%1 is not a PLCopen XML project.</source>
        <translation>%1 ist kein PLCopen-XML-Projekt.</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The project has unsaved changes. Save them first?</source>
        <translation>Das Projekt hat ungespeicherte Änderungen. Zuerst speichern?</translation>
    </message>
    <message>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <source>PLCopen XML projects (*.xml);;All files (*)</source>
        <translation>PLCopen-XML-Projekte (*.xml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The project could not be opened: %1</source>
        <translation>Das Projekt konnte nicht geöffnet werden: %1</translation>
    </message>
    <message>
        <source>Save Project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <source>The project could not be saved: %1</source>
        <translation>Das Projekt konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>Save Project As</source>
        <translation>Projekt speichern unter</translation>
    </message>
    <message>
        <source>PLCopen XML projects (*.xml)</source>
        <translation>PLCopen-XML-Projekte (*.xml)</translation>
    </message>
    <message>
        <source>&amp;Insert</source>
        <translation>&amp;Einfügen</translation>
    </message>
    <message>
        <source>&amp;Window</source>
        <translation>&amp;Fenster</translation>
    </message>
    <message>
        <source>Recent &amp;Projects</source>
        <translation>&amp;Zuletzt geöffnete Projekte</translation>
    </message>
    <message>
        <source>&amp;Examples</source>
        <translation>&amp;Beispiele</translation>
    </message>
    <message>
        <source>Toolbar</source>
        <translation>Werkzeugleiste</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>%1 does not exist any more; it was removed from the recent projects.</source>
        <translation>%1 existiert nicht mehr; es wurde aus den zuletzt geöffneten Projekten entfernt.</translation>
    </message>
    <message>
        <source>(untitled)</source>
        <translation>(unbenannt)</translation>
    </message>
    <message>
        <source>Recover Project</source>
        <translation>Projekt wiederherstellen</translation>
    </message>
    <message>
        <source>IEC Studio did not close properly. Recover the autosaved changes?</source>
        <translation>IEC Studio wurde nicht ordnungsgemäß beendet. Die automatisch gespeicherten Änderungen wiederherstellen?</translation>
    </message>
    <message>
        <source>Project: %1
Autosaved: %2</source>
        <translation>Projekt: %1
Automatisch gespeichert: %2</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>Ask &amp;Later</source>
        <translation>&amp;Später fragen</translation>
    </message>
    <message>
        <source>The project could not be recovered: %1</source>
        <translation>Das Projekt konnte nicht wiederhergestellt werden: %1</translation>
    </message>
    <message>
        <source>Build finished. Errors: %1, warnings: %2.</source>
        <translation>Übersetzen beendet. Fehler: %1, Warnungen: %2.</translation>
    </message>
</context>
<context>
    <name>iec::app::MessagesPane</name>
    <message>
        <source>%1, line %2, column %3</source>
        <translation>%1, Zeile %2, Spalte %3</translation>
    </message>
    <message>
        <source>%1, line %2</source>
        <translation>%1, Zeile %2</translation>
    </message>
    <message>
        <source>%1, element %2</source>
        <translation>%1, Element %2</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Schwere</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Location</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>Errors: %1, warnings: %2</source>
        <translation>Fehler: %1, Warnungen: %2</translation>
    </message>
</context>
<context>
    <name>iec::app::ProjectTreeActions</name>
    <message>
        <source>Add &amp;POU...</source>
        <translation>&amp;Baustein hinzufügen...</translation>
    </message>
    <message>
        <source>Add &amp;Action...</source>
        <translation>&amp;Aktion hinzufügen...</translation>
    </message>
    <message>
        <source>Add &amp;Transition...</source>
        <translation>&amp;Transition hinzufügen...</translation>
    </message>
    <message>
        <source>&amp;Rename...</source>
        <translation>&amp;Umbenennen...</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>D&amp;uplizieren</translation>
    </message>
    <message>
        <source>Add POU</source>
        <translation>Baustein hinzufügen</translation>
    </message>
    <message>
        <source>Rename %1</source>
        <translation>%1 umbenennen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Delete %1? Edit → Undo brings it back.</source>
        <translation>%1 löschen? Bearbeiten → Rückgängig holt es zurück.</translation>
    </message>
</context>
<context>
    <name>iec::app::ProjectTreeModel</name>
    <message>
        <source>Programs</source>
        <translation>Programme</translation>
    </message>
    <message>
        <source>Function Blocks</source>
        <translation>Funktionsbausteine</translation>
    </message>
    <message>
        <source>Functions</source>
        <translation>Funktionen</translation>
    </message>
    <message>
        <source>Data Types</source>
        <translation>Datentypen</translation>
    </message>
    <message>
        <source>Global Variables</source>
        <translation>Globale Variablen</translation>
    </message>
    <message>
        <source>Configurations</source>
        <translation>Konfigurationen</translation>
    </message>
    <message>
        <source>%1 (PRG)</source>
        <translation>%1 (PRG)</translation>
    </message>
    <message>
        <source>%1 (FB)</source>
        <translation>%1 (FB)</translation>
    </message>
    <message>
        <source>%1 (FUN)</source>
        <translation>%1 (FUN)</translation>
    </message>
    <message>
        <source>%1, written in %2</source>
        <translation>%1, geschrieben in %2</translation>
    </message>
    <message>
        <source>Structured Text (ST)</source>
        <translation>Strukturierter Text (ST)</translation>
    </message>
    <message>
        <source>Instruction List (IL)</source>
        <translation>Anweisungsliste (AWL)</translation>
    </message>
    <message>
        <source>Ladder Diagram (LD)</source>
        <translation>Kontaktplan (KOP)</translation>
    </message>
    <message>
        <source>Function Block Diagram (FBD)</source>
        <translation>Funktionsbausteinsprache (FUP)</translation>
    </message>
    <message>
        <source>Sequential Function Chart (SFC)</source>
        <translation>Ablaufsprache (AS)</translation>
    </message>
</context>
<context>
    <name>iec::app::RecentFilesMenu</name>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
</context>
<context>
    <name>iec::app::RecoveryManager</name>
    <message>
        <source>Cannot create the folder %1.</source>
        <translation>Der Ordner %1 kann nicht angelegt werden.</translation>
    </message>
</context>
<context>
    <name>iec::app::RenameDialog</name>
    <message>
        <source>Rename %1</source>
        <translation>%1 umbenennen</translation>
    </message>
    <message>
        <source>&amp;New name:</source>
        <translation>&amp;Neuer Name:</translation>
    </message>
</context>
<context>
    <name>iec::app::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source> pt</source>
        <translation> pt</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>User interface language:</source>
        <translation>Sprache der Oberfläche:</translation>
    </message>
    <message>
        <source>Editor font:</source>
        <translation>Editor-Schriftart:</translation>
    </message>
    <message>
        <source>Editor font size:</source>
        <translation>Editor-Schriftgröße:</translation>
    </message>
    <message>
        <source>Diagram grid size:</source>
        <translation>Rastergröße im Diagramm:</translation>
    </message>
    <message>
        <source>Autosave every:</source>
        <translation>Automatisch speichern alle:</translation>
    </message>
</context>
<context>
    <name>iec::app::UndoActions</name>
    <message>
        <source>&amp;Undo Typing</source>
        <translation>Tippen &amp;rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo Typing</source>
        <translation>Tippen &amp;wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>%1 &amp;rückgängig</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>%1 &amp;wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
</context>
<context>
    <name>iec::app::WindowMenu</name>
    <message>
        <source>&amp;Next Document</source>
        <translation>&amp;Nächstes Dokument</translation>
    </message>
    <message>
        <source>&amp;Previous Document</source>
        <translation>&amp;Vorheriges Dokument</translation>
    </message>
    <message>
        <source>&amp;Close All Documents</source>
        <translation>&amp;Alle Dokumente schließen</translation>
    </message>
</context>
<context>
    <name>iec::editors::AliasPage</name>
    <message>
        <source>Base type:</source>
        <translation>Basistyp:</translation>
    </message>
</context>
<context>
    <name>iec::editors::ArrayPage</name>
    <message>
        <source>Low</source>
        <translation>Unten</translation>
    </message>
    <message>
        <source>High</source>
        <translation>Oben</translation>
    </message>
    <message>
        <source>Dimensions</source>
        <translation>Dimensionen</translation>
    </message>
    <message>
        <source>Element type:</source>
        <translation>Elementtyp:</translation>
    </message>
</context>
<context>
    <name>iec::editors::CodeEditor</name>
    <message>
        <source>Go to Definition</source>
        <translation>Gehe zur Definition</translation>
    </message>
    <message>
        <source>Complete</source>
        <translation>Vervollständigen</translation>
    </message>
    <message>
        <source>Input Assistant...</source>
        <translation>Eingabehilfe...</translation>
    </message>
    <message>
        <source>Toggle Comment</source>
        <translation>Kommentar ein/aus</translation>
    </message>
    <message>
        <source>Fold All</source>
        <translation>Alles einklappen</translation>
    </message>
    <message>
        <source>Unfold All</source>
        <translation>Alles ausklappen</translation>
    </message>
</context>
<context>
    <name>iec::editors::DataTypeEditor</name>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation>Art:</translation>
    </message>
    <message>
        <source>Initial value:</source>
        <translation>Initialwert:</translation>
    </message>
    <message>
        <source>(the default of the type)</source>
        <translation>(Vorgabewert des Typs)</translation>
    </message>
    <message>
        <source>Structure</source>
        <translation>Struktur</translation>
    </message>
    <message>
        <source>Enumeration</source>
        <translation>Aufzählung</translation>
    </message>
    <message>
        <source>Array</source>
        <translation>Feld</translation>
    </message>
    <message>
        <source>Subrange</source>
        <translation>Unterbereich</translation>
    </message>
    <message>
        <source>Alias</source>
        <translation>Alias</translation>
    </message>
    <message>
        <source>String</source>
        <translation>Zeichenkette</translation>
    </message>
    <message>
        <source>IEC text:</source>
        <translation>IEC-Text:</translation>
    </message>
    <message>
        <source>IEC text as last applied (correct the marked fields to apply):</source>
        <translation>IEC-Text wie zuletzt übernommen (korrigieren Sie die markierten Felder, um zu übernehmen):</translation>
    </message>
</context>
<context>
    <name>iec::editors::DataTypeValidator</name>
    <message>
        <source>A POU or data type named &quot;%1&quot; exists already.</source>
        <translation>Ein Baustein oder Datentyp namens &quot;%1&quot; existiert bereits.</translation>
    </message>
    <message>
        <source>A structure needs at least one member.</source>
        <translation>Eine Struktur braucht mindestens ein Element.</translation>
    </message>
    <message>
        <source>There is a member named &quot;%1&quot; already.</source>
        <translation>Es gibt bereits ein Element namens &quot;%1&quot;.</translation>
    </message>
    <message>
        <source>An enumeration needs at least one value.</source>
        <translation>Eine Aufzählung braucht mindestens einen Wert.</translation>
    </message>
    <message>
        <source>The value &quot;%1&quot; is listed already.</source>
        <translation>Der Wert &quot;%1&quot; ist bereits aufgeführt.</translation>
    </message>
    <message>
        <source>Enter a whole number, or leave it empty.</source>
        <translation>Geben Sie eine ganze Zahl ein oder lassen Sie das Feld leer.</translation>
    </message>
    <message>
        <source>An array needs at least one dimension.</source>
        <translation>Ein Feld braucht mindestens eine Dimension.</translation>
    </message>
    <message>
        <source>Enter a length from 1 to 65535, or leave it empty for the default.</source>
        <translation>Geben Sie eine Länge von 1 bis 65535 ein oder lassen Sie das Feld für den Vorgabewert leer.</translation>
    </message>
    <message>
        <source>Choose an integer type such as INT, DINT or UINT.</source>
        <translation>Wählen Sie einen Ganzzahltyp wie INT, DINT oder UINT.</translation>
    </message>
    <message>
        <source>The upper bound %1 is less than the lower bound %2.</source>
        <translation>Die obere Grenze %1 ist kleiner als die untere Grenze %2.</translation>
    </message>
    <message>
        <source>Enter a bound.</source>
        <translation>Geben Sie eine Grenze ein.</translation>
    </message>
    <message>
        <source>Enter a whole number or the name of a constant.</source>
        <translation>Geben Sie eine ganze Zahl oder den Namen einer Konstante ein.</translation>
    </message>
    <message>
        <source>Enter a type.</source>
        <translation>Geben Sie einen Typ ein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a type.</source>
        <translation>&quot;%1&quot; ist kein Typ.</translation>
    </message>
    <message>
        <source>A type cannot contain itself.</source>
        <translation>Ein Typ kann sich nicht selbst enthalten.</translation>
    </message>
    <message>
        <source>Unknown type &quot;%1&quot;.</source>
        <translation>Unbekannter Typ &quot;%1&quot;.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid initial value.</source>
        <translation>&quot;%1&quot; ist kein gültiger Initialwert.</translation>
    </message>
    <message>
        <source>Enter a name.</source>
        <translation>Geben Sie einen Namen ein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
        <translation>&quot;%1&quot; ist kein IEC-Bezeichner: verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche; am Anfang ein Buchstabe oder Unterstrich, am Ende kein Unterstrich.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a reserved word of IEC 61131-3.</source>
        <translation>&quot;%1&quot; ist ein reserviertes Wort der IEC 61131-3.</translation>
    </message>
</context>
<context>
    <name>iec::editors::DeclarationEditor</name>
    <message>
        <source>Table</source>
        <translation>Tabelle</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Text</translation>
    </message>
    <message>
        <source>Add Variable</source>
        <translation>Variable hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Move Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <source>Row %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>Line %1, column %2: %3</source>
        <translation>Zeile %1, Spalte %2: %3</translation>
    </message>
</context>
<context>
    <name>iec::editors::DeclarationRows</name>
    <message>
        <source>&quot;%1&quot; is not a variable class.</source>
        <translation>&quot;%1&quot; ist keine Variablenklasse.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a data type.</source>
        <translation>&quot;%1&quot; ist kein Datentyp.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an initial value for %2.</source>
        <translation>&quot;%1&quot; ist kein Initialwert für %2.</translation>
    </message>
</context>
<context>
    <name>iec::editors::DeclarationTableModel</name>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Initial Value</source>
        <translation>Initialwert</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Kommentar</translation>
    </message>
</context>
<context>
    <name>iec::editors::DeclarationText</name>
    <message>
        <source>VAR_ACCESS and VAR_CONFIG belong in a configuration, not in a POU.</source>
        <translation>VAR_ACCESS und VAR_CONFIG gehören in eine Konfiguration, nicht in einen Baustein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a valid name: use letters, digits and single underscores, and no keyword.</source>
        <translation>&quot;%1&quot; ist kein gültiger Name: verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche, und kein Schlüsselwort.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an address such as %IX0.0, %QW3 or %MD10.</source>
        <translation>&quot;%1&quot; ist keine Adresse wie %IX0.0, %QW3 oder %MD10.</translation>
    </message>
    <message>
        <source>%1 is declared twice.</source>
        <translation>%1 ist doppelt deklariert.</translation>
    </message>
</context>
<context>
    <name>iec::editors::EnumPage</name>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Value (optional)</source>
        <translation>Wert (optional)</translation>
    </message>
    <message>
        <source>Values</source>
        <translation>Werte</translation>
    </message>
    <message>
        <source>Base type (optional):</source>
        <translation>Basistyp (optional):</translation>
    </message>
</context>
<context>
    <name>iec::editors::FindReplaceBar</name>
    <message>
        <source>Find</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <source>Replace with</source>
        <translation>Ersetzen durch</translation>
    </message>
    <message>
        <source>Match case</source>
        <translation>Groß-/Kleinschreibung</translation>
    </message>
    <message>
        <source>Whole words</source>
        <translation>Ganze Wörter</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Vorheriges</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Nächstes</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Ersetzen</translation>
    </message>
    <message>
        <source>Replace All</source>
        <translation>Alle ersetzen</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Find:</source>
        <translation>Suchen:</translation>
    </message>
    <message>
        <source>Replace:</source>
        <translation>Ersetzen:</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Nicht gefunden</translation>
    </message>
    <message>
        <source>Search wrapped</source>
        <translation>Suche am Anfang fortgesetzt</translation>
    </message>
    <message numerus="yes">
        <source>%n replaced</source>
        <translation>
            <numerusform>%n ersetzt</numerusform>
            <numerusform>%n ersetzt</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>iec::editors::InputAssistantDialog</name>
    <message>
        <source>Input Assistant</source>
        <translation>Eingabehilfe</translation>
    </message>
    <message>
        <source>Operators</source>
        <translation>Operatoren</translation>
    </message>
    <message>
        <source>Operands</source>
        <translation>Operanden</translation>
    </message>
    <message>
        <source>Functions</source>
        <translation>Funktionen</translation>
    </message>
    <message>
        <source>Function blocks</source>
        <translation>Funktionsbausteine</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>IL operators</source>
        <translation>AWL-Operatoren</translation>
    </message>
    <message>
        <source>ST operators</source>
        <translation>ST-Operatoren</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variablen</translation>
    </message>
    <message>
        <source>Boolean constants</source>
        <translation>Boolesche Konstanten</translation>
    </message>
    <message>
        <source>User-defined functions</source>
        <translation>Eigene Funktionen</translation>
    </message>
    <message>
        <source>User-defined function blocks</source>
        <translation>Eigene Funktionsbausteine</translation>
    </message>
    <message>
        <source>Programs</source>
        <translation>Programme</translation>
    </message>
</context>
<context>
    <name>iec::editors::RowTable</name>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Add a row below the current one</source>
        <translation>Eine Zeile unter der aktuellen hinzufügen</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>Remove the current row</source>
        <translation>Die aktuelle Zeile entfernen</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>Nach oben</translation>
    </message>
    <message>
        <source>Move the current row up</source>
        <translation>Die aktuelle Zeile nach oben verschieben</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>Nach unten</translation>
    </message>
    <message>
        <source>Move the current row down</source>
        <translation>Die aktuelle Zeile nach unten verschieben</translation>
    </message>
    <message>
        <source>Row %1, %2: %3</source>
        <translation>Zeile %1, %2: %3</translation>
    </message>
</context>
<context>
    <name>iec::editors::StandardLibrary</name>
    <message>
        <source>Arithmetic</source>
        <translation>Arithmetik</translation>
    </message>
    <message>
        <source>Numeric</source>
        <translation>Numerisch</translation>
    </message>
    <message>
        <source>Bit shift</source>
        <translation>Bitschieben</translation>
    </message>
    <message>
        <source>Selection</source>
        <translation>Auswahl</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>Vergleich</translation>
    </message>
    <message>
        <source>String</source>
        <translation>Zeichenkette</translation>
    </message>
    <message>
        <source>Type conversion</source>
        <translation>Typumwandlung</translation>
    </message>
    <message>
        <source>Bistable</source>
        <translation>Bistabil</translation>
    </message>
    <message>
        <source>Edge detection</source>
        <translation>Flankenerkennung</translation>
    </message>
    <message>
        <source>Counters</source>
        <translation>Zähler</translation>
    </message>
    <message>
        <source>Timers</source>
        <translation>Zeitgeber</translation>
    </message>
    <message>
        <source>Load the operand into the current result</source>
        <translation>Operand in das aktuelle Ergebnis laden</translation>
    </message>
    <message>
        <source>Store the current result in the operand</source>
        <translation>Aktuelles Ergebnis im Operanden speichern</translation>
    </message>
    <message>
        <source>Set the Boolean operand to TRUE if the current result is TRUE</source>
        <translation>Booleschen Operanden auf TRUE setzen, wenn das aktuelle Ergebnis TRUE ist</translation>
    </message>
    <message>
        <source>Reset the Boolean operand to FALSE if the current result is TRUE</source>
        <translation>Booleschen Operanden auf FALSE rücksetzen, wenn das aktuelle Ergebnis TRUE ist</translation>
    </message>
    <message>
        <source>Bitwise AND</source>
        <translation>Bitweises UND</translation>
    </message>
    <message>
        <source>Bitwise OR</source>
        <translation>Bitweises ODER</translation>
    </message>
    <message>
        <source>Bitwise exclusive OR</source>
        <translation>Bitweises exklusives ODER</translation>
    </message>
    <message>
        <source>Addition</source>
        <translation>Addition</translation>
    </message>
    <message>
        <source>Subtraction</source>
        <translation>Subtraktion</translation>
    </message>
    <message>
        <source>Multiplication</source>
        <translation>Multiplikation</translation>
    </message>
    <message>
        <source>Division</source>
        <translation>Division</translation>
    </message>
    <message>
        <source>Greater than (&gt;)</source>
        <translation>Größer als (&gt;)</translation>
    </message>
    <message>
        <source>Greater than or equal (&gt;=)</source>
        <translation>Größer oder gleich (&gt;=)</translation>
    </message>
    <message>
        <source>Equal (=)</source>
        <translation>Gleich (=)</translation>
    </message>
    <message>
        <source>Not equal (&lt;&gt;)</source>
        <translation>Ungleich (&lt;&gt;)</translation>
    </message>
    <message>
        <source>Less than or equal (&lt;=)</source>
        <translation>Kleiner oder gleich (&lt;=)</translation>
    </message>
    <message>
        <source>Less than (&lt;)</source>
        <translation>Kleiner als (&lt;)</translation>
    </message>
    <message>
        <source>Jump to the label</source>
        <translation>Sprung zur Marke</translation>
    </message>
    <message>
        <source>Call a function block instance</source>
        <translation>Funktionsbaustein-Instanz aufrufen</translation>
    </message>
    <message>
        <source>Return to the calling POU</source>
        <translation>Rückkehr zum aufrufenden Baustein</translation>
    </message>
    <message>
        <source>Evaluate the deferred operation</source>
        <translation>Zurückgestellte Operation auswerten</translation>
    </message>
    <message>
        <source>negated operand</source>
        <translation>negierter Operand</translation>
    </message>
    <message>
        <source>deferred until )</source>
        <translation>zurückgestellt bis )</translation>
    </message>
    <message>
        <source>only if the current result is TRUE</source>
        <translation>nur wenn das aktuelle Ergebnis TRUE ist</translation>
    </message>
    <message>
        <source>only if the current result is FALSE</source>
        <translation>nur wenn das aktuelle Ergebnis FALSE ist</translation>
    </message>
    <message>
        <source>Assignment</source>
        <translation>Zuweisung</translation>
    </message>
    <message>
        <source>Modulo</source>
        <translation>Modulo</translation>
    </message>
    <message>
        <source>Negation</source>
        <translation>Negation</translation>
    </message>
</context>
<context>
    <name>iec::editors::StringPage</name>
    <message>
        <source>Characters:</source>
        <translation>Zeichen:</translation>
    </message>
    <message>
        <source>Length (optional):</source>
        <translation>Länge (optional):</translation>
    </message>
</context>
<context>
    <name>iec::editors::StructPage</name>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>Initial value</source>
        <translation>Initialwert</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Kommentar</translation>
    </message>
    <message>
        <source>Members</source>
        <translation>Elemente</translation>
    </message>
</context>
<context>
    <name>iec::editors::SubrangePage</name>
    <message>
        <source>Base type:</source>
        <translation>Basistyp:</translation>
    </message>
    <message>
        <source>Low:</source>
        <translation>Unten:</translation>
    </message>
    <message>
        <source>High:</source>
        <translation>Oben:</translation>
    </message>
</context>
<context>
    <name>iec::model::AddDataTypeCommand</name>
    <message>
        <source>Add data type %1</source>
        <translation>Datentyp %1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>iec::model::AddPouCommand</name>
    <message>
        <source>Add POU %1</source>
        <translation>Baustein %1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>iec::model::AddPouPartCommand</name>
    <message>
        <source>Add action %1</source>
        <translation>Aktion %1 hinzufügen</translation>
    </message>
    <message>
        <source>Add transition %1</source>
        <translation>Transition %1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>iec::model::AddVariableCommand</name>
    <message>
        <source>Add variable %1</source>
        <translation>Variable %1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>iec::model::ChangeDataTypeCommand</name>
    <message>
        <source>Change data type %1</source>
        <translation>Datentyp %1 ändern</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
<context>
    <name>iec::model::ChangeElementCommand</name>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
</context>
<context>
    <name>iec::model::ChangeVariableCommand</name>
    <message>
        <source>Change variable %1</source>
        <translation>Variable %1 ändern</translation>
    </message>
</context>
<context>
    <name>iec::model::ConnectCommand</name>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
</context>
<context>
    <name>iec::model::DisconnectCommand</name>
    <message>
        <source>Disconnect</source>
        <translation>Verbindung lösen</translation>
    </message>
</context>
<context>
    <name>iec::model::DuplicatePouCommand</name>
    <message>
        <source>Duplicate POU as %1</source>
        <translation>Baustein als %1 duplizieren</translation>
    </message>
</context>
<context>
    <name>iec::model::InsertElementCommand</name>
    <message>
        <source>Insert %1</source>
        <translation>%1 einfügen</translation>
    </message>
</context>
<context>
    <name>iec::model::MoveElementsCommand</name>
    <message numerus="yes">
        <source>Move %n element(s)</source>
        <translation>
            <numerusform>%n Element verschieben</numerusform>
            <numerusform>%n Elemente verschieben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>iec::model::RemoveDataTypeCommand</name>
    <message>
        <source>Delete data type %1</source>
        <translation>Datentyp %1 löschen</translation>
    </message>
</context>
<context>
    <name>iec::model::RemoveElementCommand</name>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
</context>
<context>
    <name>iec::model::RemovePouCommand</name>
    <message>
        <source>Delete POU %1</source>
        <translation>Baustein %1 löschen</translation>
    </message>
</context>
<context>
    <name>iec::model::RemovePouPartCommand</name>
    <message>
        <source>Delete action %1</source>
        <translation>Aktion %1 löschen</translation>
    </message>
    <message>
        <source>Delete transition %1</source>
        <translation>Transition %1 löschen</translation>
    </message>
</context>
<context>
    <name>iec::model::RemoveVariableCommand</name>
    <message>
        <source>Delete variable %1</source>
        <translation>Variable %1 löschen</translation>
    </message>
</context>
<context>
    <name>iec::model::RenamePouCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
<context>
    <name>iec::model::RenamePouPartCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
<context>
    <name>iec::model::SetBodyTextCommand</name>
    <message>
        <source>Edit text</source>
        <translation>Text bearbeiten</translation>
    </message>
</context>
<context>
    <name>iec::model::SetInterfaceCommand</name>
    <message>
        <source>Edit declarations</source>
        <translation>Deklarationen bearbeiten</translation>
    </message>
</context>
<context>
    <name>iec::model::plcopen::Reader</name>
    <message>
        <source>The elements are nested too deeply; the content below is skipped.</source>
        <translation>Die Elemente sind zu tief verschachtelt; der Inhalt darunter wird übersprungen.</translation>
    </message>
    <message>
        <source>The attribute %1=&quot;%2&quot; of &lt;%3&gt; has an invalid value; it is kept as written.</source>
        <translation>Das Attribut %1=&quot;%2&quot; von &lt;%3&gt; hat einen ungültigen Wert; es bleibt wie geschrieben erhalten.</translation>
    </message>
    <message>
        <source>&lt;%1&gt; lacks the required attribute &apos;%2&apos;.</source>
        <translation>&lt;%1&gt; fehlt das erforderliche Attribut &apos;%2&apos;.</translation>
    </message>
    <message>
        <source>&lt;%1&gt; lacks the required element &lt;%2&gt;.</source>
        <translation>&lt;%1&gt; fehlt das erforderliche Element &lt;%2&gt;.</translation>
    </message>
    <message>
        <source>Unknown attribute &apos;%1&apos; on &lt;%2&gt; is kept as it is.</source>
        <translation>Das unbekannte Attribut &apos;%1&apos; an &lt;%2&gt; bleibt unverändert erhalten.</translation>
    </message>
    <message>
        <source>Unknown attribute &apos;%1&apos; on &lt;%2&gt; is ignored.</source>
        <translation>Das unbekannte Attribut &apos;%1&apos; an &lt;%2&gt; wird ignoriert.</translation>
    </message>
    <message>
        <source>Unknown element &lt;%1&gt; in &lt;%2&gt; is kept as it is.</source>
        <translation>Das unbekannte Element &lt;%1&gt; in &lt;%2&gt; bleibt unverändert erhalten.</translation>
    </message>
    <message>
        <source>Unknown element &lt;%1&gt; in &lt;%2&gt; is ignored.</source>
        <translation>Das unbekannte Element &lt;%1&gt; in &lt;%2&gt; wird ignoriert.</translation>
    </message>
    <message>
        <source>A declaration in addData is nested too deeply to read; it is kept as it is.</source>
        <translation>Eine Deklaration in addData ist zu tief verschachtelt; sie bleibt unverändert erhalten.</translation>
    </message>
    <message>
        <source>&lt;%1&gt; names no data type.</source>
        <translation>&lt;%1&gt; nennt keinen Datentyp.</translation>
    </message>
    <message>
        <source>The data type &lt;%1&gt; is not in the PLCopen schema; it is kept by name.</source>
        <translation>Der Datentyp &lt;%1&gt; gehört nicht zum PLCopen-Schema; er bleibt mit seinem Namen erhalten.</translation>
    </message>
    <message>
        <source>The namespace &apos;%1&apos; is not PLCopen TC6 XML 2.01; the file is read anyway.</source>
        <translation>Der Namensraum &apos;%1&apos; ist nicht PLCopen TC6 XML 2.01; die Datei wird trotzdem gelesen.</translation>
    </message>
    <message>
        <source>The file is not well-formed XML: %1.</source>
        <translation>Die Datei ist kein wohlgeformtes XML: %1.</translation>
    </message>
    <message>
        <source>The root element is &lt;%1&gt;, not &lt;project&gt;: this is not a PLCopen XML file.</source>
        <translation>Das Wurzelelement ist &lt;%1&gt;, nicht &lt;project&gt;: dies ist keine PLCopen-XML-Datei.</translation>
    </message>
    <message>
        <source>Cannot open %1: %2.</source>
        <translation>%1 kann nicht geöffnet werden: %2.</translation>
    </message>
</context>
<context>
    <name>iec::model::plcopen::Writer</name>
    <message>
        <source>Cannot save %1: %2.</source>
        <translation>%1 kann nicht gespeichert werden: %2.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Open Project</source>
        <translation>Projekt öffnen</translation>
    </message>
</context>
</TS>
