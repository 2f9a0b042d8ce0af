<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
    <context>
        <name>GlobalListCommands</name>
        <message>
            <source>The configuration or resource for the list does not exist any more.</source>
            <translation>Die Konfiguration oder Ressource der Liste existiert nicht mehr.</translation>
        </message>
        <message>
            <source>Add global variable list %1</source>
            <translation>Globale Variablenliste %1 hinzufügen</translation>
        </message>
        <message>
            <source>The list does not exist any more.</source>
            <translation>Die Liste existiert nicht mehr.</translation>
        </message>
        <message>
            <source>Rename global variable list %1 to %2</source>
            <translation>Globale Variablenliste %1 in %2 umbenennen</translation>
        </message>
        <message>
            <source>Duplicate global variable list %1</source>
            <translation>Globale Variablenliste %1 duplizieren</translation>
        </message>
        <message>
            <source>Delete global variable list %1</source>
            <translation>Globale Variablenliste %1 löschen</translation>
        </message>
        <message>
            <source>Create task configuration %1</source>
            <translation>Taskkonfiguration %1 anlegen</translation>
        </message>
    </context>
    <context>
        <name>ImportExport</name>
        <message>
            <source>%1 is not a PLCopen XML project.</source>
            <translation>%1 ist kein PLCopen-XML-Projekt.</translation>
        </message>
        <message>
            <source>%1 cannot be read: %2</source>
            <translation>%1 kann nicht gelesen werden: %2</translation>
        </message>
        <message>
            <source>%1 exists already; the imported one is named %2.</source>
            <translation>%1 existiert bereits; das importierte Objekt heißt %2.</translation>
        </message>
        <message numerus="yes">
            <source>Import %n object(s)</source>
            <translation>
                <numerusform>%n Objekt importieren</numerusform>
                <numerusform>%n Objekte importieren</numerusform>
            </translation>
        </message>
        <message>
            <source>The imported configuration %1 joins the project's configuration %2.</source>
            <translation>Die importierte Konfiguration %1 wird mit der Konfiguration %2 des Projekts zusammengeführt.</translation>
        </message>
        <message>
            <source>%1 exists already in resource %2; the imported one is named %3.</source>
            <translation>%1 gibt es in der Ressource %2 schon; das importierte Objekt heißt %3.</translation>
        </message>
    </context>
    <context>
        <name>ModelCompletionProvider</name>
        <message>
            <source>Global variables</source>
            <translation>Globale Variablen</translation>
        </message>
        <message>
            <source>Local variables</source>
            <translation>Lokale Variablen</translation>
        </message>
        <message>
            <source>Programs</source>
            <translation>Programme</translation>
        </message>
        <message>
            <source>Function blocks</source>
            <translation>Funktionsbausteine</translation>
        </message>
        <message>
            <source>Functions</source>
            <translation>Funktionen</translation>
        </message>
    </context>
    <context>
        <name>NameRules</name>
        <message>
            <source>Enter a name.</source>
            <translation>Geben Sie einen Namen ein.</translation>
        </message>
        <message>
            <source>"%1" is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
            <translation>"%1" ist kein IEC-Bezeichner: verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche; am Anfang ein Buchstabe oder Unterstrich, am Ende kein Unterstrich.</translation>
        </message>
        <message>
            <source>"%1" is a reserved word of IEC 61131-3.</source>
            <translation>"%1" ist ein reserviertes Wort der IEC 61131-3.</translation>
        </message>
        <message>
            <source>A POU or data type named "%1" exists already.</source>
            <translation>Ein Baustein oder Datentyp namens "%1" existiert bereits.</translation>
        </message>
        <message>
            <source>This POU has an action or transition named "%1" already.</source>
            <translation>Dieser Baustein hat bereits eine Aktion oder Transition namens "%1".</translation>
        </message>
        <message>
            <source>A global variable list named "%1" exists already.</source>
            <translation>Eine globale Variablenliste namens "%1" existiert bereits.</translation>
        </message>
        <message>
            <source>This function block has a method or property named "%1" already.</source>
            <translation>Dieser Funktionsbaustein hat bereits eine Methode oder Eigenschaft namens „%1“.</translation>
        </message>
        <message>
            <source>An interface named "%1" exists already.</source>
            <translation>Eine Schnittstelle namens „%1“ gibt es bereits.</translation>
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
        <message>
            <source>Methods and properties belong to function blocks.</source>
            <translation>Methoden und Eigenschaften gehören zu Funktionsbausteinen.</translation>
        </message>
        <message>
            <source>The name "%1" cannot start a method.</source>
            <translation>Mit dem Namen „%1“ lässt sich keine Methode anlegen.</translation>
        </message>
        <message>
            <source>Add Property %1</source>
            <translation>Eigenschaft %1 hinzufügen</translation>
        </message>
        <message>
            <source>Add Method %1</source>
            <translation>Methode %1 hinzufügen</translation>
        </message>
        <message>
            <source>Delete %1</source>
            <translation>%1 löschen</translation>
        </message>
        <message>
            <source>Add Interface %1</source>
            <translation>Schnittstelle %1 hinzufügen</translation>
        </message>
    </context>
    <context>
        <name>ProjectTemplates</name>
        <message>
            <source>Closes the contact</source>
            <translation>Schließt den Kontakt</translation>
        </message>
        <message>
            <source>Lit while Start is TRUE</source>
            <translation>Leuchtet, solange Start TRUE ist</translation>
        </message>
        <message>
            <source>Switches Lamp on and off</source>
            <translation>Schaltet Lamp ein und aus</translation>
        </message>
    </context>
    <context>
        <name>iec::app</name>
        <message>
            <source>Rename variable %1 to %2</source>
            <translation>Variable %1 in %2 umbenennen</translation>
        </message>
        <message>
            <source>Rename global variable %1 to %2</source>
            <translation>Globale Variable %1 in %2 umbenennen</translation>
        </message>
        <message>
            <source>Rename member %1 to %2</source>
            <translation>Komponente %1 in %2 umbenennen</translation>
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
        <name>iec::app::AutoDeclare</name>
        <message>
            <source>The POU does not exist any more.</source>
            <translation>Der Baustein existiert nicht mehr.</translation>
        </message>
        <message>
            <source>Declare %1</source>
            <translation>%1 deklarieren</translation>
        </message>
    </context>
    <context>
        <name>iec::app::AutoDeclareDialog</name>
        <message>
            <source>Declare Variable</source>
            <translation>Variable deklarieren</translation>
        </message>
        <message>
            <source>&amp;Name:</source>
            <translation>&amp;Name:</translation>
        </message>
        <message>
            <source>&amp;Class:</source>
            <translation>&amp;Klasse:</translation>
        </message>
        <message>
            <source>&amp;Type:</source>
            <translation>&amp;Typ:</translation>
        </message>
        <message>
            <source>&amp;Initial value:</source>
            <translation>&amp;Initialwert:</translation>
        </message>
        <message>
            <source>C&amp;omment:</source>
            <translation>K&amp;ommentar:</translation>
        </message>
    </context>
    <context>
        <name>iec::app::BreakpointDialog</name>
        <message>
            <source>Enabled</source>
            <translation>Aktiviert</translation>
        </message>
        <message>
            <source>Breakpoint Properties</source>
            <translation>Haltepunkt-Eigenschaften</translation>
        </message>
        <message>
            <source>Break always</source>
            <translation>Immer anhalten</translation>
        </message>
        <message>
            <source>Break when the hit count is equal to</source>
            <translation>Anhalten, wenn die Trefferzahl gleich ist</translation>
        </message>
        <message>
            <source>Break when the hit count is a multiple of</source>
            <translation>Anhalten, wenn die Trefferzahl ein Vielfaches ist von</translation>
        </message>
        <message>
            <source>Break when the hit count is greater than or equal to</source>
            <translation>Anhalten, wenn die Trefferzahl größer oder gleich ist</translation>
        </message>
        <message>
            <source>for example  Count = 5 AND NOT Alarm</source>
            <translation>zum Beispiel  Count = 5 AND NOT Alarm</translation>
        </message>
        <message>
            <source>Place:</source>
            <translation>Stelle:</translation>
        </message>
        <message>
            <source>Hit count:</source>
            <translation>Trefferzahl:</translation>
        </message>
        <message>
            <source>Break when TRUE:</source>
            <translation>Anhalten, wenn TRUE:</translation>
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
        <name>iec::app::DebugController</name>
        <message>
            <source>Toggle &amp;Breakpoint</source>
            <translation>&amp;Haltepunkt ein/aus</translation>
        </message>
        <message>
            <source>Remove All Breakpoints</source>
            <translation>Alle Haltepunkte entfernen</translation>
        </message>
        <message>
            <source>Step &amp;Over</source>
            <translation>Prozedurschritt (&amp;O)</translation>
        </message>
        <message>
            <source>Step &amp;Into</source>
            <translation>Einzelschritt (&amp;I)</translation>
        </message>
        <message>
            <source>Step O&amp;ut</source>
            <translation>Rücksprung (&amp;U)</translation>
        </message>
        <message>
            <source>Breakpoints in transitions are not supported; put one on the step before it.</source>
            <translation>Haltepunkte in Transitionen gibt es nicht; setzen Sie einen auf den Schritt davor.</translation>
        </message>
        <message>
            <source>element %1</source>
            <translation>Element %1</translation>
        </message>
        <message>
            <source>line %1</source>
            <translation>Zeile %1</translation>
        </message>
        <message>
            <source>Halted in %1 at %2 (cycle %3). F5 continues, F10 steps over, F8 steps into, Shift+F10 steps out.</source>
            <translation>Angehalten in %1 bei %2 (Zyklus %3). F5 setzt fort, F10 Prozedurschritt, F8 Einzelschritt, Umschalt+F10 Rücksprung.</translation>
        </message>
        <message>
            <source>The breakpoint's condition could not be checked: %1</source>
            <translation>Die Bedingung des Haltepunkts ließ sich nicht prüfen: %1</translation>
        </message>
        <message>
            <source>Breakpoint &amp;Properties...</source>
            <translation>Haltepunkt-&amp;Eigenschaften...</translation>
        </message>
        <message>
            <source>%1, element %2</source>
            <translation>%1, Element %2</translation>
        </message>
        <message>
            <source>%1, line %2</source>
            <translation>%1, Zeile %2</translation>
        </message>
        <message>
            <source>A breakpoint goes on a line of an ST or IL body, a network of an LD or FBD body, or a step or transition of a chart: put the cursor there first.</source>
            <translation>Ein Haltepunkt gehört auf eine Zeile eines ST- oder AWL-Rumpfs, ein Netzwerk eines KOP- oder FUP-Rumpfs oder einen Schritt oder eine Transition eines Ablaufplans: setzen Sie den Cursor zuerst dorthin.</translation>
        </message>
        <message>
            <source>Run to &amp;Cursor</source>
            <translation>Bis zum &amp;Cursor ausführen</translation>
        </message>
        <message>
            <source>%1 (instance %2)</source>
            <translation>%1 (Instanz %2)</translation>
        </message>
        <message>
            <source>Halted in %1 at %2 (cycle %3).</source>
            <translation>Angehalten in %1 bei %2 (Zyklus %3).</translation>
        </message>
        <message>
            <source>Called from %1 at %2.</source>
            <translation>Aufgerufen von %1 bei %2.</translation>
        </message>
    </context>
    <context>
        <name>iec::app::DiagramMenus</name>
        <message>
            <source>Zoom: %1 %</source>
            <translation>Zoom: %1 %</translation>
        </message>
    </context>
    <context>
        <name>iec::app::DocumentArea</name>
        <message>
            <source>This body is written in %1. Its editor is not available in this version; the body is kept unchanged when the project is saved.</source>
            <translation>Dieser Rumpf ist in %1 geschrieben. Sein Editor ist in dieser Version noch nicht verfügbar; der Rumpf bleibt beim Speichern unverändert erhalten.</translation>
        </message>
        <message>
            <source>Declare Variable...</source>
            <translation>Variable deklarieren...</translation>
        </message>
        <message>
            <source>%1 is declared already.</source>
            <translation>%1 ist bereits deklariert.</translation>
        </message>
    </context>
    <context>
        <name>iec::app::EditActions</name>
        <message>
            <source>Cu&amp;t</source>
            <translation>&amp;Ausschneiden</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>&amp;Kopieren</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>E&amp;infügen</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>&amp;Löschen</translation>
        </message>
        <message>
            <source>Select &amp;All</source>
            <translation>Alles a&amp;uswählen</translation>
        </message>
        <message>
            <source>&amp;Find...</source>
            <translation>&amp;Suchen...</translation>
        </message>
        <message>
            <source>R&amp;eplace...</source>
            <translation>&amp;Ersetzen...</translation>
        </message>
    </context>
    <context>
        <name>iec::app::FindInProjectDialog</name>
        <message>
            <source>Match &amp;case</source>
            <translation>&amp;Groß-/Kleinschreibung beachten</translation>
        </message>
        <message>
            <source>&amp;Whole words</source>
            <translation>Ganze &amp;Wörter</translation>
        </message>
        <message>
            <source>&amp;Regular expression</source>
            <translation>&amp;Regulärer Ausdruck</translation>
        </message>
        <message>
            <source>Find in Project</source>
            <translation>Im Projekt suchen</translation>
        </message>
        <message>
            <source>Find:</source>
            <translation>Suchen:</translation>
        </message>
        <message>
            <source>Find</source>
            <translation>Suchen</translation>
        </message>
    </context>
    <context>
        <name>iec::app::HistoryBar</name>
        <message>
            <source>Scan History</source>
            <translation>Zyklushistorie</translation>
        </message>
        <message>
            <source>History: </source>
            <translation>Historie: </translation>
        </message>
        <message>
            <source>Present</source>
            <translation>Gegenwart</translation>
        </message>
        <message>
            <source>Show the program as it is now</source>
            <translation>Das Programm so zeigen, wie es jetzt ist</translation>
        </message>
        <message>
            <source>Resume from Here</source>
            <translation>Von hier fortsetzen</translation>
        </message>
        <message>
            <source>Go on from the scan shown: the scans after it are dropped, the next cycle starts from its values (write new inputs first, if you like)</source>
            <translation>Ab dem gezeigten Zyklus weitermachen: die Zyklen danach werden verworfen, der nächste Zyklus beginnt mit seinen Werten (vorher können neue Eingänge geschrieben werden)</translation>
        </message>
        <message>
            <source>Drag (or use the arrow keys) to see the program after an earlier scan</source>
            <translation>Ziehen (oder Pfeiltasten), um das Programm nach einem früheren Zyklus zu sehen</translation>
        </message>
        <message>
            <source>%1 / %2</source>
            <translation>%1 / %2</translation>
        </message>
        <message>
            <source>%1 of at most %2 scans kept, %3</source>
            <translation>%1 von höchstens %2 Zyklen gespeichert, %3</translation>
        </message>
        <message>
            <source>History: after scan %1 (the program is at %2)</source>
            <translation>Historie: nach Zyklus %1 (das Programm ist bei %2)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ImportExportActions</name>
        <message>
            <source>&amp;Import...</source>
            <translation>&amp;Importieren...</translation>
        </message>
        <message>
            <source>&amp;Export Project...</source>
            <translation>Projekt &amp;exportieren...</translation>
        </message>
        <message>
            <source>Export Se&amp;lection...</source>
            <translation>&amp;Auswahl exportieren...</translation>
        </message>
        <message>
            <source>Imported %1: %2 POU(s), %3 data type(s).</source>
            <translation>%1 importiert: %2 Baustein(e), %3 Datentyp(en).</translation>
        </message>
        <message>
            <source>Nothing could be read from %1.</source>
            <translation>Aus %1 konnte nichts gelesen werden.</translation>
        </message>
        <message>
            <source>Import</source>
            <translation>Importieren</translation>
        </message>
        <message>
            <source>PLCopen XML (*.xml)</source>
            <translation>PLCopen XML (*.xml)</translation>
        </message>
        <message>
            <source>IEC 61131-3 text (*.st)</source>
            <translation>IEC 61131-3-Text (*.st)</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>Exportieren</translation>
        </message>
        <message>
            <source>PLCopen XML or IEC text (*.xml *.st *.exp *.iec *.txt);;PLCopen XML (*.xml);;IEC 61131-3 text (*.st *.exp *.iec *.txt)</source>
            <translation>PLCopen XML oder IEC-Text (*.xml *.st *.exp *.iec *.txt);;PLCopen XML (*.xml);;IEC 61131-3-Text (*.st *.exp *.iec *.txt)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::LibraryPane</name>
        <message>
            <source>Standard library</source>
            <translation>Standardbibliothek</translation>
        </message>
        <message>
            <source>%1 library</source>
            <translation>Bibliothek %1</translation>
        </message>
        <message>
            <source>Project</source>
            <translation>Projekt</translation>
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
            <source>A function block of this project.</source>
            <translation>Ein Funktionsbaustein dieses Projekts.</translation>
        </message>
        <message>
            <source>A function of this project.</source>
            <translation>Eine Funktion dieses Projekts.</translation>
        </message>
        <message>
            <source>(function block)</source>
            <translation>(Funktionsbaustein)</translation>
        </message>
        <message>
            <source>(function)</source>
            <translation>(Funktion)</translation>
        </message>
        <message>
            <source>Inputs:</source>
            <translation>Eingänge:</translation>
        </message>
        <message>
            <source>Outputs:</source>
            <translation>Ausgänge:</translation>
        </message>
        <message>
            <source>Returns:</source>
            <translation>Rückgabewert:</translation>
        </message>
        <message>
            <source>Search blocks</source>
            <translation>Bausteine suchen</translation>
        </message>
        <message>
            <source>Choose a block to see its pins; drag it into an editor to call it.</source>
            <translation>Wählen Sie einen Baustein, um seine Anschlüsse zu sehen; ziehen Sie ihn in einen Editor, um ihn aufzurufen.</translation>
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
        <message>
            <source>Watch</source>
            <translation>Beobachtung</translation>
        </message>
        <message>
            <source>Log out to edit (Online → Logout).</source>
            <translation>Zum Bearbeiten ausloggen (Online → Ausloggen).</translation>
        </message>
        <message>
            <source>Search Results</source>
            <translation>Suchergebnisse</translation>
        </message>
        <message>
            <source>Library</source>
            <translation>Bibliothek</translation>
        </message>
        <message>
            <source>&amp;Print Documentation...</source>
            <translation>Dokumentation d&amp;rucken...</translation>
        </message>
        <message>
            <source>Export Documentation as P&amp;DF...</source>
            <translation>Dokumentation als P&amp;DF exportieren...</translation>
        </message>
        <message>
            <source>Print Documentation</source>
            <translation>Dokumentation drucken</translation>
        </message>
        <message>
            <source>Export Documentation</source>
            <translation>Dokumentation exportieren</translation>
        </message>
        <message>
            <source>PDF documents (*.pdf)</source>
            <translation>PDF-Dokumente (*.pdf)</translation>
        </message>
        <message>
            <source>The documentation was written to %1.</source>
            <translation>Die Dokumentation wurde in %1 geschrieben.</translation>
        </message>
        <message>
            <source>Trace: %1</source>
            <translation>Trace: %1</translation>
        </message>
        <message>
            <source>Trace</source>
            <translation>Trace</translation>
        </message>
        <message>
            <source>%1, line %2: %3</source>
            <translation>%1, Zeile %2: %3</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
        <message>
            <source>PLCopen XML projects (*.xml);;IEC 61131-3 text (*.st *.exp *.iec *.txt);;All files (*)</source>
            <translation>PLCopen-XML-Projekte (*.xml);;IEC 61131-3-Text (*.st *.exp *.iec *.txt);;Alle Dateien (*)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::MemberEditor</name>
        <message>
            <source>%1 already has a method or property called %2.</source>
            <translation>%1 hat bereits eine Methode oder Eigenschaft namens %2.</translation>
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
        <message>
            <source>%1, element %2, column %3</source>
            <translation>%1, Element %2, Spalte %3</translation>
        </message>
    </context>
    <context>
        <name>iec::app::NewProjectDialog</name>
        <message>
            <source>New Project</source>
            <translation>Neues Projekt</translation>
        </message>
        <message>
            <source>Start the project from:</source>
            <translation>Projekt beginnen mit:</translation>
        </message>
    </context>
    <context>
        <name>iec::app::OnlineController</name>
        <message>
            <source>Log&amp;out</source>
            <translation>A&amp;usloggen</translation>
        </message>
        <message>
            <source>Run &amp;N Cycles...</source>
            <translation>&amp;N Zyklen ausführen...</translation>
        </message>
        <message>
            <source>Reset &amp;Warm</source>
            <translation>&amp;Warmstart (Reset)</translation>
        </message>
        <message>
            <source>Reset C&amp;old</source>
            <translation>&amp;Kaltstart (Reset)</translation>
        </message>
        <message>
            <source>C&amp;ycle Time</source>
            <translation>&amp;Zykluszeit</translation>
        </message>
        <message>
            <source>S&amp;peed</source>
            <translation>&amp;Geschwindigkeit</translation>
        </message>
        <message>
            <source>%1 ms</source>
            <translation>%1 ms</translation>
        </message>
        <message>
            <source>&amp;Real Time</source>
            <translation>&amp;Echtzeit</translation>
        </message>
        <message>
            <source>&amp;10 Times Faster</source>
            <translation>&amp;10-mal schneller</translation>
        </message>
        <message>
            <source>As &amp;Fast as Possible</source>
            <translation>So &amp;schnell wie möglich</translation>
        </message>
        <message>
            <source>The cycle time takes effect at login and at a reset.</source>
            <translation>Die Zykluszeit gilt ab dem Einloggen und nach einem Reset.</translation>
        </message>
        <message>
            <source>Login refused: the project has errors. See the Messages pane.</source>
            <translation>Einloggen abgelehnt: Das Projekt enthält Fehler. Siehe Meldungsfenster.</translation>
        </message>
        <message>
            <source>Logged out.</source>
            <translation>Ausgeloggt.</translation>
        </message>
        <message>
            <source>Run N Cycles</source>
            <translation>N Zyklen ausführen</translation>
        </message>
        <message>
            <source>Number of cycles:</source>
            <translation>Anzahl der Zyklen:</translation>
        </message>
        <message>
            <source>Log in to write values.</source>
            <translation>Zum Schreiben von Werten bitte einloggen.</translation>
        </message>
        <message>
            <source>Log in to force values.</source>
            <translation>Zum Forcen von Werten bitte einloggen.</translation>
        </message>
        <message>
            <source>The new cycle time takes effect at the next reset.</source>
            <translation>Die neue Zykluszeit gilt ab dem nächsten Reset.</translation>
        </message>
        <message>
            <source>Runtime fault in cycle %1: %2 The program stopped; Reset starts it again.</source>
            <translation>Laufzeitfehler in Zyklus %1: %2 Das Programm wurde angehalten; Reset startet es neu.</translation>
        </message>
        <message>
            <source>The program stopped: %1</source>
            <translation>Das Programm wurde angehalten: %1</translation>
        </message>
        <message>
            <source>Offline</source>
            <translation>Offline</translation>
        </message>
        <message>
            <source>real time</source>
            <translation>Echtzeit</translation>
        </message>
        <message>
            <source>10x</source>
            <translation>10-fach</translation>
        </message>
        <message>
            <source>full speed</source>
            <translation>volle Geschwindigkeit</translation>
        </message>
        <message>
            <source>FAULT</source>
            <translation>FEHLER</translation>
        </message>
        <message>
            <source>RUN</source>
            <translation>LÄUFT</translation>
        </message>
        <message>
            <source>STOP</source>
            <translation>GESTOPPT</translation>
        </message>
        <message>
            <source>ONLINE %1 | cycle %2 | t = %3 s | %4 ms, %5</source>
            <translation>ONLINE %1 | Zyklus %2 | t = %3 s | %4 ms, %5</translation>
        </message>
        <message>
            <source> | changed since login</source>
            <translation> | seit dem Einloggen geändert</translation>
        </message>
        <message>
            <source>Logged in. F5 runs the program, Ctrl+F5 runs one cycle. Log out to edit (Online → Logout).</source>
            <translation>Eingeloggt. F5 startet das Programm, Strg+F5 führt einen Zyklus aus. Zum Bearbeiten ausloggen (Online → Ausloggen).</translation>
        </message>
        <message>
            <source>HALT</source>
            <translation>HALT</translation>
        </message>
        <message>
            <source>ONLINE HISTORY | scan %1 of %2 | t = %3 s</source>
            <translation>ONLINE HISTORIE | Zyklus %1 von %2 | t = %3 s</translation>
        </message>
        <message>
            <source>Program log: %1</source>
            <translation>Programmprotokoll: %1</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectDocumentation</name>
        <message>
            <source>program</source>
            <translation>Programm</translation>
        </message>
        <message>
            <source>function block</source>
            <translation>Funktionsbaustein</translation>
        </message>
        <message>
            <source>function</source>
            <translation>Funktion</translation>
        </message>
        <message>
            <source>The body is empty.</source>
            <translation>Der Rumpf ist leer.</translation>
        </message>
        <message>
            <source>The %1 body is drawn in the editor; this version cannot print it as a picture.</source>
            <translation>Der %1-Rumpf wird im Editor gezeichnet; diese Version kann ihn nicht als Bild drucken.</translation>
        </message>
        <message>
            <source>%1 (%2, %3)</source>
            <translation>%1 (%2, %3)</translation>
        </message>
        <message>
            <source>Declarations</source>
            <translation>Deklarationen</translation>
        </message>
        <message>
            <source>Returns %1.</source>
            <translation>Gibt %1 zurück.</translation>
        </message>
        <message>
            <source>No variables.</source>
            <translation>Keine Variablen.</translation>
        </message>
        <message>
            <source>Body</source>
            <translation>Rumpf</translation>
        </message>
        <message>
            <source>Action %1</source>
            <translation>Aktion %1</translation>
        </message>
        <message>
            <source>Transition %1</source>
            <translation>Transition %1</translation>
        </message>
        <message>
            <source>Data types</source>
            <translation>Datentypen</translation>
        </message>
        <message>
            <source>Global variables</source>
            <translation>Globale Variablen</translation>
        </message>
        <message>
            <source>%1 (in %2)</source>
            <translation>%1 (in %2)</translation>
        </message>
        <message>
            <source>Configuration %1</source>
            <translation>Konfiguration %1</translation>
        </message>
        <message>
            <source>Resource %1</source>
            <translation>Ressource %1</translation>
        </message>
        <message>
            <source>No tasks.</source>
            <translation>Keine Tasks.</translation>
        </message>
        <message>
            <source>Task</source>
            <translation>Task</translation>
        </message>
        <message>
            <source>Interval</source>
            <translation>Intervall</translation>
        </message>
        <message>
            <source>SINGLE</source>
            <translation>SINGLE</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>Priorität</translation>
        </message>
        <message>
            <source>Watchdog</source>
            <translation>Watchdog</translation>
        </message>
        <message>
            <source>Programs</source>
            <translation>Programme</translation>
        </message>
        <message>
            <source>Untitled project</source>
            <translation>Unbenanntes Projekt</translation>
        </message>
        <message>
            <source>Project documentation</source>
            <translation>Projektdokumentation</translation>
        </message>
        <message>
            <source>Author: %1</source>
            <translation>Autor: %1</translation>
        </message>
        <message>
            <source>Organization: %1</source>
            <translation>Organisation: %1</translation>
        </message>
        <message>
            <source>Version: %1</source>
            <translation>Version: %1</translation>
        </message>
        <message>
            <source>Printed on %1</source>
            <translation>Gedruckt am %1</translation>
        </message>
        <message>
            <source>Contents</source>
            <translation>Inhalt</translation>
        </message>
        <message>
            <source>The PDF could not be written to %1.</source>
            <translation>Das PDF konnte nicht in %1 geschrieben werden.</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectSearch</name>
        <message>
            <source>The regular expression is not valid: %1.</source>
            <translation>Der reguläre Ausdruck ist ungültig: %1.</translation>
        </message>
        <message>
            <source>declared</source>
            <translation>deklariert</translation>
        </message>
        <message>
            <source>read</source>
            <translation>gelesen</translation>
        </message>
        <message>
            <source>written</source>
            <translation>geschrieben</translation>
        </message>
        <message>
            <source>read and written</source>
            <translation>gelesen und geschrieben</translation>
        </message>
    </context>
    <context>
        <name>iec::app::ProjectTemplates</name>
        <message>
            <source>Empty project</source>
            <translation>Leeres Projekt</translation>
        </message>
        <message>
            <source>Structured Text (ST) program</source>
            <translation>Programm in Strukturiertem Text (ST)</translation>
        </message>
        <message>
            <source>Ladder Diagram (LD) program</source>
            <translation>Programm in Kontaktplan (KOP)</translation>
        </message>
        <message>
            <source>Function Block Diagram (FBD) program</source>
            <translation>Programm in Funktionsbausteinsprache (FUP)</translation>
        </message>
        <message>
            <source>Continuous Function Chart (CFC) program</source>
            <translation>Programm in Freigraphischem Funktionsplan (CFC)</translation>
        </message>
        <message>
            <source>Sequential Function Chart (SFC) program</source>
            <translation>Programm in Ablaufsprache (AS)</translation>
        </message>
        <message>
            <source>Instruction List (IL) program</source>
            <translation>Programm in Anweisungsliste (AWL)</translation>
        </message>
        <message>
            <source>No POUs and no configuration: add what you need from the Project menu.</source>
            <translation>Keine Bausteine und keine Konfiguration: Fügen Sie das Benötigte über das Menü Projekt hinzu.</translation>
        </message>
        <message>
            <source>A program Main, run every 10 ms by the task MainTask of configuration Config.</source>
            <translation>Ein Programm Main, das alle 10 ms von der Task MainTask der Konfiguration Config ausgeführt wird.</translation>
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
            <translation>Dupli&amp;zieren</translation>
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
        <message>
            <source>Add &amp;Global Variable List...</source>
            <translation>&amp;Globale Variablenliste hinzufügen...</translation>
        </message>
        <message>
            <source>Task &amp;Configuration</source>
            <translation>Task&amp;konfiguration</translation>
        </message>
        <message>
            <source>Add Global Variable List</source>
            <translation>Globale Variablenliste hinzufügen</translation>
        </message>
        <message>
            <source>Add &amp;Method...</source>
            <translation>&amp;Methode hinzufügen...</translation>
        </message>
        <message>
            <source>Add Propert&amp;y...</source>
            <translation>&amp;Eigenschaft hinzufügen...</translation>
        </message>
        <message>
            <source>Add Property</source>
            <translation>Eigenschaft hinzufügen</translation>
        </message>
        <message>
            <source>Add Method</source>
            <translation>Methode hinzufügen</translation>
        </message>
        <message>
            <source>Add &amp;Interface...</source>
            <translation>&amp;Schnittstelle hinzufügen...</translation>
        </message>
        <message>
            <source>Add Interface</source>
            <translation>Schnittstelle hinzufügen</translation>
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
        <message>
            <source>Continuous Function Chart (CFC)</source>
            <translation>Freigraphischer Funktionsplan (CFC)</translation>
        </message>
        <message>
            <source>%1 (PROPERTY)</source>
            <translation>%1 (EIGENSCHAFT)</translation>
        </message>
        <message>
            <source>%1 (METHOD)</source>
            <translation>%1 (METHODE)</translation>
        </message>
        <message>
            <source>Edited as text: METHOD ... END_METHOD or PROPERTY ... END_PROPERTY</source>
            <translation>Als Text bearbeitet: METHOD ... END_METHOD oder PROPERTY ... END_PROPERTY</translation>
        </message>
        <message>
            <source>Interfaces</source>
            <translation>Schnittstellen</translation>
        </message>
        <message>
            <source>%1 (ITF)</source>
            <translation>%1 (ITF)</translation>
        </message>
        <message>
            <source>Edited as text: INTERFACE ... END_INTERFACE</source>
            <translation>Als Text bearbeitet: INTERFACE ... END_INTERFACE</translation>
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
        <name>iec::app::RuntimeWorker</name>
        <message>
            <source>There is no variable called %1.</source>
            <translation>Es gibt keine Variable namens %1.</translation>
        </message>
        <message>
            <source>%1: %2</source>
            <translation>%1: %2</translation>
        </message>
    </context>
    <context>
        <name>iec::app::SearchActions</name>
        <message>
            <source>Find in &amp;Project...</source>
            <translation>Im &amp;Projekt suchen...</translation>
        </message>
        <message>
            <source>&amp;Go to Definition</source>
            <translation>&amp;Gehe zur Definition</translation>
        </message>
        <message>
            <source>Cross &amp;References</source>
            <translation>&amp;Querverweisliste</translation>
        </message>
        <message>
            <source>%1 matches of "%2"</source>
            <translation>%1 Treffer für "%2"</translation>
        </message>
        <message>
            <source>Cross references of %1: %2 places</source>
            <translation>Querverweise von %1: %2 Stellen</translation>
        </message>
    </context>
    <context>
        <name>iec::app::SearchResultsPane</name>
        <message>
            <source>declaration</source>
            <translation>Deklaration</translation>
        </message>
        <message>
            <source>element %1</source>
            <translation>Element %1</translation>
        </message>
        <message>
            <source>line %1, column %2</source>
            <translation>Zeile %1, Spalte %2</translation>
        </message>
        <message>
            <source>Place</source>
            <translation>Stelle</translation>
        </message>
        <message>
            <source>Where</source>
            <translation>Ort</translation>
        </message>
        <message>
            <source>Use</source>
            <translation>Zugriff</translation>
        </message>
        <message>
            <source>Text</source>
            <translation>Text</translation>
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
        <name>iec::app::TraceExport</name>
        <message>
            <source>%1 cannot be written: %2</source>
            <translation>%1 kann nicht geschrieben werden: %2</translation>
        </message>
        <message>
            <source>%1 cannot be written.</source>
            <translation>%1 kann nicht geschrieben werden.</translation>
        </message>
        <message>
            <source>Nothing was recorded yet: choose variables, log in and run the program.</source>
            <translation>Noch nichts aufgezeichnet: Variablen wählen, einloggen und das Programm starten.</translation>
        </message>
        <message>
            <source>%1: a trace is exported as .csv, .vcd, .png or .pdf.</source>
            <translation>%1: ein Trace wird als .csv, .vcd, .png oder .pdf exportiert.</translation>
        </message>
    </context>
    <context>
        <name>iec::app::TracePane</name>
        <message>
            <source>Trace</source>
            <translation>Trace</translation>
        </message>
        <message>
            <source>Configure...</source>
            <translation>Konfigurieren...</translation>
        </message>
        <message>
            <source>Choose the variables, the trigger and how often to sample</source>
            <translation>Variablen, Trigger und Abtastrate wählen</translation>
        </message>
        <message>
            <source>Add Variable...</source>
            <translation>Variable hinzufügen...</translation>
        </message>
        <message>
            <source>Pause</source>
            <translation>Pause</translation>
        </message>
        <message>
            <source>Restart</source>
            <translation>Neu starten</translation>
        </message>
        <message>
            <source>Drop the samples and record again (the trigger is armed again)</source>
            <translation>Aufzeichnung verwerfen und neu aufzeichnen (der Trigger wird wieder scharf)</translation>
        </message>
        <message>
            <source>Zoom In</source>
            <translation>Vergrößern</translation>
        </message>
        <message>
            <source>Zoom Out</source>
            <translation>Verkleinern</translation>
        </message>
        <message>
            <source>Fit</source>
            <translation>Einpassen</translation>
        </message>
        <message>
            <source>Show every sample and follow the newest</source>
            <translation>Alle Werte zeigen und den neuesten folgen</translation>
        </message>
        <message>
            <source>Export</source>
            <translation>Exportieren</translation>
        </message>
        <message>
            <source>CSV (spreadsheet)...</source>
            <translation>CSV (Tabellenkalkulation)...</translation>
        </message>
        <message>
            <source>VCD (GTKWave)...</source>
            <translation>VCD (GTKWave)...</translation>
        </message>
        <message>
            <source>PNG picture...</source>
            <translation>PNG-Bild...</translation>
        </message>
        <message>
            <source>PDF for a lab report...</source>
            <translation>PDF für ein Laborprotokoll...</translation>
        </message>
        <message>
            <source>Remove from Trace</source>
            <translation>Aus dem Trace entfernen</translation>
        </message>
        <message>
            <source>Cursor 1</source>
            <translation>Cursor 1</translation>
        </message>
        <message>
            <source>Cursor 2</source>
            <translation>Cursor 2</translation>
        </message>
        <message>
            <source>Difference</source>
            <translation>Differenz</translation>
        </message>
        <message>
            <source>Tick to show a lane, drag to reorder. In the chart: click for cursor 1, Shift+click for cursor 2, wheel to zoom.</source>
            <translation>Ankreuzen zeigt eine Spur, Ziehen ordnet um. Im Diagramm: Klick setzt Cursor 1, Umschalt+Klick Cursor 2, das Mausrad zoomt.</translation>
        </message>
        <message>
            <source>Time (ms)</source>
            <translation>Zeit (ms)</translation>
        </message>
        <message>
            <source>Cycle</source>
            <translation>Zyklus</translation>
        </message>
        <message>
            <source>Nothing to record: choose variables with Configure... or Add Variable...</source>
            <translation>Nichts aufzuzeichnen: Variablen mit Konfigurieren... oder Variable hinzufügen... wählen</translation>
        </message>
        <message numerus="yes">
            <source>%n sample(s)</source>
            <translation>
                <numerusform>%n Wert</numerusform>
                <numerusform>%n Werte</numerusform>
            </translation>
        </message>
        <message>
            <source>Offline: the trace records while you are logged in.</source>
            <translation>Offline: der Trace zeichnet auf, solange Sie eingeloggt sind.</translation>
        </message>
        <message>
            <source>Offline: %1 from the last session.</source>
            <translation>Offline: %1 aus der letzten Sitzung.</translation>
        </message>
        <message>
            <source>The record condition cannot be evaluated: %1</source>
            <translation>Die Aufzeichnungsbedingung kann nicht ausgewertet werden: %1</translation>
        </message>
        <message>
            <source>Recording: %1.</source>
            <translation>Aufzeichnung: %1.</translation>
        </message>
        <message>
            <source>Waiting for the trigger on %1: %2 kept before it.</source>
            <translation>Warte auf den Trigger an %1: %2 davor gespeichert.</translation>
        </message>
        <message>
            <source>Triggered in cycle %1: recording what follows (%2).</source>
            <translation>Ausgelöst in Zyklus %1: zeichnet auf, was folgt (%2).</translation>
        </message>
        <message>
            <source>Triggered in cycle %1: done, %2. Restart arms the trigger again.</source>
            <translation>Ausgelöst in Zyklus %1: fertig, %2. Neu starten macht den Trigger wieder scharf.</translation>
        </message>
        <message>
            <source>Paused: %1.</source>
            <translation>Angehalten: %1.</translation>
        </message>
        <message>
            <source>None of the chosen variables can be recorded (see Messages).</source>
            <translation>Keine der gewählten Variablen kann aufgezeichnet werden (siehe Meldungen).</translation>
        </message>
        <message>
            <source>Add Variable</source>
            <translation>Variable hinzufügen</translation>
        </message>
        <message>
            <source>Variable to trace (e.g. Main.Level or a global):</source>
            <translation>Aufzuzeichnende Variable (z. B. Main.Level oder eine globale):</translation>
        </message>
        <message>
            <source>Trace of %1, %2</source>
            <translation>Trace von %1, %2</translation>
        </message>
        <message>
            <source>the project</source>
            <translation>dem Projekt</translation>
        </message>
        <message>
            <source>CSV files (*.csv)</source>
            <translation>CSV-Dateien (*.csv)</translation>
        </message>
        <message>
            <source>Value change dumps (*.vcd)</source>
            <translation>Value Change Dumps (*.vcd)</translation>
        </message>
        <message>
            <source>PNG pictures (*.png)</source>
            <translation>PNG-Bilder (*.png)</translation>
        </message>
        <message>
            <source>PDF documents (*.pdf)</source>
            <translation>PDF-Dokumente (*.pdf)</translation>
        </message>
        <message>
            <source>Export Trace</source>
            <translation>Trace exportieren</translation>
        </message>
    </context>
    <context>
        <name>iec::app::TraceSettingsDialog</name>
        <message>
            <source>Trace Configuration</source>
            <translation>Trace-Konfiguration</translation>
        </message>
        <message>
            <source>One variable per line, e.g. Main.Level</source>
            <translation>Eine Variable pro Zeile, z. B. Main.Level</translation>
        </message>
        <message>
            <source> cycle(s)</source>
            <translation> Zyklus/Zyklen</translation>
        </message>
        <message>
            <source>None (record all the time)</source>
            <translation>Keiner (immer aufzeichnen)</translation>
        </message>
        <message>
            <source>Rising edge</source>
            <translation>Steigende Flanke</translation>
        </message>
        <message>
            <source>Falling edge</source>
            <translation>Fallende Flanke</translation>
        </message>
        <message>
            <source>Level reached</source>
            <translation>Pegel erreicht</translation>
        </message>
        <message>
            <source>e.g. Main.Start</source>
            <translation>z. B. Main.Start</translation>
        </message>
        <message>
            <source>A BOOL is 1 when TRUE: the level 0.5 triggers on its edges.</source>
            <translation>Ein BOOL ist 1, wenn TRUE: der Pegel 0,5 löst an seinen Flanken aus.</translation>
        </message>
        <message>
            <source>Record only while TRUE, e.g. Main.Running</source>
            <translation>Nur aufzeichnen, solange TRUE, z. B. Main.Running</translation>
        </message>
        <message>
            <source> scans</source>
            <translation> Zyklen</translation>
        </message>
        <message>
            <source>&amp;Variables:</source>
            <translation>&amp;Variablen:</translation>
        </message>
        <message>
            <source>Sample &amp;every:</source>
            <translation>Abtasten &amp;alle:</translation>
        </message>
        <message>
            <source>Samples &amp;kept:</source>
            <translation>&amp;Gespeicherte Werte:</translation>
        </message>
        <message>
            <source>&amp;Trigger:</source>
            <translation>&amp;Trigger:</translation>
        </message>
        <message>
            <source>Trigger v&amp;ariable:</source>
            <translation>Trigger-V&amp;ariable:</translation>
        </message>
        <message>
            <source>Trigger &amp;level:</source>
            <translation>Trigger-&amp;Pegel:</translation>
        </message>
        <message>
            <source>Samples &amp;after the trigger:</source>
            <translation>Werte &amp;nach dem Trigger:</translation>
        </message>
        <message>
            <source>Record &amp;condition:</source>
            <translation>Aufzeichnungs&amp;bedingung:</translation>
        </message>
        <message>
            <source>&amp;Scan history keeps:</source>
            <translation>&amp;Zyklushistorie behält:</translation>
        </message>
        <message>
            <source>The record condition is not an expression: %1</source>
            <translation>Die Aufzeichnungsbedingung ist kein Ausdruck: %1</translation>
        </message>
        <message>
            <source>Name the variable that triggers the recording.</source>
            <translation>Geben Sie die Variable an, die die Aufzeichnung auslöst.</translation>
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
        <name>iec::app::WatchModel</name>
        <message>
            <source>(no such variable)</source>
            <translation>(keine solche Variable)</translation>
        </message>
        <message>
            <source>%1 (forced)</source>
            <translation>%1 (geforct)</translation>
        </message>
        <message>
            <source>Type the value to write or force, then choose Write or Force.</source>
            <translation>Den zu schreibenden oder zu forcenden Wert eingeben, dann Schreiben oder Forcen wählen.</translation>
        </message>
        <message>
            <source>Expression</source>
            <translation>Ausdruck</translation>
        </message>
        <message>
            <source>Type</source>
            <translation>Typ</translation>
        </message>
        <message>
            <source>Value</source>
            <translation>Wert</translation>
        </message>
        <message>
            <source>Prepared value</source>
            <translation>Vorbereiteter Wert</translation>
        </message>
        <message>
            <source>Value after scan %1 (history)</source>
            <translation>Wert nach Zyklus %1 (Historie)</translation>
        </message>
    </context>
    <context>
        <name>iec::app::WatchPane</name>
        <message>
            <source>Variable to watch, e.g. Main.Counter</source>
            <translation>Zu beobachtende Variable, z. B. Main.Counter</translation>
        </message>
        <message>
            <source>Add</source>
            <translation>Hinzufügen</translation>
        </message>
        <message>
            <source>Write</source>
            <translation>Schreiben</translation>
        </message>
        <message>
            <source>Write the prepared values once, at the start of the next cycle (Ctrl+F7)</source>
            <translation>Die vorbereiteten Werte einmal zu Beginn des nächsten Zyklus schreiben (Strg+F7)</translation>
        </message>
        <message>
            <source>Force</source>
            <translation>Forcen</translation>
        </message>
        <message>
            <source>Hold the prepared values every cycle until released (F7)</source>
            <translation>Die vorbereiteten Werte in jedem Zyklus halten, bis sie aufgehoben werden (F7)</translation>
        </message>
        <message>
            <source>Release</source>
            <translation>Aufheben</translation>
        </message>
        <message>
            <source>Release the forces of the selected variables (Alt+F7)</source>
            <translation>Forcen der ausgewählten Variablen aufheben (Alt+F7)</translation>
        </message>
        <message>
            <source>Release All</source>
            <translation>Alle aufheben</translation>
        </message>
        <message>
            <source>Remove</source>
            <translation>Entfernen</translation>
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
        <name>iec::editors</name>
        <message>
            <source>There is nothing to paste.</source>
            <translation>Es gibt nichts einzufügen.</translation>
        </message>
        <message>
            <source>The clipboard holds text, not %1 elements: nothing was pasted.</source>
            <translation>Die Zwischenablage enthält Text, keine %1-Elemente: Es wurde nichts eingefügt.</translation>
        </message>
        <message>
            <source>The clipboard holds no %1 elements that can be pasted. %2</source>
            <translation>Die Zwischenablage enthält keine %1-Elemente, die eingefügt werden können. %2</translation>
        </message>
        <message>
            <source>The clipboard holds %1 elements, which cannot be pasted into %2.</source>
            <translation>Die Zwischenablage enthält %1-Elemente, die nicht in %2 eingefügt werden können.</translation>
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
        <message>
            <source>Add to Watch</source>
            <translation>Zur Beobachtung hinzufügen</translation>
        </message>
        <message>
            <source>The program is online, so its text cannot be changed. Choose Online &gt; Logout to edit it.</source>
            <translation>Das Programm ist online, daher kann sein Text nicht geändert werden. Zum Bearbeiten Online &gt; Ausloggen wählen.</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::ConfigurationEditor</name>
        <message>
            <source>Configuration %1</source>
            <translation>Konfiguration %1</translation>
        </message>
        <message>
            <source>Resource:</source>
            <translation>Ressource:</translation>
        </message>
        <message>
            <source>Resource name</source>
            <translation>Name der Ressource</translation>
        </message>
        <message>
            <source>Add Resource</source>
            <translation>Ressource hinzufügen</translation>
        </message>
        <message>
            <source>Remove Resource</source>
            <translation>Ressource entfernen</translation>
        </message>
        <message>
            <source>Tasks (the lower the priority number, the earlier the task runs)</source>
            <translation>Tasks (je kleiner die Prioritätszahl, desto früher läuft die Task)</translation>
        </message>
        <message>
            <source>Task</source>
            <translation>Task</translation>
        </message>
        <message>
            <source>Interval (cyclic)</source>
            <translation>Intervall (zyklisch)</translation>
        </message>
        <message>
            <source>SINGLE (event variable)</source>
            <translation>SINGLE (Ereignisvariable)</translation>
        </message>
        <message>
            <source>Priority</source>
            <translation>Priorität</translation>
        </message>
        <message>
            <source>Watchdog</source>
            <translation>Watchdog</translation>
        </message>
        <message>
            <source>The task's name, unique in the configuration.</source>
            <translation>Der Name der Task, eindeutig in der Konfiguration.</translation>
        </message>
        <message>
            <source>The task runs every interval (T#10ms). With neither an interval nor a SINGLE variable it runs in every cycle (CODESYS: freewheeling).</source>
            <translation>Die Task läuft in jedem Intervall (T#10ms). Ohne Intervall und ohne SINGLE-Variable läuft sie in jedem Zyklus (CODESYS: freilaufend).</translation>
        </message>
        <message>
            <source>A global BOOL variable: the task runs once each time it becomes TRUE (CODESYS: triggered by event).</source>
            <translation>Eine globale BOOL-Variable: Die Task läuft jedes Mal einmal, wenn sie TRUE wird (CODESYS: ereignisgesteuert).</translation>
        </message>
        <message>
            <source>0 is the highest priority; tasks due in the same cycle run in the order of their priorities.</source>
            <translation>0 ist die höchste Priorität; Tasks, die im selben Zyklus fällig sind, laufen in der Reihenfolge ihrer Prioritäten.</translation>
        </message>
        <message>
            <source>The longest time one run of the task may take (T#50ms); empty for none. It is kept in the project for the target; the simulator does not check it.</source>
            <translation>Die längste Zeit, die ein Durchlauf der Task dauern darf (T#50ms); leer für keine. Sie wird im Projekt für das Zielsystem gespeichert; der Simulator prüft sie nicht.</translation>
        </message>
        <message>
            <source>Instance</source>
            <translation>Instanz</translation>
        </message>
        <message>
            <source>Program</source>
            <translation>Programm</translation>
        </message>
        <message>
            <source>Global variable lists of the resource (double-click opens one)</source>
            <translation>Globale Variablenlisten der Ressource (Doppelklick öffnet eine)</translation>
        </message>
        <message>
            <source>Add List...</source>
            <translation>Liste hinzufügen...</translation>
        </message>
        <message>
            <source>Programs run by task %1</source>
            <translation>Von Task %1 ausgeführte Programme</translation>
        </message>
        <message>
            <source>Programs run by the task</source>
            <translation>Von der Task ausgeführte Programme</translation>
        </message>
        <message>
            <source>Change tasks of %1</source>
            <translation>Tasks von %1 ändern</translation>
        </message>
        <message>
            <source>Change programs of task %1</source>
            <translation>Programme der Task %1 ändern</translation>
        </message>
        <message>
            <source>Rename resource %1 to %2</source>
            <translation>Ressource %1 in %2 umbenennen</translation>
        </message>
        <message>
            <source>Add resource %1</source>
            <translation>Ressource %1 hinzufügen</translation>
        </message>
        <message>
            <source>Remove resource %1</source>
            <translation>Ressource %1 entfernen</translation>
        </message>
        <message>
            <source>Resource %1: %2</source>
            <translation>Ressource %1: %2</translation>
        </message>
        <message>
            <source>Task %1: %2</source>
            <translation>Task %1: %2</translation>
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
        <message>
            <source>Rename member %1 to %2</source>
            <translation>Komponente %1 in %2 umbenennen</translation>
        </message>
        <message numerus="yes">
            <source>Rename %n member(s)</source>
            <translation>
                <numerusform>%n Komponente umbenennen</numerusform>
                <numerusform>%n Komponenten umbenennen</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DataTypeValidator</name>
        <message>
            <source>A POU or data type named "%1" exists already.</source>
            <translation>Ein Baustein oder Datentyp namens "%1" existiert bereits.</translation>
        </message>
        <message>
            <source>A structure needs at least one member.</source>
            <translation>Eine Struktur braucht mindestens ein Element.</translation>
        </message>
        <message>
            <source>There is a member named "%1" already.</source>
            <translation>Es gibt bereits ein Element namens "%1".</translation>
        </message>
        <message>
            <source>An enumeration needs at least one value.</source>
            <translation>Eine Aufzählung braucht mindestens einen Wert.</translation>
        </message>
        <message>
            <source>The value "%1" is listed already.</source>
            <translation>Der Wert "%1" ist bereits aufgeführt.</translation>
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
            <source>"%1" is not a type.</source>
            <translation>"%1" ist kein Typ.</translation>
        </message>
        <message>
            <source>A type cannot contain itself.</source>
            <translation>Ein Typ kann sich nicht selbst enthalten.</translation>
        </message>
        <message>
            <source>Unknown type "%1".</source>
            <translation>Unbekannter Typ "%1".</translation>
        </message>
        <message>
            <source>"%1" is not a valid initial value.</source>
            <translation>"%1" ist kein gültiger Initialwert.</translation>
        </message>
        <message>
            <source>Enter a name.</source>
            <translation>Geben Sie einen Namen ein.</translation>
        </message>
        <message>
            <source>"%1" is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an underscore and not ending with an underscore.</source>
            <translation>"%1" ist kein IEC-Bezeichner: verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche; am Anfang ein Buchstabe oder Unterstrich, am Ende kein Unterstrich.</translation>
        </message>
        <message>
            <source>"%1" is a reserved word of IEC 61131-3.</source>
            <translation>"%1" ist ein reserviertes Wort der IEC 61131-3.</translation>
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
        <message>
            <source>Rename variable %1 to %2</source>
            <translation>Variable %1 in %2 umbenennen</translation>
        </message>
        <message numerus="yes">
            <source>Rename %n variable(s)</source>
            <translation>
                <numerusform>%n Variable umbenennen</numerusform>
                <numerusform>%n Variablen umbenennen</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DeclarationRows</name>
        <message>
            <source>"%1" is not a variable class.</source>
            <translation>"%1" ist keine Variablenklasse.</translation>
        </message>
        <message>
            <source>"%1" is not a data type.</source>
            <translation>"%1" ist kein Datentyp.</translation>
        </message>
        <message>
            <source>"%1" is not an initial value for %2.</source>
            <translation>"%1" ist kein Initialwert für %2.</translation>
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
            <source>"%1" is not a valid name: use letters, digits and single underscores, and no keyword.</source>
            <translation>"%1" ist kein gültiger Name: verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche, und kein Schlüsselwort.</translation>
        </message>
        <message>
            <source>"%1" is not an address such as %IX0.0, %QW3 or %MD10.</source>
            <translation>"%1" ist keine Adresse wie %IX0.0, %QW3 oder %MD10.</translation>
        </message>
        <message>
            <source>%1 is declared twice.</source>
            <translation>%1 ist zweimal deklariert.</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DiagramEditor</name>
        <message>
            <source>Zoom In</source>
            <translation>Vergrößern</translation>
        </message>
        <message>
            <source>Zoom Out</source>
            <translation>Verkleinern</translation>
        </message>
        <message>
            <source>Fit to Window</source>
            <translation>An Fenster anpassen</translation>
        </message>
        <message>
            <source>Export Picture…</source>
            <translation>Bild exportieren…</translation>
        </message>
        <message>
            <source>Print…</source>
            <translation>Drucken…</translation>
        </message>
        <message>
            <source>The diagram cannot be changed while online. Log out first (Online → Logout).</source>
            <translation>Im Online-Betrieb kann das Diagramm nicht geändert werden. Zuerst ausloggen (Online → Ausloggen).</translation>
        </message>
        <message>
            <source>This body cannot be edited here.</source>
            <translation>Dieser Rumpf kann hier nicht bearbeitet werden.</translation>
        </message>
        <message>
            <source>Export Picture</source>
            <translation>Bild exportieren</translation>
        </message>
        <message>
            <source>SVG picture (*.svg);;PNG picture (*.png);;PDF document (*.pdf)</source>
            <translation>SVG-Bild (*.svg);;PNG-Bild (*.png);;PDF-Dokument (*.pdf)</translation>
        </message>
        <message>
            <source>Zoom 100 %</source>
            <translation>Zoom 100 %</translation>
        </message>
        <message>
            <source>Export…</source>
            <translation>Exportieren…</translation>
        </message>
        <message>
            <source>Zoom +</source>
            <translation>Zoom +</translation>
        </message>
        <message>
            <source>Zoom −</source>
            <translation>Zoom −</translation>
        </message>
        <message>
            <source>Fit</source>
            <translation>Einpassen</translation>
        </message>
        <message>
            <source>Prepare Value</source>
            <translation>Wert vorbereiten</translation>
        </message>
        <message>
            <source>New value of %1 (now %2):</source>
            <translation>Neuer Wert für %1 (jetzt %2):</translation>
        </message>
        <message>
            <source>Prepared %1 := %2. Write it with Ctrl+F7 or force it with F7.</source>
            <translation>%1 := %2 vorbereitet. Mit Strg+F7 schreiben oder mit F7 forcen.</translation>
        </message>
        <message>
            <source>network %1</source>
            <translation>Netzwerk %1</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::DiagramExport</name>
        <message>
            <source>Cannot write %1.</source>
            <translation>%1 kann nicht geschrieben werden.</translation>
        </message>
        <message>
            <source>Unknown picture type '%1': use .svg, .png or .pdf.</source>
            <translation>Unbekannter Bildtyp '%1': Verwenden Sie .svg, .png oder .pdf.</translation>
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
        <name>iec::editors::GlobalListEditor</name>
        <message>
            <source>Change global variable list %1</source>
            <translation>Globale Variablenliste %1 ändern</translation>
        </message>
        <message>
            <source>Rename global variable %1 to %2</source>
            <translation>Globale Variable %1 in %2 umbenennen</translation>
        </message>
        <message numerus="yes">
            <source>Rename %n global variable(s)</source>
            <translation>
                <numerusform>%n globale Variable umbenennen</numerusform>
                <numerusform>%n globale Variablen umbenennen</numerusform>
            </translation>
        </message>
        <message>
            <source>A global variable list holds VAR_GLOBAL sections only; %1 belongs in a POU.</source>
            <translation>Eine globale Variablenliste enthält nur VAR_GLOBAL-Abschnitte; %1 gehört in einen Baustein.</translation>
        </message>
        <message>
            <source>%1 is declared in the global variable list %2 already.</source>
            <translation>%1 ist bereits in der globalen Variablenliste %2 deklariert.</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::InPlaceEditor</name>
        <message>
            <source>Enter applies, Esc cancels, F2 opens the input assistant.</source>
            <translation>Eingabe übernimmt, Esc bricht ab, F2 öffnet die Eingabehilfe.</translation>
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
        <name>iec::editors::NetworkDialogs</name>
        <message>
            <source>Network Label</source>
            <translation>Netzwerkmarke</translation>
        </message>
        <message>
            <source>Label of network %1 (empty: none):</source>
            <translation>Marke von Netzwerk %1 (leer: keine):</translation>
        </message>
        <message>
            <source>Network Comment</source>
            <translation>Netzwerkkommentar</translation>
        </message>
        <message>
            <source>Comment of network %1:</source>
            <translation>Kommentar von Netzwerk %1:</translation>
        </message>
        <message>
            <source>Jump</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <source>Jump to the network with the label:</source>
            <translation>Sprung zum Netzwerk mit der Marke:</translation>
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
        <message>
            <source>Adds the inputs.</source>
            <translation>Addiert die Eingänge.</translation>
        </message>
        <message>
            <source>Subtracts IN2 from IN1.</source>
            <translation>Subtrahiert IN2 von IN1.</translation>
        </message>
        <message>
            <source>Multiplies the inputs.</source>
            <translation>Multipliziert die Eingänge.</translation>
        </message>
        <message>
            <source>Divides IN1 by IN2.</source>
            <translation>Dividiert IN1 durch IN2.</translation>
        </message>
        <message>
            <source>The remainder of IN1 divided by IN2.</source>
            <translation>Der Rest von IN1 geteilt durch IN2.</translation>
        </message>
        <message>
            <source>Copies the input to the output.</source>
            <translation>Kopiert den Eingang auf den Ausgang.</translation>
        </message>
        <message>
            <source>IN1 raised to the power IN2.</source>
            <translation>IN1 hoch IN2.</translation>
        </message>
        <message>
            <source>The absolute value.</source>
            <translation>Der Absolutwert.</translation>
        </message>
        <message>
            <source>The square root.</source>
            <translation>Die Quadratwurzel.</translation>
        </message>
        <message>
            <source>The natural logarithm.</source>
            <translation>Der natürliche Logarithmus.</translation>
        </message>
        <message>
            <source>The logarithm to base 10.</source>
            <translation>Der Logarithmus zur Basis 10.</translation>
        </message>
        <message>
            <source>e raised to the power IN.</source>
            <translation>e hoch IN.</translation>
        </message>
        <message>
            <source>The sine (IN in radians).</source>
            <translation>Der Sinus (IN im Bogenmaß).</translation>
        </message>
        <message>
            <source>The cosine (IN in radians).</source>
            <translation>Der Kosinus (IN im Bogenmaß).</translation>
        </message>
        <message>
            <source>The tangent (IN in radians).</source>
            <translation>Der Tangens (IN im Bogenmaß).</translation>
        </message>
        <message>
            <source>The arc sine, in radians.</source>
            <translation>Der Arkussinus, im Bogenmaß.</translation>
        </message>
        <message>
            <source>The arc cosine, in radians.</source>
            <translation>Der Arkuskosinus, im Bogenmaß.</translation>
        </message>
        <message>
            <source>The arc tangent, in radians.</source>
            <translation>Der Arkustangens, im Bogenmaß.</translation>
        </message>
        <message>
            <source>The whole-number part of a REAL.</source>
            <translation>Der ganzzahlige Anteil eines REAL.</translation>
        </message>
        <message>
            <source>Shifts the bits N places to the left.</source>
            <translation>Schiebt die Bits um N Stellen nach links.</translation>
        </message>
        <message>
            <source>Shifts the bits N places to the right.</source>
            <translation>Schiebt die Bits um N Stellen nach rechts.</translation>
        </message>
        <message>
            <source>Rotates the bits N places to the left.</source>
            <translation>Rotiert die Bits um N Stellen nach links.</translation>
        </message>
        <message>
            <source>Rotates the bits N places to the right.</source>
            <translation>Rotiert die Bits um N Stellen nach rechts.</translation>
        </message>
        <message>
            <source>IN0 when G is FALSE, IN1 when G is TRUE.</source>
            <translation>IN0, wenn G FALSE ist, IN1, wenn G TRUE ist.</translation>
        </message>
        <message>
            <source>The larger input.</source>
            <translation>Der größere Eingang.</translation>
        </message>
        <message>
            <source>The smaller input.</source>
            <translation>Der kleinere Eingang.</translation>
        </message>
        <message>
            <source>IN limited to the range MN..MX.</source>
            <translation>IN, begrenzt auf den Bereich MN..MX.</translation>
        </message>
        <message>
            <source>Input number K (IN0, IN1, ...).</source>
            <translation>Eingang Nummer K (IN0, IN1, ...).</translation>
        </message>
        <message>
            <source>TRUE when IN1 &gt; IN2.</source>
            <translation>TRUE, wenn IN1 &gt; IN2.</translation>
        </message>
        <message>
            <source>TRUE when IN1 &gt;= IN2.</source>
            <translation>TRUE, wenn IN1 &gt;= IN2.</translation>
        </message>
        <message>
            <source>TRUE when IN1 = IN2.</source>
            <translation>TRUE, wenn IN1 = IN2.</translation>
        </message>
        <message>
            <source>TRUE when IN1 &lt;&gt; IN2.</source>
            <translation>TRUE, wenn IN1 &lt;&gt; IN2.</translation>
        </message>
        <message>
            <source>TRUE when IN1 &lt;= IN2.</source>
            <translation>TRUE, wenn IN1 &lt;= IN2.</translation>
        </message>
        <message>
            <source>TRUE when IN1 &lt; IN2.</source>
            <translation>TRUE, wenn IN1 &lt; IN2.</translation>
        </message>
        <message>
            <source>The number of characters of STR.</source>
            <translation>Die Anzahl der Zeichen von STR.</translation>
        </message>
        <message>
            <source>The first SIZE characters of STR.</source>
            <translation>Die ersten SIZE Zeichen von STR.</translation>
        </message>
        <message>
            <source>The last SIZE characters of STR.</source>
            <translation>Die letzten SIZE Zeichen von STR.</translation>
        </message>
        <message>
            <source>LEN characters of STR from position POS.</source>
            <translation>LEN Zeichen von STR ab Position POS.</translation>
        </message>
        <message>
            <source>STR1 followed by STR2.</source>
            <translation>STR1, gefolgt von STR2.</translation>
        </message>
        <message>
            <source>STR2 inserted into STR1 after position POS.</source>
            <translation>STR2, in STR1 nach Position POS eingefügt.</translation>
        </message>
        <message>
            <source>STR without LEN characters from position POS.</source>
            <translation>STR ohne LEN Zeichen ab Position POS.</translation>
        </message>
        <message>
            <source>STR1 with L characters from position P replaced by STR2.</source>
            <translation>STR1, in dem L Zeichen ab Position P durch STR2 ersetzt sind.</translation>
        </message>
        <message>
            <source>The position of STR2 in STR1 (0: not found).</source>
            <translation>Die Position von STR2 in STR1 (0: nicht gefunden).</translation>
        </message>
        <message>
            <source>Bistable, set dominant: Q1 stays TRUE from SET1 until RESET.</source>
            <translation>Bistabil, setzdominant: Q1 bleibt von SET1 bis RESET TRUE.</translation>
        </message>
        <message>
            <source>Bistable, reset dominant: Q1 stays TRUE from SET until RESET1.</source>
            <translation>Bistabil, rücksetzdominant: Q1 bleibt von SET bis RESET1 TRUE.</translation>
        </message>
        <message>
            <source>Q is TRUE for one cycle when CLK rises.</source>
            <translation>Q ist für einen Zyklus TRUE, wenn CLK steigt.</translation>
        </message>
        <message>
            <source>Q is TRUE for one cycle when CLK falls.</source>
            <translation>Q ist für einen Zyklus TRUE, wenn CLK fällt.</translation>
        </message>
        <message>
            <source>Counts rising edges of CU up; Q when CV reaches PV.</source>
            <translation>Zählt steigende Flanken von CU aufwärts; Q, wenn CV PV erreicht.</translation>
        </message>
        <message>
            <source>Counts rising edges of CD down from PV; Q when CV reaches 0.</source>
            <translation>Zählt steigende Flanken von CD ab PV abwärts; Q, wenn CV 0 erreicht.</translation>
        </message>
        <message>
            <source>Counts up (CU) and down (CD); QU when CV reaches PV, QD at 0.</source>
            <translation>Zählt aufwärts (CU) und abwärts (CD); QU, wenn CV PV erreicht, QD bei 0.</translation>
        </message>
        <message>
            <source>Pulse: Q is TRUE for PT after IN rises.</source>
            <translation>Impuls: Q ist für PT TRUE, nachdem IN steigt.</translation>
        </message>
        <message>
            <source>On delay: Q follows IN after it was TRUE for PT.</source>
            <translation>Einschaltverzögerung: Q folgt IN, nachdem es für PT TRUE war.</translation>
        </message>
        <message>
            <source>Off delay: Q stays TRUE for PT after IN falls.</source>
            <translation>Ausschaltverzögerung: Q bleibt für PT TRUE, nachdem IN fällt.</translation>
        </message>
        <message>
            <source>Converts %1 to %2.</source>
            <translation>Wandelt %1 in %2 um.</translation>
        </message>
        <message>
            <source>BCD conversion</source>
            <translation>BCD-Konvertierung</translation>
        </message>
        <message>
            <source>Bit and byte functions</source>
            <translation>Bit-/Byte-Funktionen</translation>
        </message>
        <message>
            <source>Mathematical helpers</source>
            <translation>Mathematische Hilfsfunktionen</translation>
        </message>
        <message>
            <source>Controllers</source>
            <translation>Regler</translation>
        </message>
        <message>
            <source>Signal generators</source>
            <translation>Signalgeneratoren</translation>
        </message>
        <message>
            <source>Function manipulators</source>
            <translation>Funktionsmanipulatoren</translation>
        </message>
        <message>
            <source>Analog values</source>
            <translation>Analogwertverarbeitung</translation>
        </message>
        <message>
            <source>Messages</source>
            <translation>Meldungen</translation>
        </message>
        <message>
            <source>The two BCD digits of B as a number; -1 when a digit is not 0 to 9.</source>
            <translation>Die zwei BCD-Ziffern von B als Zahl; -1, wenn eine Ziffer nicht 0 bis 9 ist.</translation>
        </message>
        <message>
            <source>I as two BCD digits; 255 when I is not 0 to 99.</source>
            <translation>I als zwei BCD-Ziffern; 255, wenn I nicht 0 bis 99 ist.</translation>
        </message>
        <message>
            <source>Bit N of X (bit 0 first).</source>
            <translation>Bit N von X (Bit 0 zuerst).</translation>
        </message>
        <message>
            <source>The eight inputs as the bits of a byte, B0 lowest.</source>
            <translation>Die acht Eingänge als Bits eines Bytes, B0 als niedrigstes.</translation>
        </message>
        <message>
            <source>X with bit N set to B.</source>
            <translation>X, mit Bit N auf B gesetzt.</translation>
        </message>
        <message>
            <source>The eight bits of B as outputs B0 to B7.</source>
            <translation>Die acht Bits von B als Ausgänge B0 bis B7.</translation>
        </message>
        <message>
            <source>The slope of IN per second; TM is the time since the last call in ms.</source>
            <translation>Die Steigung von IN pro Sekunde; TM ist die Zeit seit dem letzten Aufruf in ms.</translation>
        </message>
        <message>
            <source>Sums IN over time; TM is the time since the last call in ms.</source>
            <translation>Summiert IN über die Zeit; TM ist die Zeit seit dem letzten Aufruf in ms.</translation>
        </message>
        <message>
            <source>Maps IN linearly from IN_MIN..IN_MAX to OUT_MIN..OUT_MAX.</source>
            <translation>Bildet IN linear von IN_MIN..IN_MAX auf OUT_MIN..OUT_MAX ab.</translation>
        </message>
        <message>
            <source>Minimum, maximum and average of the INT values since RESET.</source>
            <translation>Minimum, Maximum und Mittelwert der INT-Werte seit RESET.</translation>
        </message>
        <message>
            <source>Minimum, maximum and average of the REAL values since RESET.</source>
            <translation>Minimum, Maximum und Mittelwert der REAL-Werte seit RESET.</translation>
        </message>
        <message>
            <source>The variance of the values since RESET.</source>
            <translation>Die Varianz der Werte seit RESET.</translation>
        </message>
        <message>
            <source>PD controller: Y from the error SET_POINT - ACTUAL.</source>
            <translation>PD-Regler: Y aus der Regelabweichung SET_POINT - ACTUAL.</translation>
        </message>
        <message>
            <source>PID controller: Y from the error SET_POINT - ACTUAL.</source>
            <translation>PID-Regler: Y aus der Regelabweichung SET_POINT - ACTUAL.</translation>
        </message>
        <message>
            <source>PID controller for a fixed cycle of CYCLE seconds.</source>
            <translation>PID-Regler für einen festen Zyklus von CYCLE Sekunden.</translation>
        </message>
        <message>
            <source>While ENABLE, OUT is TRUE for TIMEHIGH, then FALSE for TIMELOW, and so on.</source>
            <translation>Solange ENABLE, ist OUT für TIMEHIGH TRUE, dann für TIMELOW FALSE, und so fort.</translation>
        </message>
        <message>
            <source>A periodic signal of the shape MODE (triangle, sawtooth, rectangle, sine).</source>
            <translation>Ein periodisches Signal der Form MODE (Dreieck, Sägezahn, Rechteck, Sinus).</translation>
        </message>
        <message>
            <source>OUT on the characteristic curve through the points P.</source>
            <translation>OUT auf der Kennlinie durch die Punkte P.</translation>
        </message>
        <message>
            <source>OUT follows IN, rising by ASCEND and falling by DESCEND at most per TIMEBASE.</source>
            <translation>OUT folgt IN und steigt um höchstens ASCEND bzw. fällt um höchstens DESCEND pro TIMEBASE.</translation>
        </message>
        <message>
            <source>OUT becomes TRUE below LOW and FALSE above HIGH.</source>
            <translation>OUT wird unterhalb von LOW TRUE und oberhalb von HIGH FALSE.</translation>
        </message>
        <message>
            <source>O when IN is above HIGH, U when below LOW, IL when in between.</source>
            <translation>O, wenn IN über HIGH liegt, U, wenn unter LOW, IL dazwischen.</translation>
        </message>
        <message>
            <source>Real-time clock: CDT runs on from PDT while IN is TRUE.</source>
            <translation>Echtzeituhr: CDT läuft ab PDT weiter, solange IN TRUE ist.</translation>
        </message>
        <message>
            <source>On a rising edge of TRIG, writes MSG to the messages pane.</source>
            <translation>Schreibt bei einer steigenden Flanke von TRIG MSG in das Meldungsfenster.</translation>
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
        <name>iec::editors::TaskRows</name>
        <message>
            <source>"%1" is not a time such as T#10ms, T#1s or 20ms.</source>
            <translation>"%1" ist keine Zeit wie T#10ms, T#1s oder 20ms.</translation>
        </message>
        <message>
            <source>Enter a name.</source>
            <translation>Geben Sie einen Namen ein.</translation>
        </message>
        <message>
            <source>"%1" is not a valid name: use letters, digits and single underscores.</source>
            <translation>"%1" ist kein gültiger Name: Verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche.</translation>
        </message>
        <message>
            <source>A cyclic task needs an interval above 0; leave it empty for a task started by its SINGLE variable.</source>
            <translation>Eine zyklische Task braucht ein Intervall über 0; lassen Sie es leer für eine Task, die von ihrer SINGLE-Variable gestartet wird.</translation>
        </message>
        <message>
            <source>There is no global BOOL variable %1 in this configuration.</source>
            <translation>In dieser Konfiguration gibt es keine globale BOOL-Variable %1.</translation>
        </message>
        <message>
            <source>A task runs either every interval or when its SINGLE variable becomes TRUE: clear the interval or the SINGLE variable.</source>
            <translation>Eine Task läuft entweder in jedem Intervall oder wenn ihre SINGLE-Variable TRUE wird: Leeren Sie das Intervall oder die SINGLE-Variable.</translation>
        </message>
        <message>
            <source>A watchdog time must be above 0; leave it empty for none.</source>
            <translation>Eine Watchdog-Zeit muss über 0 liegen; lassen Sie sie leer für keine.</translation>
        </message>
        <message>
            <source>"%1" is not a priority: use a whole number from 0 (highest) to 65535.</source>
            <translation>"%1" ist keine Priorität: Verwenden Sie eine ganze Zahl von 0 (höchste) bis 65535.</translation>
        </message>
        <message>
            <source>There is another resource named %1.</source>
            <translation>Es gibt bereits eine Ressource namens %1.</translation>
        </message>
        <message>
            <source>There is another task named %1.</source>
            <translation>Es gibt bereits eine Task namens %1.</translation>
        </message>
        <message>
            <source>There is another program instance named %1.</source>
            <translation>Es gibt bereits eine Programminstanz namens %1.</translation>
        </message>
        <message>
            <source>There is no program called %1.</source>
            <translation>Es gibt kein Programm namens %1.</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::TextEditorWidget</name>
        <message>
            <source>Online: %1, cycle %2</source>
            <translation>Online: %1, Zyklus %2</translation>
        </message>
        <message>
            <source>no instance</source>
            <translation>keine Instanz</translation>
        </message>
        <message>
            <source>&amp;Operator...</source>
            <translation>&amp;Operator...</translation>
        </message>
        <message>
            <source>O&amp;perand...</source>
            <translation>O&amp;perand...</translation>
        </message>
        <message>
            <source>&amp;Function...</source>
            <translation>&amp;Funktion...</translation>
        </message>
        <message>
            <source>Function &amp;Block...</source>
            <translation>Funktions&amp;baustein...</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::cfc</name>
        <message>
            <source>There is nothing to paste.</source>
            <translation>Es gibt nichts einzufügen.</translation>
        </message>
        <message>
            <source>Select the elements to delete first.</source>
            <translation>Wählen Sie zuerst die Elemente aus, die gelöscht werden sollen.</translation>
        </message>
        <message>
            <source>Select the elements to move first.</source>
            <translation>Wählen Sie zuerst die Elemente aus, die verschoben werden sollen.</translation>
        </message>
        <message>
            <source>The wire has no element at one of its ends.</source>
            <translation>An einem Ende der Verbindung ist kein Element.</translation>
        </message>
        <message>
            <source>That element has no such output.</source>
            <translation>Dieses Element hat keinen solchen Ausgang.</translation>
        </message>
        <message>
            <source>That element has no such input.</source>
            <translation>Dieses Element hat keinen solchen Eingang.</translation>
        </message>
        <message>
            <source>Select an element that has an execution order number (a box, an output, a jump, a return or a label).</source>
            <translation>Wählen Sie ein Element mit einer Ausführungsreihenfolge aus (einen Baustein, einen Ausgang, einen Sprung, einen Rücksprung oder eine Marke).</translation>
        </message>
        <message>
            <source>Only boxes, outputs, jumps, returns and labels have an execution order number.</source>
            <translation>Nur Bausteine, Ausgänge, Sprünge, Rücksprünge und Marken haben eine Nummer in der Ausführungsreihenfolge.</translation>
        </message>
        <message>
            <source>The number must lie between 1 and %1.</source>
            <translation>Die Nummer muss zwischen 1 und %1 liegen.</translation>
        </message>
        <message>
            <source>The box is gone.</source>
            <translation>Der Baustein ist nicht mehr da.</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::cfc::CfcEditor</name>
        <message>
            <source>This CFC diagram cannot be shown: %1</source>
            <translation>Dieser CFC-Plan kann nicht angezeigt werden: %1</translation>
        </message>
        <message>
            <source>Move</source>
            <translation>Verschieben</translation>
        </message>
        <message>
            <source>Connect</source>
            <translation>Verbinden</translation>
        </message>
        <message>
            <source>Insert %1</source>
            <translation>%1 einfügen</translation>
        </message>
        <message>
            <source>Insert input</source>
            <translation>Eingang einfügen</translation>
        </message>
        <message>
            <source>Insert output</source>
            <translation>Ausgang einfügen</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>Sprung einfügen</translation>
        </message>
        <message>
            <source>Insert label</source>
            <translation>Marke einfügen</translation>
        </message>
        <message>
            <source>Insert return</source>
            <translation>Rücksprung einfügen</translation>
        </message>
        <message>
            <source>Insert comment</source>
            <translation>Kommentar einfügen</translation>
        </message>
        <message>
            <source>Insert connection mark</source>
            <translation>Verbindungsmarke einfügen</translation>
        </message>
        <message>
            <source>Rename</source>
            <translation>Umbenennen</translation>
        </message>
        <message>
            <source>The element is gone.</source>
            <translation>Das Element gibt es nicht mehr.</translation>
        </message>
        <message>
            <source>Change box to %1</source>
            <translation>Baustein in %1 ändern</translation>
        </message>
        <message>
            <source>Negate</source>
            <translation>Negieren</translation>
        </message>
        <message>
            <source>Select an input or an output to negate.</source>
            <translation>Wählen Sie einen Eingang oder Ausgang zum Negieren aus.</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>Löschen</translation>
        </message>
        <message>
            <source>Select the elements to copy first.</source>
            <translation>Wählen Sie zuerst die Elemente aus, die kopiert werden sollen.</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>Einfügen</translation>
        </message>
        <message>
            <source>Order by data flow</source>
            <translation>Nach Datenfluss anordnen</translation>
        </message>
        <message>
            <source>Order by topology</source>
            <translation>Nach Topologie anordnen</translation>
        </message>
        <message>
            <source>Change execution order</source>
            <translation>Ausführungsreihenfolge ändern</translation>
        </message>
        <message>
            <source>Set execution order</source>
            <translation>Ausführungsreihenfolge setzen</translation>
        </message>
        <message>
            <source>Select one element that has an execution order number.</source>
            <translation>Wählen Sie genau ein Element mit einer Nummer in der Ausführungsreihenfolge aus.</translation>
        </message>
        <message>
            <source>Execution Order</source>
            <translation>Ausführungsreihenfolge</translation>
        </message>
        <message>
            <source>Number of this element (1 to %1):</source>
            <translation>Nummer dieses Elements (1 bis %1):</translation>
        </message>
        <message>
            <source>Insert Comment</source>
            <translation>Kommentar einfügen</translation>
        </message>
        <message>
            <source>Comment:</source>
            <translation>Kommentar:</translation>
        </message>
        <message>
            <source>&amp;Box</source>
            <translation>&amp;Baustein</translation>
        </message>
        <message>
            <source>Box</source>
            <translation>Baustein</translation>
        </message>
        <message>
            <source>&amp;Input</source>
            <translation>&amp;Eingang</translation>
        </message>
        <message>
            <source>Input</source>
            <translation>Eingang</translation>
        </message>
        <message>
            <source>O&amp;utput</source>
            <translation>&amp;Ausgang</translation>
        </message>
        <message>
            <source>Output</source>
            <translation>Ausgang</translation>
        </message>
        <message>
            <source>&amp;Jump</source>
            <translation>&amp;Sprung</translation>
        </message>
        <message>
            <source>&amp;Label</source>
            <translation>&amp;Marke</translation>
        </message>
        <message>
            <source>&amp;Return</source>
            <translation>&amp;Rücksprung</translation>
        </message>
        <message>
            <source>Co&amp;mment…</source>
            <translation>&amp;Kommentar…</translation>
        </message>
        <message>
            <source>Connection Mark (&amp;Source)</source>
            <translation>Verbindungsmarke (&amp;Quelle)</translation>
        </message>
        <message>
            <source>Connection Mark (&amp;Sink)</source>
            <translation>Verbindungsmarke (&amp;Ziel)</translation>
        </message>
        <message>
            <source>Ne&amp;gate</source>
            <translation>&amp;Negieren</translation>
        </message>
        <message>
            <source>Edit &amp;Name</source>
            <translation>&amp;Namen bearbeiten</translation>
        </message>
        <message>
            <source>Order by &amp;Data Flow</source>
            <translation>Nach &amp;Datenfluss anordnen</translation>
        </message>
        <message>
            <source>Data Flow</source>
            <translation>Datenfluss</translation>
        </message>
        <message>
            <source>Order by &amp;Topology</source>
            <translation>Nach &amp;Topologie anordnen</translation>
        </message>
        <message>
            <source>Order: One &amp;Earlier</source>
            <translation>Reihenfolge: Eins &amp;früher</translation>
        </message>
        <message>
            <source>Order: One &amp;Later</source>
            <translation>Reihenfolge: Eins &amp;später</translation>
        </message>
        <message>
            <source>Order: To the &amp;Front</source>
            <translation>Reihenfolge: An den &amp;Anfang</translation>
        </message>
        <message>
            <source>Order: To the &amp;Back</source>
            <translation>Reihenfolge: An das &amp;Ende</translation>
        </message>
        <message>
            <source>Set Order &amp;Number…</source>
            <translation>Reihenfolge-&amp;Nummer setzen…</translation>
        </message>
        <message>
            <source>Cu&amp;t</source>
            <translation>&amp;Ausschneiden</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>&amp;Kopieren</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>&amp;Einfügen</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>&amp;Löschen</translation>
        </message>
        <message>
            <source>Jump</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <source>Label</source>
            <translation>Marke</translation>
        </message>
        <message>
            <source>Return</source>
            <translation>Rücksprung</translation>
        </message>
        <message>
            <source>Comment</source>
            <translation>Kommentar</translation>
        </message>
        <message>
            <source>Select a box to give it EN/ENO or take them away.</source>
            <translation>Einen Baustein auswählen, um ihm EN/ENO zu geben oder sie zu entfernen.</translation>
        </message>
        <message>
            <source>Remove EN/ENO from %1</source>
            <translation>EN/ENO von %1 entfernen</translation>
        </message>
        <message>
            <source>Add EN/ENO to %1</source>
            <translation>EN/ENO zu %1 hinzufügen</translation>
        </message>
        <message>
            <source>EN/ENO</source>
            <translation>EN/ENO</translation>
        </message>
        <message>
            <source>box %1 (%2)</source>
            <translation>Baustein %1 (%2)</translation>
        </message>
        <message>
            <source>element %1</source>
            <translation>Element %1</translation>
        </message>
        <message>
            <source>output %1 (%2)</source>
            <translation>Ausgang %1 (%2)</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::fbd::FbdEditor</name>
        <message>
            <source>Insert network</source>
            <translation>Netzwerk einfügen</translation>
        </message>
        <message>
            <source>Insert %1</source>
            <translation>%1 einfügen</translation>
        </message>
        <message>
            <source>Change box to %1</source>
            <translation>Baustein in %1 ändern</translation>
        </message>
        <message>
            <source>Insert input</source>
            <translation>Eingang einfügen</translation>
        </message>
        <message>
            <source>Insert output</source>
            <translation>Ausgang einfügen</translation>
        </message>
        <message>
            <source>Insert assignment</source>
            <translation>Zuweisung einfügen</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>Sprung einfügen</translation>
        </message>
        <message>
            <source>Insert return</source>
            <translation>Rücksprung einfügen</translation>
        </message>
        <message>
            <source>Change label</source>
            <translation>Marke ändern</translation>
        </message>
        <message>
            <source>Change comment</source>
            <translation>Kommentar ändern</translation>
        </message>
        <message>
            <source>Negate</source>
            <translation>Negieren</translation>
        </message>
        <message>
            <source>Set/Reset</source>
            <translation>Setzen/Rücksetzen</translation>
        </message>
        <message>
            <source>Edge</source>
            <translation>Flanke</translation>
        </message>
        <message>
            <source>Rename</source>
            <translation>Umbenennen</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>Löschen</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>Einfügen</translation>
        </message>
        <message>
            <source>&amp;Network Before</source>
            <translation>Netzwerk &amp;davor</translation>
        </message>
        <message>
            <source>Network Aft&amp;er</source>
            <translation>Netzwerk &amp;danach</translation>
        </message>
        <message>
            <source>Network</source>
            <translation>Netzwerk</translation>
        </message>
        <message>
            <source>&amp;Operator</source>
            <translation>&amp;Operator</translation>
        </message>
        <message>
            <source>Operator</source>
            <translation>Operator</translation>
        </message>
        <message>
            <source>Box with E&amp;N…</source>
            <translation>Baustein mit E&amp;N…</translation>
        </message>
        <message>
            <source>&amp;Input</source>
            <translation>&amp;Eingang</translation>
        </message>
        <message>
            <source>O&amp;utput</source>
            <translation>&amp;Ausgang</translation>
        </message>
        <message>
            <source>&amp;Assignment</source>
            <translation>&amp;Zuweisung</translation>
        </message>
        <message>
            <source>&amp;Jump…</source>
            <translation>&amp;Sprung…</translation>
        </message>
        <message>
            <source>&amp;Return</source>
            <translation>&amp;Rücksprung</translation>
        </message>
        <message>
            <source>La&amp;bel…</source>
            <translation>&amp;Marke…</translation>
        </message>
        <message>
            <source>Co&amp;mment…</source>
            <translation>&amp;Kommentar…</translation>
        </message>
        <message>
            <source>Ne&amp;gate</source>
            <translation>&amp;Negieren</translation>
        </message>
        <message>
            <source>&amp;Set/Reset</source>
            <translation>&amp;Setzen/Rücksetzen</translation>
        </message>
        <message>
            <source>S/R</source>
            <translation>S/R</translation>
        </message>
        <message>
            <source>E&amp;dge (Rising/Falling)</source>
            <translation>&amp;Flanke (steigend/fallend)</translation>
        </message>
        <message>
            <source>Edit &amp;Name</source>
            <translation>&amp;Namen bearbeiten</translation>
        </message>
        <message>
            <source>Cu&amp;t</source>
            <translation>&amp;Ausschneiden</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>&amp;Kopieren</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>&amp;Einfügen</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>&amp;Löschen</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::fbd::FbdEdits</name>
        <message>
            <source>Insert a network first (Network After, Ctrl+T).</source>
            <translation>Fügen Sie zuerst ein Netzwerk ein (Netzwerk danach, Strg+T).</translation>
        </message>
        <message>
            <source>This network was drawn freely in another tool: it is not a tree of boxes, so boxes, inputs and outputs cannot be inserted into it. Its elements can still be renamed, negated or deleted.</source>
            <translation>Dieses Netzwerk wurde in einem anderen Werkzeug frei gezeichnet: Es ist kein Baum aus Bausteinen, daher lassen sich keine Bausteine, Eingänge oder Ausgänge einfügen. Seine Elemente können weiterhin umbenannt, negiert oder gelöscht werden.</translation>
        </message>
        <message>
            <source>Nothing is wired to this input yet.</source>
            <translation>An diesem Eingang ist noch nichts angeschlossen.</translation>
        </message>
        <message>
            <source>Nothing is wired to this element yet.</source>
            <translation>An diesem Element ist noch nichts angeschlossen.</translation>
        </message>
        <message>
            <source>This box has no output.</source>
            <translation>Dieser Baustein hat keinen Ausgang.</translation>
        </message>
        <message>
            <source>The last box of this network has no output.</source>
            <translation>Der letzte Baustein dieses Netzwerks hat keinen Ausgang.</translation>
        </message>
        <message>
            <source>Select a box or one of its inputs first.</source>
            <translation>Wählen Sie zuerst einen Baustein oder einen seiner Eingänge.</translation>
        </message>
        <message>
            <source>%1 has a fixed number of inputs.</source>
            <translation>%1 hat eine feste Anzahl von Eingängen.</translation>
        </message>
        <message>
            <source>Select a box first.</source>
            <translation>Wählen Sie zuerst einen Baustein.</translation>
        </message>
        <message>
            <source>%1 has no output to feed the input with.</source>
            <translation>%1 hat keinen Ausgang, der den Eingang speisen könnte.</translation>
        </message>
        <message>
            <source>%1 has no output to feed the assignment with.</source>
            <translation>%1 hat keinen Ausgang für die Zuweisung.</translation>
        </message>
        <message>
            <source>%1 has no output to pass the value on.</source>
            <translation>%1 hat keinen Ausgang, um den Wert weiterzugeben.</translation>
        </message>
        <message>
            <source>Select an input, an output, an assignment, a jump or a return first.</source>
            <translation>Wählen Sie zuerst einen Eingang, einen Ausgang, eine Zuweisung, einen Sprung oder einen Rücksprung.</translation>
        </message>
        <message>
            <source>The value in front of this jump or return goes elsewhere too: negate the output that feeds it, or insert a NOT.</source>
            <translation>Der Wert vor diesem Sprung oder Rücksprung wird auch anderswo verwendet: Negieren Sie den Ausgang, der ihn liefert, oder fügen Sie ein NOT ein.</translation>
        </message>
        <message>
            <source>Select an assignment (an output variable) first.</source>
            <translation>Wählen Sie zuerst eine Zuweisung (eine Ausgangsvariable).</translation>
        </message>
        <message>
            <source>Select an input of a box first (edge detection works on BOOL inputs).</source>
            <translation>Wählen Sie zuerst einen Eingang eines Bausteins (die Flankenerkennung wirkt auf BOOL-Eingänge).</translation>
        </message>
        <message>
            <source>There is no such element.</source>
            <translation>Dieses Element gibt es nicht.</translation>
        </message>
        <message>
            <source>Type a name or a value.</source>
            <translation>Geben Sie einen Namen oder einen Wert ein.</translation>
        </message>
        <message>
            <source>This element has no name to type.</source>
            <translation>Dieses Element hat keinen Namen, der sich eingeben ließe.</translation>
        </message>
        <message>
            <source>Select an element of the network first.</source>
            <translation>Wählen Sie zuerst ein Element des Netzwerks.</translation>
        </message>
        <message>
            <source>There is no assignment on this output to delete.</source>
            <translation>An diesem Ausgang gibt es keine Zuweisung zum Löschen.</translation>
        </message>
        <message>
            <source>Select an input of a box first.</source>
            <translation>Wählen Sie zuerst einen Eingang eines Bausteins.</translation>
        </message>
        <message>
            <source>Select what to delete first: an element, an input, an output or a network.</source>
            <translation>Wählen Sie zuerst, was gelöscht werden soll: ein Element, einen Eingang, einen Ausgang oder ein Netzwerk.</translation>
        </message>
        <message>
            <source>There is nothing to copy here.</source>
            <translation>Hier gibt es nichts zu kopieren.</translation>
        </message>
        <message>
            <source>Select a network, a box or an input to copy.</source>
            <translation>Wählen Sie zum Kopieren ein Netzwerk, einen Baustein oder einen Eingang.</translation>
        </message>
        <message>
            <source>There is nothing to paste.</source>
            <translation>Es gibt nichts einzufügen.</translation>
        </message>
        <message>
            <source>The clipboard holds elements of another language (not a function block diagram): nothing was pasted.</source>
            <translation>Die Zwischenablage enthält Elemente einer anderen Sprache (kein Funktionsbausteindiagramm): Es wurde nichts eingefügt.</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::ld::LdEditor</name>
        <message>
            <source>free</source>
            <translation>frei</translation>
        </message>
        <message>
            <source>Insert network</source>
            <translation>Netzwerk einfügen</translation>
        </message>
        <message>
            <source>Insert contact</source>
            <translation>Kontakt einfügen</translation>
        </message>
        <message>
            <source>Insert parallel contact</source>
            <translation>Parallelen Kontakt einfügen</translation>
        </message>
        <message>
            <source>Insert coil</source>
            <translation>Spule einfügen</translation>
        </message>
        <message>
            <source>Insert box %1</source>
            <translation>Baustein %1 einfügen</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>Sprung einfügen</translation>
        </message>
        <message>
            <source>Insert return</source>
            <translation>Rücksprung einfügen</translation>
        </message>
        <message>
            <source>Insert input</source>
            <translation>Eingang einfügen</translation>
        </message>
        <message>
            <source>Insert assignment</source>
            <translation>Zuweisung einfügen</translation>
        </message>
        <message>
            <source>Insert operator</source>
            <translation>Operator einfügen</translation>
        </message>
        <message>
            <source>Change label</source>
            <translation>Marke ändern</translation>
        </message>
        <message>
            <source>Change comment</source>
            <translation>Kommentar ändern</translation>
        </message>
        <message>
            <source>Negate</source>
            <translation>Negieren</translation>
        </message>
        <message>
            <source>Set/Reset</source>
            <translation>Setzen/Rücksetzen</translation>
        </message>
        <message>
            <source>Edge</source>
            <translation>Flanke</translation>
        </message>
        <message>
            <source>Rename</source>
            <translation>Umbenennen</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>Löschen</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>Einfügen</translation>
        </message>
        <message>
            <source>&amp;Network Before</source>
            <translation>Netzwerk &amp;davor</translation>
        </message>
        <message>
            <source>Network Aft&amp;er</source>
            <translation>Netzwerk dan&amp;ach</translation>
        </message>
        <message>
            <source>C&amp;ontact</source>
            <translation>K&amp;ontakt</translation>
        </message>
        <message>
            <source>&amp;Parallel Contact (Below)</source>
            <translation>&amp;Paralleler Kontakt (unten)</translation>
        </message>
        <message>
            <source>Parallel Contact (Abo&amp;ve)</source>
            <translation>Paralleler Kontakt (&amp;oben)</translation>
        </message>
        <message>
            <source>&amp;Function Block…</source>
            <translation>&amp;Funktionsbaustein…</translation>
        </message>
        <message>
            <source>Coi&amp;l</source>
            <translation>Spu&amp;le</translation>
        </message>
        <message>
            <source>Box with E&amp;N…</source>
            <translation>Baustein mit E&amp;N…</translation>
        </message>
        <message>
            <source>Insert at Box: In&amp;put</source>
            <translation>Am Baustein: &amp;Eingang</translation>
        </message>
        <message>
            <source>Insert at Box: &amp;Assignment</source>
            <translation>Am Baustein: &amp;Zuweisung</translation>
        </message>
        <message>
            <source>Insert at Box: Operato&amp;r</source>
            <translation>Am Baustein: Ope&amp;rator</translation>
        </message>
        <message>
            <source>&amp;Jump…</source>
            <translation>&amp;Sprung…</translation>
        </message>
        <message>
            <source>&amp;Return</source>
            <translation>&amp;Rücksprung</translation>
        </message>
        <message>
            <source>La&amp;bel…</source>
            <translation>&amp;Marke…</translation>
        </message>
        <message>
            <source>Co&amp;mment…</source>
            <translation>&amp;Kommentar…</translation>
        </message>
        <message>
            <source>Ne&amp;gate</source>
            <translation>&amp;Negieren</translation>
        </message>
        <message>
            <source>&amp;Set/Reset</source>
            <translation>&amp;Setzen/Rücksetzen</translation>
        </message>
        <message>
            <source>E&amp;dge (P/N)</source>
            <translation>&amp;Flanke (P/N)</translation>
        </message>
        <message>
            <source>Edit &amp;Name</source>
            <translation>&amp;Namen bearbeiten</translation>
        </message>
        <message>
            <source>Cu&amp;t</source>
            <translation>&amp;Ausschneiden</translation>
        </message>
        <message>
            <source>&amp;Copy</source>
            <translation>&amp;Kopieren</translation>
        </message>
        <message>
            <source>&amp;Paste</source>
            <translation>E&amp;infügen</translation>
        </message>
        <message>
            <source>Paste &amp;Below</source>
            <translation>Einfügen &amp;unterhalb</translation>
        </message>
        <message>
            <source>Paste Abo&amp;ve</source>
            <translation>Einfügen o&amp;berhalb</translation>
        </message>
        <message>
            <source>&amp;Delete</source>
            <translation>&amp;Löschen</translation>
        </message>
        <message>
            <source>Network</source>
            <translation>Netzwerk</translation>
        </message>
        <message>
            <source>Parallel</source>
            <translation>Parallel</translation>
        </message>
        <message>
            <source>Box…</source>
            <translation>Baustein…</translation>
        </message>
        <message>
            <source>S/R</source>
            <translation>S/R</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::ld::LdEdits</name>
        <message>
            <source>There is no network here. Insert a network first (Network After).</source>
            <translation>Hier ist kein Netzwerk. Fügen Sie zuerst eines ein (Netzwerk danach).</translation>
        </message>
        <message>
            <source>This network is drawn freely by another tool, not as a rung: change its elements one by one (their names, negation), or delete it and draw it again.</source>
            <translation>Dieses Netzwerk wurde von einem anderen Werkzeug frei gezeichnet, nicht als Kontaktplan: ändern Sie seine Elemente einzeln (Namen, Negation) oder löschen Sie es und zeichnen es neu.</translation>
        </message>
        <message>
            <source>Put the cursor on an element or on a wire of the rung first.</source>
            <translation>Setzen Sie den Cursor zuerst auf ein Element oder eine Verbindung des Netzwerks.</translation>
        </message>
        <message>
            <source>Network %1 has the label %2 already: labels name one network each.</source>
            <translation>Netzwerk %1 hat die Marke %2 schon: eine Marke benennt genau ein Netzwerk.</translation>
        </message>
        <message>
            <source>Select the contacts (shift-click for a range) that the parallel contact goes around.</source>
            <translation>Wählen Sie die Kontakte (Umschalt-Klick für einen Bereich), die der parallele Kontakt umschließt.</translation>
        </message>
        <message>
            <source>A parallel contact goes around contacts and boxes; for another output use Coil.</source>
            <translation>Ein paralleler Kontakt umschließt Kontakte und Bausteine; für einen weiteren Ausgang nehmen Sie Spule.</translation>
        </message>
        <message>
            <source>Choose the function or function block the box calls.</source>
            <translation>Wählen Sie die Funktion oder den Funktionsbaustein, den der Baustein aufruft.</translation>
        </message>
        <message>
            <source>This box has no input the rung could drive: use the box with EN.</source>
            <translation>Dieser Baustein hat keinen Eingang, den das Netzwerk treiben kann: nehmen Sie den Baustein mit EN.</translation>
        </message>
        <message>
            <source>Select a box (or a variable on its inputs) first.</source>
            <translation>Wählen Sie zuerst einen Baustein (oder eine Variable an seinen Eingängen).</translation>
        </message>
        <message>
            <source>%1 has a fixed number of inputs.</source>
            <translation>%1 hat eine feste Anzahl von Eingängen.</translation>
        </message>
        <message>
            <source>Select a box first.</source>
            <translation>Wählen Sie zuerst einen Baustein.</translation>
        </message>
        <message>
            <source>Every output of this box has an assignment already.</source>
            <translation>Jeder Ausgang dieses Bausteins hat schon eine Zuweisung.</translation>
        </message>
        <message>
            <source>Select a variable on a box's input first: the operator goes in front of it.</source>
            <translation>Wählen Sie zuerst eine Variable an einem Bausteineingang: der Operator kommt davor.</translation>
        </message>
        <message>
            <source>An operator needs an input and an output.</source>
            <translation>Ein Operator braucht einen Eingang und einen Ausgang.</translation>
        </message>
        <message>
            <source>Select a contact or a coil to negate.</source>
            <translation>Wählen Sie einen Kontakt oder eine Spule zum Negieren.</translation>
        </message>
        <message>
            <source>Select a coil: Set/Reset makes it a set (S) or reset (R) coil.</source>
            <translation>Wählen Sie eine Spule: Setzen/Rücksetzen macht daraus eine Setz- (S) oder Rücksetzspule (R).</translation>
        </message>
        <message>
            <source>Select a contact or a coil: an edge makes it react to a rising (P) or falling (N) edge.</source>
            <translation>Wählen Sie einen Kontakt oder eine Spule: eine Flanke lässt sie auf eine steigende (P) oder fallende (N) Flanke reagieren.</translation>
        </message>
        <message>
            <source>The element is gone.</source>
            <translation>Das Element gibt es nicht mehr.</translation>
        </message>
        <message>
            <source>Type a name (or press Esc to keep the old one).</source>
            <translation>Geben Sie einen Namen ein (oder Esc, um den alten zu behalten).</translation>
        </message>
        <message>
            <source>This element has no name to type.</source>
            <translation>Dieses Element hat keinen Namen zum Eingeben.</translation>
        </message>
        <message>
            <source>Select an element or a network to delete.</source>
            <translation>Wählen Sie ein Element oder ein Netzwerk zum Löschen.</translation>
        </message>
        <message>
            <source>The power rails belong to the network: delete the network to remove them.</source>
            <translation>Die Stromschienen gehören zum Netzwerk: löschen Sie das Netzwerk, um sie zu entfernen.</translation>
        </message>
        <message>
            <source>The clipboard holds elements that do not form a rung.</source>
            <translation>Die Elemente in der Zwischenablage bilden kein Netzwerk.</translation>
        </message>
        <message>
            <source>This network is drawn freely by another tool, not as a rung: paste into a rung network.</source>
            <translation>Dieses Netzwerk wurde von einem anderen Werkzeug frei gezeichnet: fügen Sie in ein Kontaktplan-Netzwerk ein.</translation>
        </message>
        <message>
            <source>Select the elements the pasted ones go parallel to.</source>
            <translation>Wählen Sie die Elemente, zu denen das Eingefügte parallel kommt.</translation>
        </message>
        <message>
            <source>There is nothing to copy here.</source>
            <translation>Hier gibt es nichts zu kopieren.</translation>
        </message>
        <message>
            <source>Select elements or a network to copy.</source>
            <translation>Wählen Sie Elemente oder ein Netzwerk zum Kopieren.</translation>
        </message>
        <message>
            <source>This network is drawn freely: copy the whole network (click its number).</source>
            <translation>Dieses Netzwerk ist frei gezeichnet: kopieren Sie das ganze Netzwerk (Klick auf seine Nummer).</translation>
        </message>
        <message>
            <source>Select rung elements (contacts, coils, boxes) or a network to copy.</source>
            <translation>Wählen Sie Netzwerkelemente (Kontakte, Spulen, Bausteine) oder ein Netzwerk zum Kopieren.</translation>
        </message>
        <message>
            <source>There is nothing to paste.</source>
            <translation>Es gibt nichts einzufügen.</translation>
        </message>
        <message>
            <source>The clipboard holds elements of another language (not a ladder diagram): nothing was pasted.</source>
            <translation>Die Zwischenablage enthält Elemente einer anderen Sprache (keinen Kontaktplan): nichts eingefügt.</translation>
        </message>
        <message>
            <source>%1 is a program: a box calls a function or a function block.</source>
            <translation>%1 ist ein Programm: ein Baustein ruft eine Funktion oder einen Funktionsbaustein auf.</translation>
        </message>
        <message>
            <source>There is no function or function block called %1 (in the standard library or the project).</source>
            <translation>Es gibt keine Funktion und keinen Funktionsbaustein namens %1 (weder in der Standardbibliothek noch im Projekt).</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::ActionAssociationsDialog</name>
        <message>
            <source>IEC Actions of the Step</source>
            <translation>IEC-Aktionen des Schritts</translation>
        </message>
        <message>
            <source>Qualifier</source>
            <translation>Bestimmungszeichen</translation>
        </message>
        <message>
            <source>Time</source>
            <translation>Zeit</translation>
        </message>
        <message>
            <source>Action or variable</source>
            <translation>Aktion oder Variable</translation>
        </message>
        <message>
            <source>Indicator</source>
            <translation>Anzeigevariable</translation>
        </message>
        <message>
            <source>Add</source>
            <translation>Hinzufügen</translation>
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
            <source>BOOL variable</source>
            <translation>BOOL-Variable</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::SfcEditor</name>
        <message>
            <source>Step-Transition (after)</source>
            <translation>Schritt-Transition (danach)</translation>
        </message>
        <message>
            <source>Step-Transition (before)</source>
            <translation>Schritt-Transition (davor)</translation>
        </message>
        <message>
            <source>Alternative Branch (right)</source>
            <translation>Alternativzweig (rechts)</translation>
        </message>
        <message>
            <source>Alternative Branch (left)</source>
            <translation>Alternativzweig (links)</translation>
        </message>
        <message>
            <source>Parallel Branch (right)</source>
            <translation>Parallelzweig (rechts)</translation>
        </message>
        <message>
            <source>Parallel Branch (left)</source>
            <translation>Parallelzweig (links)</translation>
        </message>
        <message>
            <source>Jump…</source>
            <translation>Sprung…</translation>
        </message>
        <message>
            <source>Transition-Jump…</source>
            <translation>Transition-Sprung…</translation>
        </message>
        <message>
            <source>Macro Step</source>
            <translation>Makroschritt</translation>
        </message>
        <message>
            <source>Delete</source>
            <translation>Löschen</translation>
        </message>
        <message>
            <source>Cut</source>
            <translation>Ausschneiden</translation>
        </message>
        <message>
            <source>Copy</source>
            <translation>Kopieren</translation>
        </message>
        <message>
            <source>Paste</source>
            <translation>Einfügen</translation>
        </message>
        <message>
            <source>Step Properties…</source>
            <translation>Schritteigenschaften…</translation>
        </message>
        <message>
            <source>Select a step first.</source>
            <translation>Wählen Sie zuerst einen Schritt aus.</translation>
        </message>
        <message>
            <source>IEC Actions…</source>
            <translation>IEC-Aktionen…</translation>
        </message>
        <message>
            <source>Edit Condition</source>
            <translation>Bedingung bearbeiten</translation>
        </message>
        <message>
            <source>Select a transition first.</source>
            <translation>Wählen Sie zuerst eine Transition aus.</translation>
        </message>
        <message>
            <source>Transition Priority…</source>
            <translation>Transitionspriorität…</translation>
        </message>
        <message>
            <source>Transition Priority</source>
            <translation>Transitionspriorität</translation>
        </message>
        <message>
            <source>Priority (0: none, branches are tried from left to right):</source>
            <translation>Priorität (0: keine, Zweige werden von links nach rechts geprüft):</translation>
        </message>
        <message>
            <source>Leave Macro</source>
            <translation>Makro verlassen</translation>
        </message>
        <message>
            <source>New chart</source>
            <translation>Neuer Ablaufplan</translation>
        </message>
        <message>
            <source>Insert step-transition</source>
            <translation>Schritt-Transition einfügen</translation>
        </message>
        <message>
            <source>Insert alternative branch</source>
            <translation>Alternativzweig einfügen</translation>
        </message>
        <message>
            <source>Insert parallel branch</source>
            <translation>Parallelzweig einfügen</translation>
        </message>
        <message>
            <source>Insert jump</source>
            <translation>Sprung einfügen</translation>
        </message>
        <message>
            <source>Insert transition-jump</source>
            <translation>Transition-Sprung einfügen</translation>
        </message>
        <message>
            <source>Insert macro step</source>
            <translation>Makroschritt einfügen</translation>
        </message>
        <message>
            <source>Change step</source>
            <translation>Schritt ändern</translation>
        </message>
        <message>
            <source>Change condition</source>
            <translation>Bedingung ändern</translation>
        </message>
        <message>
            <source>Change priority</source>
            <translation>Priorität ändern</translation>
        </message>
        <message>
            <source>Add %1 action %2</source>
            <translation>%1-Aktion %2 hinzufügen</translation>
        </message>
        <message>
            <source>Select a macro step first.</source>
            <translation>Wählen Sie zuerst einen Makroschritt aus.</translation>
        </message>
        <message>
            <source>Inside macro step %1</source>
            <translation>Im Makroschritt %1</translation>
        </message>
        <message>
            <source>An ST expression, or the name of a transition of the POU. Enter applies, Esc cancels.</source>
            <translation>Ein ST-Ausdruck oder der Name einer Transition des Bausteins. Eingabe übernimmt, Esc bricht ab.</translation>
        </message>
        <message>
            <source>Change actions</source>
            <translation>Aktionen ändern</translation>
        </message>
        <message>
            <source>The chart has no step to jump to.</source>
            <translation>Der Ablaufplan hat keinen Schritt, zu dem gesprungen werden kann.</translation>
        </message>
        <message>
            <source>Jump</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <source>Jump to step:</source>
            <translation>Sprung zu Schritt:</translation>
        </message>
        <message>
            <source>Arrange Chart</source>
            <translation>Plan anordnen</translation>
        </message>
        <message>
            <source>The chart is empty: there is nothing to arrange.</source>
            <translation>Der Plan ist leer: es gibt nichts anzuordnen.</translation>
        </message>
        <message>
            <source>Arrange chart</source>
            <translation>Plan anordnen</translation>
        </message>
        <message>
            <source>Initial Step</source>
            <translation>Initialschritt</translation>
        </message>
        <message>
            <source>Step</source>
            <translation>Schritt</translation>
        </message>
        <message>
            <source>Alternative</source>
            <translation>Alternativ</translation>
        </message>
        <message>
            <source>Parallel</source>
            <translation>Parallel</translation>
        </message>
        <message>
            <source>Macro</source>
            <translation>Makro</translation>
        </message>
        <message>
            <source>Properties…</source>
            <translation>Eigenschaften…</translation>
        </message>
        <message>
            <source>Actions…</source>
            <translation>Aktionen…</translation>
        </message>
        <message>
            <source>Arrange</source>
            <translation>Anordnen</translation>
        </message>
        <message>
            <source>Leave</source>
            <translation>Verlassen</translation>
        </message>
        <message>
            <source>step %1</source>
            <translation>Schritt %1</translation>
        </message>
        <message>
            <source>a transition</source>
            <translation>eine Transition</translation>
        </message>
        <message>
            <source>the transition after %1</source>
            <translation>die Transition nach %1</translation>
        </message>
        <message>
            <source>an action block</source>
            <translation>ein Aktionsblock</translation>
        </message>
        <message>
            <source>the actions of %1</source>
            <translation>die Aktionen von %1</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::SfcEdits</name>
        <message>
            <source>Select a step or a transition first.</source>
            <translation>Wählen Sie zuerst einen Schritt oder eine Transition aus.</translation>
        </message>
        <message>
            <source>Nothing can follow a jump. Select the transition before it.</source>
            <translation>Nach einem Sprung kann nichts folgen. Wählen Sie die Transition davor aus.</translation>
        </message>
        <message>
            <source>Nothing can go before the initial step. Insert after it instead.</source>
            <translation>Vor dem Initialschritt kann nichts stehen. Fügen Sie stattdessen danach ein.</translation>
        </message>
        <message>
            <source>Select a step (or steps from one to another) to add a parallel branch.</source>
            <translation>Wählen Sie einen Schritt (oder Schritte von einem bis zu einem anderen) aus, um einen Parallelzweig hinzuzufügen.</translation>
        </message>
        <message>
            <source>Select a transition (or a range from a transition to a transition) to add an alternative branch.</source>
            <translation>Wählen Sie eine Transition (oder einen Bereich von Transition zu Transition) aus, um einen Alternativzweig hinzuzufügen.</translation>
        </message>
        <message>
            <source>The chart is not empty.</source>
            <translation>Der Ablaufplan ist nicht leer.</translation>
        </message>
        <message>
            <source>There is no step '%1' to jump to.</source>
            <translation>Es gibt keinen Schritt '%1', zu dem gesprungen werden kann.</translation>
        </message>
        <message>
            <source>Select the transition the jump follows.</source>
            <translation>Wählen Sie die Transition aus, der der Sprung folgt.</translation>
        </message>
        <message>
            <source>A jump can only follow the last transition of a chain or branch.</source>
            <translation>Ein Sprung kann nur auf die letzte Transition einer Kette oder eines Zweigs folgen.</translation>
        </message>
        <message>
            <source>Select the step the transition and jump follow.</source>
            <translation>Wählen Sie den Schritt aus, dem Transition und Sprung folgen.</translation>
        </message>
        <message>
            <source>A transition-jump can only follow the last step of a chain or of an alternative branch.</source>
            <translation>Ein Transition-Sprung kann nur auf den letzten Schritt einer Kette oder eines Alternativzweigs folgen.</translation>
        </message>
        <message>
            <source>Select what to delete first.</source>
            <translation>Wählen Sie zuerst aus, was gelöscht werden soll.</translation>
        </message>
        <message>
            <source>The initial step cannot be deleted on its own. Delete what follows it, or the whole chart.</source>
            <translation>Der Initialschritt kann nicht allein gelöscht werden. Löschen Sie, was ihm folgt, oder den ganzen Ablaufplan.</translation>
        </message>
        <message>
            <source>Deleting this would leave two steps or two transitions in a row. Select a step together with its transition.</source>
            <translation>Dieses Löschen würde zwei Schritte oder zwei Transitionen hintereinander hinterlassen. Wählen Sie einen Schritt zusammen mit seiner Transition aus.</translation>
        </message>
        <message>
            <source>Select a step first.</source>
            <translation>Wählen Sie zuerst einen Schritt aus.</translation>
        </message>
        <message>
            <source>'%1' is not a valid step name: use letters, digits and single underscores, starting with a letter.</source>
            <translation>'%1' ist kein gültiger Schrittname: Verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche, beginnend mit einem Buchstaben.</translation>
        </message>
        <message>
            <source>There is already a step named '%1'.</source>
            <translation>Es gibt bereits einen Schritt namens '%1'.</translation>
        </message>
        <message>
            <source>Only the first step of the chart is the initial step.</source>
            <translation>Nur der erste Schritt des Ablaufplans ist der Initialschritt.</translation>
        </message>
        <message>
            <source>This step has IEC actions. Remove them before making it a simplified step.</source>
            <translation>Dieser Schritt hat IEC-Aktionen. Entfernen Sie sie, bevor Sie ihn zu einem vereinfachten Schritt machen.</translation>
        </message>
        <message>
            <source>'%1' is not an action qualifier.</source>
            <translation>'%1' ist kein Aktionsbestimmungszeichen.</translation>
        </message>
        <message>
            <source>The qualifier %1 needs a time, such as T#5s.</source>
            <translation>Das Bestimmungszeichen %1 braucht eine Zeit, z. B. T#5s.</translation>
        </message>
        <message>
            <source>'%1' is not an action or variable name.</source>
            <translation>'%1' ist kein Aktions- oder Variablenname.</translation>
        </message>
        <message>
            <source>A simplified step has no IEC actions. Make it an IEC step in its properties first.</source>
            <translation>Ein vereinfachter Schritt hat keine IEC-Aktionen. Machen Sie ihn zuerst in seinen Eigenschaften zu einem IEC-Schritt.</translation>
        </message>
        <message>
            <source>The step has no such action.</source>
            <translation>Der Schritt hat keine solche Aktion.</translation>
        </message>
        <message>
            <source>The action cannot move there.</source>
            <translation>Die Aktion kann nicht dorthin verschoben werden.</translation>
        </message>
        <message>
            <source>Select a transition first.</source>
            <translation>Wählen Sie zuerst eine Transition aus.</translation>
        </message>
        <message>
            <source>A transition needs a condition, such as TRUE or Level &gt; 50.</source>
            <translation>Eine Transition braucht eine Bedingung, z. B. TRUE oder Level &gt; 50.</translation>
        </message>
        <message>
            <source>'%1' is not a valid transition name.</source>
            <translation>'%1' ist kein gültiger Transitionsname.</translation>
        </message>
        <message>
            <source>Select steps and transitions of one chain to copy.</source>
            <translation>Wählen Sie Schritte und Transitionen einer Kette zum Kopieren aus.</translation>
        </message>
        <message>
            <source>There is nothing to paste.</source>
            <translation>Es gibt nichts einzufügen.</translation>
        </message>
        <message>
            <source>Select where to paste first.</source>
            <translation>Wählen Sie zuerst aus, wo eingefügt werden soll.</translation>
        </message>
        <message>
            <source>The copied part does not fit here: after a step paste a part that starts with a transition, after a transition one that starts with a step.</source>
            <translation>Der kopierte Teil passt hier nicht: Fügen Sie nach einem Schritt einen Teil ein, der mit einer Transition beginnt, nach einer Transition einen, der mit einem Schritt beginnt.</translation>
        </message>
        <message>
            <source>The copied elements are not one chain of steps and transitions: nothing was pasted.</source>
            <translation>Die kopierten Elemente sind keine Kette aus Schritten und Transitionen: Es wurde nichts eingefügt.</translation>
        </message>
        <message>
            <source>'%1' is not a valid action name: use letters, digits and single underscores, starting with a letter.</source>
            <translation>'%1' ist kein gültiger Aktionsname: Verwenden Sie Buchstaben, Ziffern und einzelne Unterstriche, beginnend mit einem Buchstaben.</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::SfcItem</name>
        <message>
            <source>Initial step %1</source>
            <translation>Initialschritt %1</translation>
        </message>
        <message>
            <source>Step %1</source>
            <translation>Schritt %1</translation>
        </message>
        <message>
            <source>Entry action: %1</source>
            <translation>Eingangsaktion: %1</translation>
        </message>
        <message>
            <source>Exit action: %1</source>
            <translation>Ausgangsaktion: %1</translation>
        </message>
        <message>
            <source>Active action: %1</source>
            <translation>Aktive Aktion: %1</translation>
        </message>
        <message>
            <source>Time: minimum %1, maximum %2</source>
            <translation>Zeit: Minimum %1, Maximum %2</translation>
        </message>
        <message>
            <source>Macro step %1 (double-click to open)</source>
            <translation>Makroschritt %1 (Doppelklick öffnet ihn)</translation>
        </message>
        <message>
            <source>Transition: %1</source>
            <translation>Transition: %1</translation>
        </message>
        <message>
            <source>Jump to step %1</source>
            <translation>Sprung zu Schritt %1</translation>
        </message>
        <message>
            <source>Jump to step %1, which does not exist</source>
            <translation>Sprung zu Schritt %1, den es nicht gibt</translation>
        </message>
        <message>
            <source>Parallel branch (start)</source>
            <translation>Parallelzweig (Anfang)</translation>
        </message>
        <message>
            <source>Parallel branch (end)</source>
            <translation>Parallelzweig (Ende)</translation>
        </message>
        <message>
            <source>Alternative branch (start)</source>
            <translation>Alternativzweig (Anfang)</translation>
        </message>
        <message>
            <source>Alternative branch (end)</source>
            <translation>Alternativzweig (Ende)</translation>
        </message>
    </context>
    <context>
        <name>iec::editors::sfc::StepPropertiesDialog</name>
        <message>
            <source>Initial step</source>
            <translation>Initialschritt</translation>
        </message>
        <message>
            <source>Simplified step (no IEC actions)</source>
            <translation>Vereinfachter Schritt (keine IEC-Aktionen)</translation>
        </message>
        <message>
            <source>Step Properties</source>
            <translation>Schritteigenschaften</translation>
        </message>
        <message>
            <source>e.g. T#2s</source>
            <translation>z. B. T#2s</translation>
        </message>
        <message>
            <source>e.g. T#10s</source>
            <translation>z. B. T#10s</translation>
        </message>
        <message>
            <source>Name:</source>
            <translation>Name:</translation>
        </message>
        <message>
            <source>Entry action (E):</source>
            <translation>Eingangsaktion (E):</translation>
        </message>
        <message>
            <source>Exit action (X):</source>
            <translation>Ausgangsaktion (X):</translation>
        </message>
        <message>
            <source>Active action:</source>
            <translation>Aktive Aktion:</translation>
        </message>
        <message>
            <source>Minimum time:</source>
            <translation>Minimale Zeit:</translation>
        </message>
        <message>
            <source>Maximum time:</source>
            <translation>Maximale Zeit:</translation>
        </message>
        <message>
            <source>Comment:</source>
            <translation>Kommentar:</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Compiler</name>
        <message>
            <source>a statement</source>
            <translation>eine Anweisung</translation>
        </message>
        <message>
            <source>VAR ... END_VAR</source>
            <translation>VAR ... END_VAR</translation>
        </message>
        <message>
            <source>the end of the text</source>
            <translation>das Ende des Texts</translation>
        </message>
        <message>
            <source>'%1' is not valid IEC 61131-3 text.</source>
            <translation>'%1' ist kein gültiger IEC 61131-3-Text.</translation>
        </message>
        <message>
            <source>Expected %1 but found %2.</source>
            <translation>%1 erwartet, aber %2 gefunden.</translation>
        </message>
        <message>
            <source>close the string on the same line, and write $$ for a dollar sign</source>
            <translation>den String in derselben Zeile schließen und $$ für ein Dollarzeichen schreiben</translation>
        </message>
        <message>
            <source>check the digits and units of the literal, e.g. 16#FF or T#1s500ms</source>
            <translation>Ziffern und Einheiten des Literals prüfen, z. B. 16#FF oder T#1s500ms</translation>
        </message>
        <message>
            <source>PROGRAM, FUNCTION_BLOCK, FUNCTION, TYPE or CONFIGURATION</source>
            <translation>PROGRAM, FUNCTION_BLOCK, FUNCTION, TYPE oder CONFIGURATION</translation>
        </message>
        <message>
            <source>the name of the POU</source>
            <translation>den Namen der POE</translation>
        </message>
        <message>
            <source>A FUNCTION needs a result type after its name.</source>
            <translation>Eine FUNCTION braucht nach ihrem Namen einen Ergebnistyp.</translation>
        </message>
        <message>
            <source>write e.g. FUNCTION %1 : INT</source>
            <translation>z. B. FUNCTION %1 : INT schreiben</translation>
        </message>
        <message>
            <source>the name of the action</source>
            <translation>den Namen der Aktion</translation>
        </message>
        <message>
            <source>%1 has no %2.</source>
            <translation>%1 hat kein %2.</translation>
        </message>
        <message>
            <source>add %1 after its last statement</source>
            <translation>%1 nach seiner letzten Anweisung einfügen</translation>
        </message>
        <message>
            <source>the name of a type</source>
            <translation>den Namen eines Typs</translation>
        </message>
        <message>
            <source>':' after the type name</source>
            <translation>':' nach dem Typnamen</translation>
        </message>
        <message>
            <source>Missing ';' after the declaration of type %1.</source>
            <translation>Fehlendes ';' nach der Deklaration des Typs %1.</translation>
        </message>
        <message>
            <source>the name of the configuration</source>
            <translation>den Namen der Konfiguration</translation>
        </message>
        <message>
            <source>the name of the resource</source>
            <translation>den Namen der Ressource</translation>
        </message>
        <message>
            <source>the processor type after ON</source>
            <translation>den Prozessortyp nach ON</translation>
        </message>
        <message>
            <source>the name of the task</source>
            <translation>den Namen der Task</translation>
        </message>
        <message>
            <source>'(' with the task's INTERVAL and PRIORITY</source>
            <translation>'(' mit INTERVAL und PRIORITY der Task</translation>
        </message>
        <message>
            <source>SINGLE, INTERVAL or PRIORITY</source>
            <translation>SINGLE, INTERVAL oder PRIORITY</translation>
        </message>
        <message>
            <source>the name of the program instance</source>
            <translation>den Namen der Programminstanz</translation>
        </message>
        <message>
            <source>the task name after WITH</source>
            <translation>den Tasknamen nach WITH</translation>
        </message>
        <message>
            <source>':' and the program type</source>
            <translation>':' und den Programmtyp</translation>
        </message>
        <message>
            <source>the program type</source>
            <translation>den Programmtyp</translation>
        </message>
        <message>
            <source>TASK, PROGRAM or %1</source>
            <translation>TASK, PROGRAM oder %1</translation>
        </message>
        <message>
            <source>This variable section has no END_VAR.</source>
            <translation>Diesem Variablenabschnitt fehlt END_VAR.</translation>
        </message>
        <message>
            <source>add END_VAR after its last declaration</source>
            <translation>END_VAR nach seiner letzten Deklaration einfügen</translation>
        </message>
        <message>
            <source>a variable name</source>
            <translation>einen Variablennamen</translation>
        </message>
        <message>
            <source>an address such as %IX0.0 after AT</source>
            <translation>eine Adresse wie %IX0.0 nach AT</translation>
        </message>
        <message>
            <source>':' and a type</source>
            <translation>':' und einen Typ</translation>
        </message>
        <message>
            <source>An initial value is given with ':=', not '='.</source>
            <translation>Ein Anfangswert wird mit ':=' angegeben, nicht mit '='.</translation>
        </message>
        <message>
            <source>write %1 : ... := value;</source>
            <translation>%1 : ... := Wert; schreiben</translation>
        </message>
        <message>
            <source>Missing ';' after the declaration of %1.</source>
            <translation>Fehlendes ';' nach der Deklaration von %1.</translation>
        </message>
        <message>
            <source>'[' and the index range, e.g. ARRAY[1..10]</source>
            <translation>'[' und den Indexbereich, z. B. ARRAY[1..10]</translation>
        </message>
        <message>
            <source>'..' between the bounds</source>
            <translation>'..' zwischen den Grenzen</translation>
        </message>
        <message>
            <source>This STRUCT has no END_STRUCT.</source>
            <translation>Diesem STRUCT fehlt END_STRUCT.</translation>
        </message>
        <message>
            <source>an enumeration value</source>
            <translation>einen Aufzählungswert</translation>
        </message>
        <message>
            <source>')' after the enumeration values</source>
            <translation>')' nach den Aufzählungswerten</translation>
        </message>
        <message>
            <source>the closing bracket of the string length</source>
            <translation>die schließende Klammer der Stringlänge</translation>
        </message>
        <message>
            <source>a type</source>
            <translation>einen Typ</translation>
        </message>
        <message>
            <source>')' after the repeated value</source>
            <translation>')' nach dem wiederholten Wert</translation>
        </message>
        <message>
            <source>']' at the end of the array's initial values</source>
            <translation>']' am Ende der Anfangswerte des Felds</translation>
        </message>
        <message>
            <source>a member name</source>
            <translation>einen Komponentennamen</translation>
        </message>
        <message>
            <source>')' at the end of the structure's initial values</source>
            <translation>')' am Ende der Anfangswerte der Struktur</translation>
        </message>
        <message>
            <source>INITIAL_STEP, STEP, TRANSITION or ACTION</source>
            <translation>INITIAL_STEP, STEP, TRANSITION oder ACTION</translation>
        </message>
        <message>
            <source>the name of the step</source>
            <translation>den Namen des Schritts</translation>
        </message>
        <message>
            <source>':' after the step name</source>
            <translation>':' nach dem Schrittnamen</translation>
        </message>
        <message>
            <source>an action name</source>
            <translation>einen Aktionsnamen</translation>
        </message>
        <message>
            <source>an action qualifier such as N, S, R, L or D</source>
            <translation>ein Aktionsbestimmungszeichen wie N, S, R, L oder D</translation>
        </message>
        <message>
            <source>a duration or an indicator variable</source>
            <translation>eine Dauer oder eine Anzeigevariable</translation>
        </message>
        <message>
            <source>Missing ';' after the action association.</source>
            <translation>Fehlendes ';' nach der Aktionszuordnung.</translation>
        </message>
        <message>
            <source>Step %1 has no END_STEP.</source>
            <translation>Dem Schritt %1 fehlt END_STEP.</translation>
        </message>
        <message>
            <source>a step name</source>
            <translation>einen Schrittnamen</translation>
        </message>
        <message>
            <source>')' after the step names</source>
            <translation>')' nach den Schrittnamen</translation>
        </message>
        <message>
            <source>':=' and the transition condition</source>
            <translation>':=' und die Transitionsbedingung</translation>
        </message>
        <message>
            <source>This TRANSITION has no END_TRANSITION.</source>
            <translation>Dieser TRANSITION fehlt END_TRANSITION.</translation>
        </message>
        <message>
            <source>Missing ';' at the end of the statement.</source>
            <translation>Fehlendes ';' am Ende der Anweisung.</translation>
        </message>
        <message>
            <source>every ST statement ends with ';'</source>
            <translation>jede ST-Anweisung endet mit ';'</translation>
        </message>
        <message>
            <source>'=' compares two values; to assign a value write ':='.</source>
            <translation>'=' vergleicht zwei Werte; für eine Zuweisung ':=' schreiben.</translation>
        </message>
        <message>
            <source>write %1 := ...;</source>
            <translation>%1 := ...; schreiben</translation>
        </message>
        <message>
            <source>Expected ':=' or a call after '%1'.</source>
            <translation>':=' oder ein Aufruf nach '%1' erwartet.</translation>
        </message>
        <message>
            <source>This %1 has no matching %2.</source>
            <translation>Dieses %1 hat kein passendes %2.</translation>
        </message>
        <message>
            <source>add %1; after the last statement that belongs to it</source>
            <translation>%1; nach der letzten dazugehörigen Anweisung einfügen</translation>
        </message>
        <message>
            <source>A condition compares with '=', not ':='.</source>
            <translation>Eine Bedingung vergleicht mit '=', nicht mit ':='.</translation>
        </message>
        <message>
            <source>a case label such as 1:, 2, 3: or 10..20:</source>
            <translation>eine CASE-Marke wie 1:, 2, 3: oder 10..20:</translation>
        </message>
        <message>
            <source>':' after the case label</source>
            <translation>':' nach der CASE-Marke</translation>
        </message>
        <message>
            <source>the control variable of the FOR loop</source>
            <translation>die Laufvariable der FOR-Schleife</translation>
        </message>
        <message>
            <source>':=' and the start value</source>
            <translation>':=' und den Startwert</translation>
        </message>
        <message>
            <source>This REPEAT has no UNTIL condition.</source>
            <translation>Diesem REPEAT fehlt die UNTIL-Bedingung.</translation>
        </message>
        <message>
            <source>a value</source>
            <translation>einen Wert</translation>
        </message>
        <message>
            <source>a value, a variable or a function call</source>
            <translation>einen Wert, eine Variable oder einen Funktionsaufruf</translation>
        </message>
        <message>
            <source>a member name or a bit number after '.'</source>
            <translation>einen Komponentennamen oder eine Bitnummer nach '.'</translation>
        </message>
        <message>
            <source>')' or ',' in the argument list</source>
            <translation>')' oder ',' in der Argumentliste</translation>
        </message>
        <message>
            <source>an IL operator such as LD, ST, ADD or JMP</source>
            <translation>einen AWL-Operator wie LD, ST, ADD oder JMP</translation>
        </message>
        <message>
            <source>An IL instruction takes one operand; %1 is left over.</source>
            <translation>Eine AWL-Anweisung nimmt einen Operanden; %1 bleibt übrig.</translation>
        </message>
        <message>
            <source>put each instruction on its own line</source>
            <translation>jede Anweisung in eine eigene Zeile schreiben</translation>
        </message>
        <message>
            <source>There is no global variable %1 for this VAR_EXTERNAL.</source>
            <translation>Es gibt keine globale Variable %1 für diese VAR_EXTERNAL.</translation>
        </message>
        <message>
            <source>declare it in VAR_GLOBAL</source>
            <translation>in VAR_GLOBAL deklarieren</translation>
        </message>
        <message>
            <source>%1 is declared as %2 here but as %3 in VAR_GLOBAL.</source>
            <translation>%1 ist hier als %2 deklariert, in VAR_GLOBAL aber als %3.</translation>
        </message>
        <message>
            <source>%1 is a sequential function chart; charts run with the next version of the interpreter.</source>
            <translation>%1 ist in Ablaufsprache geschrieben; Abläufe laufen mit der nächsten Version des Interpreters.</translation>
        </message>
        <message>
            <source>Only the first configuration (%1) runs.</source>
            <translation>Nur die erste Konfiguration (%1) läuft.</translation>
        </message>
        <message>
            <source>SINGLE needs a global BOOL variable.</source>
            <translation>SINGLE braucht eine globale BOOL-Variable.</translation>
        </message>
        <message>
            <source>There is no PROGRAM called %1.</source>
            <translation>Es gibt kein PROGRAM namens %1.</translation>
        </message>
        <message>
            <source>There is no task called %1.</source>
            <translation>Es gibt keine Task namens %1.</translation>
        </message>
        <message>
            <source>Recursion is not allowed in IEC 61131-3: %1 calls itself (%2).</source>
            <translation>Rekursion ist in IEC 61131-3 nicht erlaubt: %1 ruft sich selbst auf (%2).</translation>
        </message>
        <message>
            <source>The type %1 is declared twice.</source>
            <translation>Der Typ %1 ist zweimal deklariert.</translation>
        </message>
        <message>
            <source>There are two POUs called %1.</source>
            <translation>Es gibt zwei POEs namens %1.</translation>
        </message>
        <message>
            <source>%1 is already the name of a type.</source>
            <translation>%1 ist bereits der Name eines Typs.</translation>
        </message>
        <message>
            <source>The type %1 is defined in terms of itself.</source>
            <translation>Der Typ %1 ist durch sich selbst definiert.</translation>
        </message>
        <message>
            <source>Unknown type '%1'.</source>
            <translation>Unbekannter Typ '%1'.</translation>
        </message>
        <message>
            <source>A string holds 1 to 65535 characters, not %1.</source>
            <translation>Ein String fasst 1 bis 65535 Zeichen, nicht %1.</translation>
        </message>
        <message>
            <source>The array range %1..%2 is empty; the upper bound must not be below the lower one.</source>
            <translation>Der Feldbereich %1..%2 ist leer; die obere Grenze darf nicht unter der unteren liegen.</translation>
        </message>
        <message>
            <source>This array needs %1 MB; an array may use at most 256 MB.</source>
            <translation>Dieses Feld braucht %1 MB; ein Feld darf höchstens 256 MB belegen.</translation>
        </message>
        <message>
            <source>A subrange needs an integer type, not %1.</source>
            <translation>Ein Unterbereich braucht einen Ganzzahltyp, nicht %1.</translation>
        </message>
        <message>
            <source>The structure has two members called %1.</source>
            <translation>Die Struktur hat zwei Komponenten namens %1.</translation>
        </message>
        <message>
            <source>%1 contains an instance of itself, which would never end.</source>
            <translation>%1 enthält eine Instanz von sich selbst, was nie enden würde.</translation>
        </message>
        <message>
            <source>%1 is declared twice.</source>
            <translation>%1 ist zweimal deklariert.</translation>
        </message>
        <message>
            <source>A function cannot hold a function block instance (%1); use a function block instead.</source>
            <translation>Eine Funktion kann keine Funktionsbausteininstanz (%1) enthalten; stattdessen einen Funktionsbaustein verwenden.</translation>
        </message>
        <message>
            <source>The program needs more than 1 GB of memory for its variables.</source>
            <translation>Das Programm braucht für seine Variablen mehr als 1 GB Speicher.</translation>
        </message>
        <message>
            <source>The global variable %1 is declared twice.</source>
            <translation>Die globale Variable %1 ist zweimal deklariert.</translation>
        </message>
        <message>
            <source>The address %1 does not fit a variable of type %2.</source>
            <translation>Die Adresse %1 passt nicht zu einer Variablen vom Typ %2.</translation>
        </message>
        <message>
            <source>A %1 is initialised with a single value.</source>
            <translation>Ein %1 wird mit einem einzelnen Wert initialisiert.</translation>
        </message>
        <message>
            <source>There are more initial values than the array's %1 elements.</source>
            <translation>Es gibt mehr Anfangswerte als die %1 Elemente des Felds.</translation>
        </message>
        <message>
            <source>An array is initialised with a list in brackets, e.g. [1, 2, 3] or [10(0)].</source>
            <translation>Ein Feld wird mit einer Liste in Klammern initialisiert, z. B. [1, 2, 3] oder [10(0)].</translation>
        </message>
        <message>
            <source>%1 has no member %2.</source>
            <translation>%1 hat keine Komponente %2.</translation>
        </message>
        <message>
            <source>A structure is initialised with (member := value, ...).</source>
            <translation>Eine Struktur wird mit (Komponente := Wert, ...) initialisiert.</translation>
        </message>
        <message>
            <source>The text has %1 characters but the string holds only %2.</source>
            <translation>Der Text hat %1 Zeichen, aber der String fasst nur %2.</translation>
        </message>
        <message>
            <source>This must be a constant: a literal, a CONSTANT or an expression of them.</source>
            <translation>Dies muss eine Konstante sein: ein Literal, eine CONSTANT oder ein Ausdruck daraus.</translation>
        </message>
        <message>
            <source>This must be a constant integer.</source>
            <translation>Dies muss eine ganzzahlige Konstante sein.</translation>
        </message>
        <message>
            <source>%1 is a constant and cannot be changed.</source>
            <translation>%1 ist eine Konstante und kann nicht geändert werden.</translation>
        </message>
        <message>
            <source>%1 is an output of the function block and can only be read.</source>
            <translation>%1 ist ein Ausgang des Funktionsbausteins und kann nur gelesen werden.</translation>
        </message>
        <message>
            <source>%1 is internal to the function block.</source>
            <translation>%1 ist intern im Funktionsbaustein.</translation>
        </message>
        <message>
            <source>%1 has no value %2.</source>
            <translation>%1 hat keinen Wert %2.</translation>
        </message>
        <message>
            <source>%1 is a value of several enumerations.</source>
            <translation>%1 ist ein Wert mehrerer Aufzählungen.</translation>
        </message>
        <message>
            <source>write the type in front, e.g. Type#%1</source>
            <translation>den Typ davor schreiben, z. B. Typ#%1</translation>
        </message>
        <message>
            <source>%1 is a POU, not a variable.</source>
            <translation>%1 ist eine POE, keine Variable.</translation>
        </message>
        <message>
            <source>Unknown variable '%1'.</source>
            <translation>Unbekannte Variable '%1'.</translation>
        </message>
        <message>
            <source>declare it in a VAR section</source>
            <translation>in einem VAR-Abschnitt deklarieren</translation>
        </message>
        <message>
            <source>%1 is a %2 and has no members.</source>
            <translation>%1 ist ein %2 und hat keine Komponenten.</translation>
        </message>
        <message>
            <source>%1 has no bit %2.</source>
            <translation>%1 hat kein Bit %2.</translation>
        </message>
        <message>
            <source>%1 is not an array.</source>
            <translation>%1 ist kein Feld.</translation>
        </message>
        <message>
            <source>%1 has %2 dimension(s) but %3 index(es) are given.</source>
            <translation>%1 hat %2 Dimension(en), aber %3 Index/Indizes sind angegeben.</translation>
        </message>
        <message>
            <source>The index %1 is outside the range %2..%3 of %4.</source>
            <translation>Der Index %1 liegt außerhalb des Bereichs %2..%3 von %4.</translation>
        </message>
        <message>
            <source>An array index must be an integer, not %1.</source>
            <translation>Ein Feldindex muss eine Ganzzahl sein, nicht %1.</translation>
        </message>
        <message>
            <source>This is not a variable.</source>
            <translation>Dies ist keine Variable.</translation>
        </message>
        <message>
            <source>The value %1 is outside the range %2..%3 of %4.</source>
            <translation>Der Wert %1 liegt außerhalb des Bereichs %2..%3 von %4.</translation>
        </message>
        <message>
            <source>A function block instance cannot be assigned; call it instead.</source>
            <translation>Einer Funktionsbausteininstanz kann nichts zugewiesen werden; stattdessen aufrufen.</translation>
        </message>
        <message>
            <source>'**' needs numbers, not %1 and %2.</source>
            <translation>'**' braucht Zahlen, nicht %1 und %2.</translation>
        </message>
        <message>
            <source>'%1' cannot combine %2 and %3.</source>
            <translation>'%1' kann %2 und %3 nicht verknüpfen.</translation>
        </message>
        <message>
            <source>BOOL or a bit string (BYTE, WORD, ...)</source>
            <translation>BOOL oder eine Bitfolge (BYTE, WORD, ...)</translation>
        </message>
        <message>
            <source>integers</source>
            <translation>Ganzzahlen</translation>
        </message>
        <message>
            <source>numbers</source>
            <translation>Zahlen</translation>
        </message>
        <message>
            <source>'%1' needs %2, not %3.</source>
            <translation>'%1' braucht %2, nicht %3.</translation>
        </message>
        <message>
            <source>Division by zero.</source>
            <translation>Division durch null.</translation>
        </message>
        <message>
            <source>A %1 cannot be negated.</source>
            <translation>Ein %1 kann nicht negiert werden.</translation>
        </message>
        <message>
            <source>NOT needs BOOL or a bit string (BYTE, WORD, ...), not %1.</source>
            <translation>NOT braucht BOOL oder eine Bitfolge (BYTE, WORD, ...), nicht %1.</translation>
        </message>
        <message>
            <source>an integer literal</source>
            <translation>ein Ganzzahlliteral</translation>
        </message>
        <message>
            <source>'%1' is not a valid literal.</source>
            <translation>'%1' ist kein gültiges Literal.</translation>
        </message>
        <message>
            <source>A value of type %1 cannot be used as %2%3 without a conversion.</source>
            <translation>Ein Wert vom Typ %1 kann nicht ohne Konvertierung als %2%3 verwendet werden.</translation>
        </message>
        <message>
            <source>The value %1 does not fit into %2 (%3 to %4).</source>
            <translation>Der Wert %1 passt nicht in %2 (%3 bis %4).</translation>
        </message>
        <message>
            <source>The text has %1 characters but %2 holds only %3.</source>
            <translation>Der Text hat %1 Zeichen, aber %2 fasst nur %3.</translation>
        </message>
        <message>
            <source>A %1 cannot be converted to text.</source>
            <translation>Ein %1 kann nicht in Text umgewandelt werden.</translation>
        </message>
        <message>
            <source>Text cannot be converted to %1.</source>
            <translation>Text kann nicht in %1 umgewandelt werden.</translation>
        </message>
        <message>
            <source>A %1 cannot be converted to %2.</source>
            <translation>Ein %1 kann nicht in %2 umgewandelt werden.</translation>
        </message>
        <message>
            <source>convert it explicitly, e.g. %1_TO_%2(...)</source>
            <translation>explizit umwandeln, z. B. %1_TO_%2(...)</translation>
        </message>
        <message>
            <source>A function block call is a statement of its own.</source>
            <translation>Ein Funktionsbausteinaufruf ist eine eigene Anweisung.</translation>
        </message>
        <message>
            <source>The action %1 takes no arguments.</source>
            <translation>Die Aktion %1 hat keine Argumente.</translation>
        </message>
        <message>
            <source>%1 is a %2, not a function block; it cannot be called.</source>
            <translation>%1 ist ein %2, kein Funktionsbaustein; es kann nicht aufgerufen werden.</translation>
        </message>
        <message>
            <source>call %1(...); then read its outputs, e.g. %1.Q</source>
            <translation>%1(...) aufrufen; dann seine Ausgänge lesen, z. B. %1.Q</translation>
        </message>
        <message>
            <source>%1 is a function block type; declare an instance (e.g. inst : %1;) and call that.</source>
            <translation>%1 ist ein Funktionsbausteintyp; eine Instanz deklarieren (z. B. inst : %1;) und diese aufrufen.</translation>
        </message>
        <message>
            <source>%1 has no outputs to connect with '=&gt;'.</source>
            <translation>%1 hat keine Ausgänge, die mit '=&gt;' verbunden werden können.</translation>
        </message>
        <message>
            <source>Unknown function '%1'.</source>
            <translation>Unbekannte Funktion '%1'.</translation>
        </message>
        <message>
            <source>%1 takes only %2 input(s).</source>
            <translation>%1 hat nur %2 Eingang/Eingänge.</translation>
        </message>
        <message>
            <source>%1 has no input or output called %2.</source>
            <translation>%1 hat keinen Eingang oder Ausgang namens %2.</translation>
        </message>
        <message>
            <source>%1 is not an output of %2; connect inputs with ':='.</source>
            <translation>%1 ist kein Ausgang von %2; Eingänge mit ':=' verbinden.</translation>
        </message>
        <message>
            <source>%1 is an output of %2; connect it with '=&gt;'.</source>
            <translation>%1 ist ein Ausgang von %2; mit '=&gt;' verbinden.</translation>
        </message>
        <message>
            <source>write %1 =&gt; variable</source>
            <translation>%1 =&gt; Variable schreiben</translation>
        </message>
        <message>
            <source>%1 takes only %2 argument(s).</source>
            <translation>%1 nimmt nur %2 Argument(e).</translation>
        </message>
        <message>
            <source>%1 has no parameter called %2.</source>
            <translation>%1 hat keinen Parameter namens %2.</translation>
        </message>
        <message>
            <source>Connect inputs of %1 with ':=' and outputs with '=&gt;'.</source>
            <translation>Eingänge von %1 mit ':=' und Ausgänge mit '=&gt;' verbinden.</translation>
        </message>
        <message>
            <source>%1 needs a variable for its VAR_IN_OUT %2.</source>
            <translation>%1 braucht eine Variable für seinen VAR_IN_OUT %2.</translation>
        </message>
        <message>
            <source>%1 needs a REAL or LREAL, not %2.</source>
            <translation>%1 braucht REAL oder LREAL, nicht %2.</translation>
        </message>
        <message>
            <source>The inputs of %1 have types that do not go together (%2).</source>
            <translation>Die Eingänge von %1 haben Typen, die nicht zusammenpassen (%2).</translation>
        </message>
        <message>
            <source>%1 needs numbers, times or bit strings.</source>
            <translation>%1 braucht Zahlen, Zeiten oder Bitfolgen.</translation>
        </message>
        <message>
            <source>%1 has no input %2.</source>
            <translation>%1 hat keinen Eingang %2.</translation>
        </message>
        <message>
            <source>%1 needs a bit string (BYTE, WORD, DWORD, LWORD), not %2.</source>
            <translation>%1 braucht eine Bitfolge (BYTE, WORD, DWORD, LWORD), nicht %2.</translation>
        </message>
        <message>
            <source>convert it first, e.g. %1_TO_%2</source>
            <translation>zuerst umwandeln, z. B. %1_TO_%2</translation>
        </message>
        <message>
            <source>A length or position must be an integer, not %1.</source>
            <translation>Eine Länge oder Position muss eine Ganzzahl sein, nicht %1.</translation>
        </message>
        <message>
            <source>%1 needs a STRING or WSTRING, not %2.</source>
            <translation>%1 braucht STRING oder WSTRING, nicht %2.</translation>
        </message>
        <message>
            <source>This time function needs a %1, not %2.</source>
            <translation>Diese Zeitfunktion braucht ein %1, nicht %2.</translation>
        </message>
        <message>
            <source>ABS needs a number, not %1.</source>
            <translation>ABS braucht eine Zahl, nicht %1.</translation>
        </message>
        <message>
            <source>TRUNC needs a REAL or LREAL, not %1.</source>
            <translation>TRUNC braucht REAL oder LREAL, nicht %1.</translation>
        </message>
        <message>
            <source>(the G input of SEL)</source>
            <translation>(der Eingang G von SEL)</translation>
        </message>
        <message>
            <source>The selector K of MUX must be an integer.</source>
            <translation>Der Selektor K von MUX muss eine Ganzzahl sein.</translation>
        </message>
        <message>
            <source>CONCAT_DATE_TOD needs a DATE and a TIME_OF_DAY.</source>
            <translation>CONCAT_DATE_TOD braucht ein DATE und ein TIME_OF_DAY.</translation>
        </message>
        <message>
            <source>%1 takes one argument.</source>
            <translation>%1 nimmt ein Argument.</translation>
        </message>
        <message>
            <source>(the input of %1)</source>
            <translation>(der Eingang von %1)</translation>
        </message>
        <message>
            <source>%1 needs a bit string holding BCD digits.</source>
            <translation>%1 braucht eine Bitfolge mit BCD-Ziffern.</translation>
        </message>
        <message>
            <source>%1 takes %2%3 argument(s), not %4.</source>
            <translation>%1 nimmt %2%3 Argument(e), nicht %4.</translation>
        </message>
        <message>
            <source>at least </source>
            <translation>mindestens </translation>
        </message>
        <message>
            <source>An argument of %1 is missing.</source>
            <translation>Ein Argument von %1 fehlt.</translation>
        </message>
        <message>
            <source>A condition must be BOOL, not %1.</source>
            <translation>Eine Bedingung muss BOOL sein, nicht %1.</translation>
        </message>
        <message>
            <source>compare it, e.g. x &lt;&gt; 0</source>
            <translation>vergleichen, z. B. x &lt;&gt; 0</translation>
        </message>
        <message>
            <source>CASE needs an integer or an enumeration, not %1.</source>
            <translation>CASE braucht eine Ganzzahl oder eine Aufzählung, nicht %1.</translation>
        </message>
        <message>
            <source>The FOR loop needs an integer variable as its counter.</source>
            <translation>Die FOR-Schleife braucht eine Ganzzahlvariable als Zähler.</translation>
        </message>
        <message>
            <source>(the end value)</source>
            <translation>(der Endwert)</translation>
        </message>
        <message>
            <source>(the step)</source>
            <translation>(die Schrittweite)</translation>
        </message>
        <message>
            <source>A FOR loop with step 0 never ends.</source>
            <translation>Eine FOR-Schleife mit Schrittweite 0 endet nie.</translation>
        </message>
        <message>
            <source>%1 is only allowed inside a FOR, WHILE or REPEAT loop.</source>
            <translation>%1 ist nur innerhalb einer FOR-, WHILE- oder REPEAT-Schleife erlaubt.</translation>
        </message>
        <message>
            <source>%1 needs a current result; load one first with LD.</source>
            <translation>%1 braucht ein aktuelles Ergebnis; zuerst eines mit LD laden.</translation>
        </message>
        <message>
            <source>%1 needs an operand.</source>
            <translation>%1 braucht einen Operanden.</translation>
        </message>
        <message>
            <source>(the condition of %1)</source>
            <translation>(die Bedingung von %1)</translation>
        </message>
        <message>
            <source>The label %1 is defined twice.</source>
            <translation>Die Marke %1 ist zweimal definiert.</translation>
        </message>
        <message>
            <source>This ')' has no matching operator with '('.</source>
            <translation>Diese ')' hat keinen passenden Operator mit '('.</translation>
        </message>
        <message>
            <source>%1 needs a label to jump to.</source>
            <translation>%1 braucht eine Sprungmarke.</translation>
        </message>
        <message>
            <source>%1 is not a function block with an input %2.</source>
            <translation>%1 ist kein Funktionsbaustein mit einem Eingang %2.</translation>
        </message>
        <message>
            <source>This '(' is never closed with ')'.</source>
            <translation>Diese '(' wird nie mit ')' geschlossen.</translation>
        </message>
        <message>
            <source>There is no label %1 to jump to.</source>
            <translation>Es gibt keine Marke %1, zu der gesprungen werden kann.</translation>
        </message>
        <message>
            <source>This string is not closed on its line.</source>
            <translation>Diese Zeichenkette wird in ihrer Zeile nicht geschlossen.</translation>
        </message>
        <message>
            <source>Expected %1 but found '%2'.</source>
            <translation>%1 erwartet, aber '%2' gefunden.</translation>
        </message>
        <message>
            <source>This ')' has no matching '('.</source>
            <translation>Zu dieser ')' gibt es keine passende '('.</translation>
        </message>
        <message>
            <source>did you mean %1?</source>
            <translation>meinten Sie %1?</translation>
        </message>
        <message>
            <source>the %1 of line %2 ends with %3</source>
            <translation>das %1 aus Zeile %2 endet mit %3</translation>
        </message>
        <message>
            <source>ELSE IF opens a second IF that needs its own END_IF; write ELSIF instead</source>
            <translation>ELSE IF öffnet ein zweites IF, das ein eigenes END_IF braucht; schreiben Sie stattdessen ELSIF</translation>
        </message>
        <message>
            <source>Expected a value, a variable or a function call but found '='.</source>
            <translation>Ein Wert, eine Variable oder ein Funktionsaufruf erwartet, aber '=' gefunden.</translation>
        </message>
        <message>
            <source>IEC 61131-3 compares with a single '='</source>
            <translation>IEC 61131-3 vergleicht mit einem einzelnen '='</translation>
        </message>
        <message>
            <source>This is ST, but the body is written in IL; a body uses one language.</source>
            <translation>Das ist ST, aber der Rumpf ist in AWL geschrieben; ein Rumpf verwendet eine Sprache.</translation>
        </message>
        <message>
            <source>write it in IL (LD, ST, JMPC ...) or write the whole body in ST</source>
            <translation>schreiben Sie es in AWL (LD, ST, JMPC ...) oder den ganzen Rumpf in ST</translation>
        </message>
        <message>
            <source>A %1 holds exactly one character, not %2.</source>
            <translation>Ein %1 enthält genau ein Zeichen, nicht %2.</translation>
        </message>
        <message>
            <source>VAR_IN_OUT %1 of %2 needs a variable, not a value.</source>
            <translation>VAR_IN_OUT %1 von %2 braucht eine Variable, keinen Wert.</translation>
        </message>
        <message>
            <source>it may change what it is given; pass a variable</source>
            <translation>der Baustein darf das Übergebene ändern; übergeben Sie eine Variable</translation>
        </message>
        <message>
            <source>%1 cannot be changed.</source>
            <translation>%1 kann nicht geändert werden.</translation>
        </message>
        <message>
            <source>VAR_IN_OUT %1 of %2 may change the variable it is given</source>
            <translation>VAR_IN_OUT %1 von %2 darf die übergebene Variable ändern</translation>
        </message>
        <message>
            <source>VAR_IN_OUT %1 of %2 needs a variable of type %3, not %4.</source>
            <translation>VAR_IN_OUT %1 von %2 braucht eine Variable vom Typ %3, nicht %4.</translation>
        </message>
        <message>
            <source>VAR_IN_OUT passes the variable itself, so no conversion is possible; use a variable of type %1</source>
            <translation>VAR_IN_OUT übergibt die Variable selbst, daher ist keine Konvertierung möglich; verwenden Sie eine Variable vom Typ %1</translation>
        </message>
        <message>
            <source>A call gives either all its arguments by name or none; here only some have a name.</source>
            <translation>Ein Aufruf gibt entweder alle Argumente mit Namen an oder keines; hier haben nur einige einen Namen.</translation>
        </message>
        <message>
            <source>write each argument as name := value</source>
            <translation>schreiben Sie jedes Argument als Name := Wert</translation>
        </message>
        <message>
            <source>pass it in every call, e.g. %1(%2 := variable)</source>
            <translation>übergeben Sie sie bei jedem Aufruf, z. B. %1(%2 := Variable)</translation>
        </message>
        <message>
            <source>This FOR loop ends by setting %1 to %2, outside its range %3..%4, which stops the program.</source>
            <translation>Diese FOR-Schleife endet, indem sie %1 auf %2 setzt, außerhalb des Bereichs %3..%4; das hält das Programm an.</translation>
        </message>
        <message>
            <source>This FOR loop ends by setting %1 beyond %2, outside its range %3..%4, which stops the program.</source>
            <translation>Diese FOR-Schleife endet, indem sie %1 über %2 hinaus setzt, außerhalb des Bereichs %3..%4; das hält das Programm an.</translation>
        </message>
        <message>
            <source>give %1 a type with room for the value that ends the loop</source>
            <translation>geben Sie %1 einen Typ, der auch den Wert aufnimmt, mit dem die Schleife endet</translation>
        </message>
        <message>
            <source>This FOR loop never ends: %1 wraps around before it can pass %2.</source>
            <translation>Diese FOR-Schleife endet nie: %1 läuft über, bevor es %2 überschreiten kann.</translation>
        </message>
        <message>
            <source>use a larger type than %1 for %2</source>
            <translation>verwenden Sie für %2 einen größeren Typ als %1</translation>
        </message>
        <message>
            <source>The case value %1 is already handled on line %2; only the first branch runs for it.</source>
            <translation>Der CASE-Wert %1 wird bereits in Zeile %2 behandelt; nur der erste Zweig wird für ihn ausgeführt.</translation>
        </message>
        <message>
            <source>The value %1 does not fit into %2.</source>
            <translation>Der Wert %1 passt nicht in %2.</translation>
        </message>
        <message>
            <source>The global list %1 has no variable %2.</source>
            <translation>Die globale Variablenliste %1 hat keine Variable %2.</translation>
        </message>
        <message>
            <source>The pragma {%1} means nothing to IEC Studio; it is ignored.</source>
            <translation>Das Pragma {%1} hat für IEC Studio keine Bedeutung; es wird ignoriert.</translation>
        </message>
        <message>
            <source>the name it extends</source>
            <translation>den Namen, den es erweitert</translation>
        </message>
        <message>
            <source>the name of an interface</source>
            <translation>den Namen einer Schnittstelle</translation>
        </message>
        <message>
            <source>the name of the method</source>
            <translation>den Namen der Methode</translation>
        </message>
        <message>
            <source>The method %1 has no END_METHOD.</source>
            <translation>Der Methode %1 fehlt END_METHOD.</translation>
        </message>
        <message>
            <source>the name of the property</source>
            <translation>den Namen der Eigenschaft</translation>
        </message>
        <message>
            <source>':' and the type of the property</source>
            <translation>':' und den Typ der Eigenschaft</translation>
        </message>
        <message>
            <source>The property %1 has no END_PROPERTY.</source>
            <translation>Der Eigenschaft %1 fehlt END_PROPERTY.</translation>
        </message>
        <message>
            <source>This expression is nested too deeply (more than %1 levels).</source>
            <translation>Dieser Ausdruck ist zu tief verschachtelt (mehr als %1 Ebenen).</translation>
        </message>
        <message>
            <source>split it into several statements, with variables for the parts</source>
            <translation>teilen Sie ihn in mehrere Anweisungen auf, mit Variablen für die Teile</translation>
        </message>
        <message>
            <source>These statements are nested too deeply (more than %1 levels).</source>
            <translation>Diese Anweisungen sind zu tief verschachtelt (mehr als %1 Ebenen).</translation>
        </message>
        <message>
            <source>move the inner blocks into a function, a function block or an action</source>
            <translation>verschieben Sie die inneren Blöcke in eine Funktion, einen Funktionsbaustein oder eine Aktion</translation>
        </message>
        <message>
            <source>This type is nested too deeply (more than %1 levels).</source>
            <translation>Dieser Typ ist zu tief verschachtelt (mehr als %1 Ebenen).</translation>
        </message>
        <message>
            <source>declare the inner types as types of their own in a TYPE block</source>
            <translation>deklarieren Sie die inneren Typen als eigene Typen in einem TYPE-Block</translation>
        </message>
        <message>
            <source>This initial value is nested too deeply (more than %1 levels).</source>
            <translation>Dieser Initialwert ist zu tief verschachtelt (mehr als %1 Ebenen).</translation>
        </message>
        <message>
            <source>This is nested too deeply to compile.</source>
            <translation>Dies ist zu tief verschachtelt, um übersetzt zu werden.</translation>
        </message>
        <message>
            <source>split it into simpler steps: constants, types and function blocks defined in fewer steps, expressions with fewer levels</source>
            <translation>zerlegen Sie es in einfachere Teile: Konstanten, Typen und Funktionsbausteine in weniger Stufen definiert, Ausdrücke mit weniger Ebenen</translation>
        </message>
        <message>
            <source>%1 is FINAL; no function block can extend it.</source>
            <translation>%1 ist FINAL; kein Funktionsbaustein kann ihn erweitern.</translation>
        </message>
        <message>
            <source>%1 extends %2, which is no function block.</source>
            <translation>%1 erweitert %2, das kein Funktionsbaustein ist.</translation>
        </message>
        <message>
            <source>%1 is ABSTRACT; declare an instance of a function block that extends it.</source>
            <translation>%1 ist ABSTRACT; deklarieren Sie eine Instanz eines Funktionsbausteins, der ihn erweitert.</translation>
        </message>
        <message>
            <source>A %1 starts at 0; set it in the code instead (p := ADR(x); or r REF= x;).</source>
            <translation>Ein %1 beginnt mit 0; setzen Sie ihn stattdessen im Code (p := ADR(x); oder r REF= x;).</translation>
        </message>
        <message>
            <source>This constant is defined in terms of itself.</source>
            <translation>Diese Konstante ist durch sich selbst definiert.</translation>
        </message>
        <message>
            <source>%1 combines BOOL values, not %2.</source>
            <translation>%1 verknüpft BOOL-Werte, nicht %2.</translation>
        </message>
        <message>
            <source>Implicit conversion from %1 to %2: possible loss of information.</source>
            <translation>Implizite Konvertierung von %1 nach %2: möglicher Informationsverlust.</translation>
        </message>
        <message>
            <source>Implicit conversion from signed type %1 to unsigned type %2: possible change of sign.</source>
            <translation>Implizite Konvertierung vom vorzeichenbehafteten Typ %1 in den vorzeichenlosen Typ %2: mögliche Vorzeichenänderung.</translation>
        </message>
        <message>
            <source>Implicit conversion from unsigned type %1 to signed type %2: possible change of sign.</source>
            <translation>Implizite Konvertierung vom vorzeichenlosen Typ %1 in den vorzeichenbehafteten Typ %2: mögliche Vorzeichenänderung.</translation>
        </message>
        <message>
            <source>SUPER^() calls the body of the block this one extends; it is only known in such a block's body.</source>
            <translation>SUPER^() ruft den Rumpf des Bausteins auf, den dieser erweitert; es ist nur im Rumpf eines solchen Bausteins bekannt.</translation>
        </message>
        <message>
            <source>A program call is a statement of its own.</source>
            <translation>Ein Programmaufruf ist eine eigene Anweisung.</translation>
        </message>
        <message>
            <source>call %1(...); then read its outputs, e.g. %1.Out</source>
            <translation>rufen Sie %1(...); auf und lesen Sie dann seine Ausgänge, z. B. %1.Out</translation>
        </message>
        <message>
            <source>The program %1 runs in %2 instances; its name alone does not say which.</source>
            <translation>Das Programm %1 läuft in %2 Instanzen; sein Name allein sagt nicht, welche gemeint ist.</translation>
        </message>
        <message>
            <source>give each instance its own program, or reach the values through a global variable</source>
            <translation>geben Sie jeder Instanz ein eigenes Programm, oder greifen Sie über eine globale Variable auf die Werte zu</translation>
        </message>
        <message>
            <source>(the current result at label %1)</source>
            <translation>(das aktuelle Ergebnis an der Marke %1)</translation>
        </message>
        <message>
            <source>%1 is a %2, not a pointer; only a pointer is dereferenced with ^.</source>
            <translation>%1 ist ein %2, kein Pointer; nur ein Pointer wird mit ^ dereferenziert.</translation>
        </message>
        <message>
            <source>%1 needs a variable (not a constant or a single bit).</source>
            <translation>%1 braucht eine Variable (keine Konstante und kein einzelnes Bit).</translation>
        </message>
        <message>
            <source>__ISVALIDREF needs a REFERENCE TO variable, not %1.</source>
            <translation>__ISVALIDREF braucht eine REFERENCE TO-Variable, nicht %1.</translation>
        </message>
        <message>
            <source>REF= needs a REFERENCE TO variable on its left, not %1.</source>
            <translation>REF= braucht links eine REFERENCE TO-Variable, nicht %1.</translation>
        </message>
        <message>
            <source>to assign a value write :=</source>
            <translation>um einen Wert zuzuweisen, schreiben Sie :=</translation>
        </message>
        <message>
            <source>%1 can refer to a variable of type %2, not to %3.</source>
            <translation>%1 kann auf eine Variable vom Typ %2 verweisen, nicht auf %3.</translation>
        </message>
        <message>
            <source>a constant</source>
            <translation>eine Konstante</translation>
        </message>
        <message>
            <source>A pointer can only be moved with + and -, and compared.</source>
            <translation>Ein Pointer kann nur mit + und - verschoben und verglichen werden.</translation>
        </message>
        <message>
            <source>Two pointers cannot be added; add a number of bytes to one.</source>
            <translation>Zwei Pointer können nicht addiert werden; addieren Sie eine Anzahl Bytes zu einem.</translation>
        </message>
        <message>
            <source>the OpenPLC TCP socket library</source>
            <translation>die TCP-Socket-Bibliothek von OpenPLC</translation>
        </message>
        <message>
            <source>an MQTT library</source>
            <translation>eine MQTT-Bibliothek</translation>
        </message>
        <message>
            <source>CODESYS SoftMotion (PLCopen motion control)</source>
            <translation>CODESYS SoftMotion (PLCopen Motion Control)</translation>
        </message>
        <message>
            <source>CODESYS SoftMotion</source>
            <translation>CODESYS SoftMotion</translation>
        </message>
        <message>
            <source>the OpenPLC UDP socket library</source>
            <translation>die UDP-Socket-Bibliothek von OpenPLC</translation>
        </message>
        <message>
            <source>Beremiz's Python blocks</source>
            <translation>die Python-Bausteine von Beremiz</translation>
        </message>
        <message>
            <source>%1 is a block of %2, which IEC Studio does not have; the POUs that use it cannot run.</source>
            <translation>%1 ist ein Baustein aus %2, das IEC Studio nicht hat; die POEs, die ihn verwenden, können nicht laufen.</translation>
        </message>
        <message>
            <source>the rest of the project is still checked and runs</source>
            <translation>der Rest des Projekts wird trotzdem geprüft und läuft</translation>
        </message>
        <message>
            <source>%1 cannot run: %2 uses %3.</source>
            <translation>%1 kann nicht laufen: %2 verwendet %3.</translation>
        </message>
        <message>
            <source>%1 has two methods or properties called %2.</source>
            <translation>%1 hat zwei Methoden oder Eigenschaften namens %2.</translation>
        </message>
        <message>
            <source>%1 is %2 and cannot be called from here.</source>
            <translation>%1 ist %2 und kann von hier nicht aufgerufen werden.</translation>
        </message>
        <message>
            <source>SUPER is only known in a function block that EXTENDS another one.</source>
            <translation>SUPER ist nur in einem Funktionsbaustein bekannt, der einen anderen erweitert (EXTENDS).</translation>
        </message>
        <message>
            <source>THIS is only known in a function block and its methods.</source>
            <translation>THIS ist nur in einem Funktionsbaustein und seinen Methoden bekannt.</translation>
        </message>
        <message>
            <source>No function block implements %1.%2, so it cannot be called.</source>
            <translation>Kein Funktionsbaustein implementiert %1.%2, daher kann es nicht aufgerufen werden.</translation>
        </message>
        <message>
            <source>%1 is ABSTRACT and has no code to run.</source>
            <translation>%1 ist ABSTRACT und hat keinen Code, der laufen kann.</translation>
        </message>
        <message>
            <source>The property %1 has no SET and cannot be written.</source>
            <translation>Die Eigenschaft %1 hat kein SET und kann nicht geschrieben werden.</translation>
        </message>
        <message>
            <source>The property %1 has no GET and cannot be read.</source>
            <translation>Die Eigenschaft %1 hat kein GET und kann nicht gelesen werden.</translation>
        </message>
        <message>
            <source>%1 does not extend %2.</source>
            <translation>%1 erweitert %2 nicht.</translation>
        </message>
        <message>
            <source>%1 does not implement %2.</source>
            <translation>%1 implementiert %2 nicht.</translation>
        </message>
        <message>
            <source>%1 is an SFC chart that contains itself.</source>
            <translation>%1 ist ein AS-Ablaufplan, der sich selbst enthält.</translation>
        </message>
        <message>
            <source>This IL condition is nested too deeply (more than %1 levels).</source>
            <translation>Diese AWL-Bedingung ist zu tief verschachtelt (mehr als %1 Ebenen).</translation>
        </message>
        <message>
            <source>The action %1 of step %2 is a variable of type %3; it is 1 while the action is active and 0 otherwise.</source>
            <translation>Die Aktion %1 von Schritt %2 ist eine Variable vom Typ %3; sie ist 1, solange die Aktion aktiv ist, sonst 0.</translation>
        </message>
        <message>
            <source>%1 is a program, not a type; only function blocks can be instantiated.</source>
            <translation>%1 ist ein Programm, kein Typ; nur Funktionsbausteine können instanziiert werden.</translation>
        </message>
        <message>
            <source>%1 is a function, not a type; only function blocks can be instantiated.</source>
            <translation>%1 ist eine Funktion, kein Typ; nur Funktionsbausteine können instanziiert werden.</translation>
        </message>
        <message>
            <source>%1 is written in %2, which has no IEC text form; its body was left out.</source>
            <translation>%1 ist in %2 geschrieben, das keine IEC-Textform hat; sein Rumpf wurde weggelassen.</translation>
        </message>
        <message>
            <source>The entry, exit and active actions and the times of steps %1 have no IEC text form and were left out.</source>
            <translation>Die Eingangs-, Ausgangs- und aktiven Aktionen sowie die Zeiten der Schritte %1 haben keine IEC-Textform und wurden weggelassen.</translation>
        </message>
        <message>
            <source>VAR_CONFIG cannot be stored in a PLCopen project yet and was left out.</source>
            <translation>VAR_CONFIG kann noch nicht in einem PLCopen-Projekt gespeichert werden und wurde weggelassen.</translation>
        </message>
        <message>
            <source>The priority of task %1 must be a number from 0 to 65535; 0 is used.</source>
            <translation>Die Priorität der Task %1 muss eine Zahl von 0 bis 65535 sein; 0 wird verwendet.</translation>
        </message>
        <message>
            <source>The arguments of program instance %1 cannot be stored in a PLCopen project and were left out.</source>
            <translation>Die Argumente der Programminstanz %1 können nicht in einem PLCopen-Projekt gespeichert werden und wurden weggelassen.</translation>
        </message>
        <message>
            <source>VAR_GLOBAL outside a CONFIGURATION cannot be stored in a PLCopen project; put it inside the CONFIGURATION.</source>
            <translation>VAR_GLOBAL außerhalb einer CONFIGURATION kann nicht in einem PLCopen-Projekt gespeichert werden; setzen Sie es in die CONFIGURATION.</translation>
        </message>
        <message>
            <source>The vendor element '%1' cannot run in this version.</source>
            <translation>Das herstellerspezifische Element '%1' kann in dieser Version nicht laufen.</translation>
        </message>
        <message>
            <source>This element could not be read from the file, so it cannot run.</source>
            <translation>Dieses Element konnte nicht aus der Datei gelesen werden und kann daher nicht laufen.</translation>
        </message>
        <message>
            <source>A %1 belongs in an SFC chart, not in an LD or FBD network.</source>
            <translation>Ein Element vom Typ %1 gehört in einen AS-Ablaufplan, nicht in ein KOP- oder FUP-Netzwerk.</translation>
        </message>
        <message>
            <source>Two labels are called '%1'.</source>
            <translation>Zwei Marken heißen '%1'.</translation>
        </message>
        <message>
            <source>rename one of them</source>
            <translation>benennen Sie eine davon um</translation>
        </message>
        <message>
            <source>This condition</source>
            <translation>Diese Bedingung</translation>
        </message>
        <message>
            <source>comment</source>
            <translation>Kommentar</translation>
        </message>
        <message>
            <source>unreadable element</source>
            <translation>unlesbares Element</translation>
        </message>
        <message>
            <source>connector</source>
            <translation>Konnektor</translation>
        </message>
        <message>
            <source>continuation</source>
            <translation>Fortsetzung</translation>
        </message>
        <message>
            <source>action block</source>
            <translation>Aktionsblock</translation>
        </message>
        <message>
            <source>vendor element</source>
            <translation>herstellerspezifisches Element</translation>
        </message>
        <message>
            <source>block</source>
            <translation>Baustein</translation>
        </message>
        <message>
            <source>input variable</source>
            <translation>Eingangsvariable</translation>
        </message>
        <message>
            <source>output variable</source>
            <translation>Ausgangsvariable</translation>
        </message>
        <message>
            <source>in-out variable</source>
            <translation>Ein-/Ausgangsvariable</translation>
        </message>
        <message>
            <source>label</source>
            <translation>Marke</translation>
        </message>
        <message>
            <source>jump</source>
            <translation>Sprung</translation>
        </message>
        <message>
            <source>return</source>
            <translation>Rücksprung</translation>
        </message>
        <message>
            <source>left power rail</source>
            <translation>linke Stromschiene</translation>
        </message>
        <message>
            <source>right power rail</source>
            <translation>rechte Stromschiene</translation>
        </message>
        <message>
            <source>coil</source>
            <translation>Spule</translation>
        </message>
        <message>
            <source>contact</source>
            <translation>Kontakt</translation>
        </message>
        <message>
            <source>step</source>
            <translation>Schritt</translation>
        </message>
        <message>
            <source>macro step</source>
            <translation>Makroschritt</translation>
        </message>
        <message>
            <source>transition</source>
            <translation>Transition</translation>
        </message>
        <message>
            <source>selection divergence</source>
            <translation>Alternativverzweigung</translation>
        </message>
        <message>
            <source>selection convergence</source>
            <translation>Alternativzusammenführung</translation>
        </message>
        <message>
            <source>simultaneous divergence</source>
            <translation>Parallelverzweigung</translation>
        </message>
        <message>
            <source>simultaneous convergence</source>
            <translation>Parallelzusammenführung</translation>
        </message>
        <message>
            <source>An element has no variable or value written in it.</source>
            <translation>In einem Element steht keine Variable und kein Wert.</translation>
        </message>
        <message>
            <source>enter a variable name or a constant</source>
            <translation>geben Sie einen Variablennamen oder eine Konstante ein</translation>
        </message>
        <message>
            <source>'%1' is not a variable or an expression.</source>
            <translation>'%1' ist keine Variable und kein Ausdruck.</translation>
        </message>
        <message>
            <source>write a name such as Motor, Tank.Level or %QX0.1, or a constant such as T#5s</source>
            <translation>schreiben Sie einen Namen wie Motor, Tank.Level oder %QX0.1 oder eine Konstante wie T#5s</translation>
        </message>
        <message>
            <source>Two elements have the same localId %1.</source>
            <translation>Zwei Elemente haben dieselbe localId %1.</translation>
        </message>
        <message>
            <source>give every element its own localId</source>
            <translation>geben Sie jedem Element eine eigene localId</translation>
        </message>
        <message>
            <source>There is no connector named '%1' for this continuation.</source>
            <translation>Es gibt keinen Konnektor namens '%1' für diese Fortsetzung.</translation>
        </message>
        <message>
            <source>add a connector with that name where the wire starts</source>
            <translation>fügen Sie dort, wo die Verbindung beginnt, einen Konnektor mit diesem Namen ein</translation>
        </message>
        <message>
            <source>The wires make a loop through %1 elements with no variable to keep the value from one scan to the next.</source>
            <translation>Die Verbindungen bilden eine Schleife über %1 Elemente ohne Variable, die den Wert von einem Zyklus zum nächsten hält.</translation>
        </message>
        <message>
            <source>put a feedback variable (an in-out variable) into the loop</source>
            <translation>setzen Sie eine Rückkopplungsvariable (eine Ein-/Ausgangsvariable) in die Schleife</translation>
        </message>
        <message>
            <source>%1 cannot be used in a condition wired into a chart.</source>
            <translation>%1 kann nicht in einer Bedingung verwendet werden, die im Ablaufplan verdrahtet ist.</translation>
        </message>
        <message>
            <source>write the condition as a named transition instead</source>
            <translation>schreiben Sie die Bedingung stattdessen als benannte Transition</translation>
        </message>
        <message>
            <source>A wire comes from element %1, which is not in this diagram.</source>
            <translation>Eine Verbindung kommt von Element %1, das nicht in diesem Diagramm ist.</translation>
        </message>
        <message>
            <source>A wire comes from an element that gives no value (%1).</source>
            <translation>Eine Verbindung kommt von einem Element, das keinen Wert liefert (%1).</translation>
        </message>
        <message>
            <source>A wire comes from the output '%1', which %2 does not have.</source>
            <translation>Eine Verbindung kommt vom Ausgang '%1', den %2 nicht hat.</translation>
        </message>
        <message>
            <source>A wire comes from a %1, which gives no value.</source>
            <translation>Eine Verbindung kommt von einem Element vom Typ %1, das keinen Wert liefert.</translation>
        </message>
        <message>
            <source>draw a wire to it</source>
            <translation>ziehen Sie eine Verbindung dorthin</translation>
        </message>
        <message>
            <source>%1 wires end at one input; an input takes exactly one.</source>
            <translation>%1 Verbindungen enden an einem Eingang; ein Eingang nimmt genau eine.</translation>
        </message>
        <message>
            <source>combine them with an OR block</source>
            <translation>verknüpfen Sie sie mit einem OR-Baustein</translation>
        </message>
        <message>
            <source>%1 is not connected.</source>
            <translation>%1 ist nicht verbunden.</translation>
        </message>
        <message>
            <source>An edge detection</source>
            <translation>Eine Flankenerkennung</translation>
        </message>
        <message>
            <source>Nothing is wired to the connector '%1'.</source>
            <translation>Mit dem Konnektor '%1' ist nichts verbunden.</translation>
        </message>
        <message>
            <source>The contact '%1' has no wire on its left.</source>
            <translation>Der Kontakt '%1' hat links keine Verbindung.</translation>
        </message>
        <message>
            <source>The coil '%1' has no wire on its left.</source>
            <translation>Die Spule '%1' hat links keine Verbindung.</translation>
        </message>
        <message>
            <source>A coil</source>
            <translation>Eine Spule</translation>
        </message>
        <message>
            <source>Nothing is wired to the output '%1'.</source>
            <translation>Mit dem Ausgang '%1' ist nichts verbunden.</translation>
        </message>
        <message>
            <source>An output variable</source>
            <translation>Eine Ausgangsvariable</translation>
        </message>
        <message>
            <source>A variable that is written</source>
            <translation>Eine beschriebene Variable</translation>
        </message>
        <message>
            <source>The input %1 of %2 is not connected.</source>
            <translation>Der Eingang %1 von %2 ist nicht verbunden.</translation>
        </message>
        <message>
            <source>draw a wire to it or write a constant</source>
            <translation>ziehen Sie eine Verbindung dorthin oder schreiben Sie eine Konstante</translation>
        </message>
        <message>
            <source>A function block</source>
            <translation>Ein Funktionsbaustein</translation>
        </message>
        <message>
            <source>Only the result of the function %1 can be wired; its output %2 cannot yet.</source>
            <translation>Nur das Ergebnis der Funktion %1 kann verbunden werden; ihr Ausgang %2 noch nicht.</translation>
        </message>
        <message>
            <source>call %1 from ST to use its other outputs</source>
            <translation>rufen Sie %1 aus ST auf, um seine anderen Ausgänge zu verwenden</translation>
        </message>
        <message>
            <source>A function call</source>
            <translation>Ein Funktionsaufruf</translation>
        </message>
        <message>
            <source>A function with EN</source>
            <translation>Eine Funktion mit EN</translation>
        </message>
        <message>
            <source>The result type of %1 cannot be told here, so it cannot run under EN.</source>
            <translation>Der Ergebnistyp von %1 ist hier nicht bestimmbar, daher kann es nicht unter EN laufen.</translation>
        </message>
        <message>
            <source>wire its output to a variable, or leave EN open</source>
            <translation>verbinden Sie seinen Ausgang mit einer Variablen oder lassen Sie EN offen</translation>
        </message>
        <message>
            <source>This EXECUTE box holds no ST code.</source>
            <translation>Dieser EXECUTE-Baustein enthält keinen ST-Code.</translation>
        </message>
        <message>
            <source>The ST code of this EXECUTE box does not parse: %1</source>
            <translation>Der ST-Code dieses EXECUTE-Bausteins ist fehlerhaft: %1</translation>
        </message>
        <message>
            <source>An EXECUTE box</source>
            <translation>Ein EXECUTE-Baustein</translation>
        </message>
        <message>
            <source>The jump to '%1' has no condition wired to it.</source>
            <translation>Mit dem Sprung zu '%1' ist keine Bedingung verbunden.</translation>
        </message>
        <message>
            <source>There is no label '%1' to jump to.</source>
            <translation>Es gibt keine Marke '%1', zu der gesprungen werden kann.</translation>
        </message>
        <message>
            <source>add a label with that name, or correct the jump</source>
            <translation>fügen Sie eine Marke mit diesem Namen ein oder korrigieren Sie den Sprung</translation>
        </message>
        <message>
            <source>A jump</source>
            <translation>Ein Sprung</translation>
        </message>
        <message>
            <source>The return has no condition wired to it.</source>
            <translation>Mit dem Rücksprung ist keine Bedingung verbunden.</translation>
        </message>
        <message>
            <source>A return</source>
            <translation>Ein Rücksprung</translation>
        </message>
        <message>
            <source>A step has no name.</source>
            <translation>Ein Schritt hat keinen Namen.</translation>
        </message>
        <message>
            <source>give every step a unique name</source>
            <translation>geben Sie jedem Schritt einen eindeutigen Namen</translation>
        </message>
        <message>
            <source>Two steps are called %1; every step of a chart needs its own name.</source>
            <translation>Zwei Schritte heißen %1; jeder Schritt eines Ablaufplans braucht einen eigenen Namen.</translation>
        </message>
        <message>
            <source>Macro step %1 has no steps inside.</source>
            <translation>Der Makroschritt %1 enthält keine Schritte.</translation>
        </message>
        <message>
            <source>The transition is connected to element %1, which the chart does not have.</source>
            <translation>Die Transition ist mit Element %1 verbunden, das der Ablaufplan nicht hat.</translation>
        </message>
        <message>
            <source>A transition must come after a step, a selection divergence or a simultaneous convergence, not after a %1.</source>
            <translation>Eine Transition muss auf einen Schritt, eine Alternativverzweigung oder eine Parallelzusammenführung folgen, nicht auf ein Element vom Typ %1.</translation>
        </message>
        <message>
            <source>Two transitions follow each other; put a step between them.</source>
            <translation>Zwei Transitionen folgen aufeinander; setzen Sie einen Schritt dazwischen.</translation>
        </message>
        <message>
            <source>A transition must lead to a step, a jump, a simultaneous divergence or a selection convergence, not to a %1.</source>
            <translation>Eine Transition muss zu einem Schritt, einem Sprung, einer Parallelverzweigung oder einer Alternativzusammenführung führen, nicht zu einem Element vom Typ %1.</translation>
        </message>
        <message>
            <source>This transition has no step before it.</source>
            <translation>Vor dieser Transition steht kein Schritt.</translation>
        </message>
        <message>
            <source>connect it below a step</source>
            <translation>verbinden Sie sie unterhalb eines Schritts</translation>
        </message>
        <message>
            <source>This transition leads to no step.</source>
            <translation>Diese Transition führt zu keinem Schritt.</translation>
        </message>
        <message>
            <source>connect a step or a jump below it</source>
            <translation>verbinden Sie darunter einen Schritt oder einen Sprung</translation>
        </message>
        <message>
            <source>This transition has no condition.</source>
            <translation>Diese Transition hat keine Bedingung.</translation>
        </message>
        <message>
            <source>write a condition such as TRUE or Start AND NOT Stop</source>
            <translation>schreiben Sie eine Bedingung wie TRUE oder Start AND NOT Stop</translation>
        </message>
        <message>
            <source>Step %1 has no transition after it.</source>
            <translation>Nach Schritt %1 folgt keine Transition.</translation>
        </message>
        <message>
            <source>add a transition below it, or a jump back</source>
            <translation>fügen Sie darunter eine Transition oder einen Rücksprung ein</translation>
        </message>
        <message>
            <source>The jump goes to step %1, which the chart does not have.</source>
            <translation>Der Sprung führt zu Schritt %1, den der Ablaufplan nicht hat.</translation>
        </message>
        <message>
            <source>Each branch of a selection divergence must begin with a transition, not a %1.</source>
            <translation>Jeder Zweig einer Alternativverzweigung muss mit einer Transition beginnen, nicht mit einem Element vom Typ %1.</translation>
        </message>
        <message>
            <source>A selection divergence must come after a step, not after a %1.</source>
            <translation>Eine Alternativverzweigung muss auf einen Schritt folgen, nicht auf ein Element vom Typ %1.</translation>
        </message>
        <message>
            <source>Each branch of a simultaneous divergence must begin with a step, not a %1.</source>
            <translation>Jeder Zweig einer Parallelverzweigung muss mit einem Schritt beginnen, nicht mit einem Element vom Typ %1.</translation>
        </message>
        <message>
            <source>A simultaneous divergence must come after a transition, not after a %1.</source>
            <translation>Eine Parallelverzweigung muss auf eine Transition folgen, nicht auf ein Element vom Typ %1.</translation>
        </message>
        <message>
            <source>Each branch of a selection convergence must end with a transition, not a %1.</source>
            <translation>Jeder Zweig einer Alternativzusammenführung muss mit einer Transition enden, nicht mit einem Element vom Typ %1.</translation>
        </message>
        <message>
            <source>A selection convergence must lead to a step, not to a %1.</source>
            <translation>Eine Alternativzusammenführung muss zu einem Schritt führen, nicht zu einem Element vom Typ %1.</translation>
        </message>
        <message>
            <source>Each branch of a simultaneous convergence must end with a step, not a %1.</source>
            <translation>Jeder Zweig einer Parallelzusammenführung muss mit einem Schritt enden, nicht mit einem Element vom Typ %1.</translation>
        </message>
        <message>
            <source>A simultaneous convergence must lead to a transition, not to a %1.</source>
            <translation>Eine Parallelzusammenführung muss zu einer Transition führen, nicht zu einem Element vom Typ %1.</translation>
        </message>
        <message>
            <source>This action block is not connected to a step.</source>
            <translation>Dieser Aktionsblock ist mit keinem Schritt verbunden.</translation>
        </message>
        <message>
            <source>An action block must be connected to a step.</source>
            <translation>Ein Aktionsblock muss mit einem Schritt verbunden sein.</translation>
        </message>
        <message>
            <source>This action of step %1 names no action.</source>
            <translation>Diese Aktion von Schritt %1 nennt keine Aktion.</translation>
        </message>
        <message>
            <source>%1 is not an action qualifier; use N, R, S, L, D, P, P0, P1, SD, DS or SL.</source>
            <translation>%1 ist kein Aktionsbestimmungszeichen; verwenden Sie N, R, S, L, D, P, P0, P1, SD, DS oder SL.</translation>
        </message>
        <message>
            <source>The qualifier %1 of action %2 needs a duration, e.g. T#5s.</source>
            <translation>Das Bestimmungszeichen %1 der Aktion %2 braucht eine Zeitdauer, z. B. T#5s.</translation>
        </message>
        <message>
            <source>The chart of %1 has no initial step.</source>
            <translation>Der Ablaufplan von %1 hat keinen Initialschritt.</translation>
        </message>
        <message>
            <source>make one step the initial step (double frame)</source>
            <translation>machen Sie einen Schritt zum Initialschritt (doppelter Rahmen)</translation>
        </message>
        <message>
            <source>Step %1 is a second initial step; a chart has exactly one (the first is %2).</source>
            <translation>Schritt %1 ist ein zweiter Initialschritt; ein Ablaufplan hat genau einen (der erste ist %2).</translation>
        </message>
        <message>
            <source>The chart's code for this element does not parse: %1</source>
            <translation>Der Code des Ablaufplans für dieses Element ist fehlerhaft: %1</translation>
        </message>
        <message>
            <source>%1 is the name of a variable and of the chart's implicit variable; rename one of them.</source>
            <translation>%1 ist der Name einer Variablen und einer impliziten Variablen des Ablaufplans; benennen Sie eine davon um.</translation>
        </message>
        <message>
            <source>The chart's variables cannot be declared: %1</source>
            <translation>Die Variablen des Ablaufplans können nicht deklariert werden: %1</translation>
        </message>
        <message>
            <source>This inline action is written in IL; an inline action must be written in ST, LD or FBD.</source>
            <translation>Diese Inline-Aktion ist in AWL geschrieben; eine Inline-Aktion muss in ST, KOP oder FUP geschrieben sein.</translation>
        </message>
        <message>
            <source>make it an action of %1 and name it in the step</source>
            <translation>machen Sie sie zu einer Aktion von %1 und nennen Sie sie im Schritt</translation>
        </message>
        <message>
            <source>Step %1 runs action %2, which %3 does not have.</source>
            <translation>Schritt %1 führt die Aktion %2 aus, die %3 nicht hat.</translation>
        </message>
        <message>
            <source>This IL condition uses jumps, parentheses or calls, which a transition cannot run yet.</source>
            <translation>Diese AWL-Bedingung verwendet Sprünge, Klammern oder Aufrufe, die eine Transition noch nicht ausführen kann.</translation>
        </message>
        <message>
            <source>write the condition as an ST expression</source>
            <translation>schreiben Sie die Bedingung als ST-Ausdruck</translation>
        </message>
        <message>
            <source>A graphical transition condition needs a name: its network assigns that name.</source>
            <translation>Eine grafische Transitionsbedingung braucht einen Namen: ihr Netzwerk weist diesen Namen zu.</translation>
        </message>
        <message>
            <source>A transition condition cannot be an SFC chart.</source>
            <translation>Eine Transitionsbedingung kann kein AS-Ablaufplan sein.</translation>
        </message>
        <message>
            <source>The transition refers to %1, which is neither a transition of %2 nor a variable.</source>
            <translation>Die Transition verweist auf %1, das weder eine Transition von %2 noch eine Variable ist.</translation>
        </message>
        <message>
            <source>The condition of this transition is not connected.</source>
            <translation>Die Bedingung dieser Transition ist nicht verbunden.</translation>
        </message>
        <message>
            <source>The condition %1 is not an expression: %2</source>
            <translation>Die Bedingung %1 ist kein Ausdruck: %2</translation>
        </message>
        <message>
            <source>%1 %2 is not a TIME literal or variable.</source>
            <translation>%1 %2 ist kein TIME-Literal und keine Variable.</translation>
        </message>
        <message>
            <source>write e.g. T#5s</source>
            <translation>schreiben Sie z. B. T#5s</translation>
        </message>
        <message>
            <source>The maximum time</source>
            <translation>Die Maximalzeit</translation>
        </message>
        <message>
            <source>The minimum time</source>
            <translation>Die Minimalzeit</translation>
        </message>
        <message>
            <source>The duration</source>
            <translation>Die Zeitdauer</translation>
        </message>
        <message>
            <source>%1 is a function written in SFC; a chart keeps its state, so it must be a program or a function block.</source>
            <translation>%1 ist eine in AS geschriebene Funktion; ein Ablaufplan behält seinen Zustand, daher muss er ein Programm oder ein Funktionsbaustein sein.</translation>
        </message>
        <message>
            <source>Two steps are called %1.</source>
            <translation>Zwei Schritte heißen %1.</translation>
        </message>
        <message>
            <source>The transition refers to step %1, which the chart does not have.</source>
            <translation>Die Transition verweist auf Schritt %1, den der Ablaufplan nicht hat.</translation>
        </message>
        <message>
            <source>This selection divergence needs at least two branches; it has %1.</source>
            <translation>Diese Alternativverzweigung braucht mindestens zwei Zweige; sie hat %1.</translation>
        </message>
        <message>
            <source>This simultaneous divergence needs at least two branches; it has %1.</source>
            <translation>Diese Parallelverzweigung braucht mindestens zwei Zweige; sie hat %1.</translation>
        </message>
        <message>
            <source>This selection convergence needs at least two branches; it joins %1.</source>
            <translation>Diese Alternativzusammenführung braucht mindestens zwei Zweige; sie führt %1 zusammen.</translation>
        </message>
        <message>
            <source>This simultaneous convergence needs at least two branches; it joins %1.</source>
            <translation>Diese Parallelzusammenführung braucht mindestens zwei Zweige; sie führt %1 zusammen.</translation>
        </message>
        <message>
            <source>The condition %1 is incomplete: something is missing at its end.</source>
            <translation>Die Bedingung %1 ist unvollständig: An ihrem Ende fehlt etwas.</translation>
        </message>
        <message>
            <source>The type of the value this loop carries cannot be told.</source>
            <translation>Der Typ des Werts, den diese Schleife weitergibt, lässt sich nicht bestimmen.</translation>
        </message>
        <message>
            <source>wire the loop through a variable of the type you mean</source>
            <translation>führen Sie die Schleife über eine Variable des gemeinten Typs</translation>
        </message>
        <message>
            <source>Write one METHOD ... END_METHOD or one PROPERTY ... END_PROPERTY here, and nothing before or after it.</source>
            <translation>Schreiben Sie hier genau ein METHOD ... END_METHOD oder ein PROPERTY ... END_PROPERTY und nichts davor oder danach.</translation>
        </message>
        <message>
            <source>The text holds the control character U+%1, which a project file cannot keep; remove it.</source>
            <translation>Der Text enthält das Steuerzeichen U+%1, das eine Projektdatei nicht speichern kann; entfernen Sie es.</translation>
        </message>
        <message>
            <source>%1 must implement the method %2 of %3.</source>
            <translation>%1 muss die Methode %2 von %3 implementieren.</translation>
        </message>
        <message>
            <source>%1 must implement the GET of the property %2 of %3.</source>
            <translation>%1 muss das GET der Eigenschaft %2 von %3 implementieren.</translation>
        </message>
        <message>
            <source>%1 must implement the SET of the property %2 of %3.</source>
            <translation>%1 muss das SET der Eigenschaft %2 von %3 implementieren.</translation>
        </message>
        <message>
            <source>%1 implements %2, which is no interface of the project.</source>
            <translation>%1 implementiert %2, doch das ist keine Schnittstelle des Projekts.</translation>
        </message>
        <message>
            <source>This text must be one INTERFACE ... END_INTERFACE and nothing else.</source>
            <translation>Dieser Text muss genau ein INTERFACE ... END_INTERFACE sein, sonst nichts.</translation>
        </message>
        <message>
            <source>%1 cannot override %2: it is FINAL.</source>
            <translation>%1 kann %2 nicht überschreiben: %2 ist FINAL.</translation>
        </message>
        <message>
            <source>%1 must implement the ABSTRACT %2, or be ABSTRACT itself.</source>
            <translation>%1 muss das ABSTRACT %2 implementieren oder selbst ABSTRACT sein.</translation>
        </message>
        <message>
            <source>%1 is a type of Beremiz's SVGHMI, which IEC Studio does not have: its variables are read as %2 and no HMI is shown.</source>
            <translation>%1 ist ein Typ von Beremiz' SVGHMI, das IEC Studio nicht hat: seine Variablen werden als %2 gelesen, und keine HMI wird angezeigt.</translation>
        </message>
        <message>
            <source>watch and write them in the watch pane instead</source>
            <translation>beobachten und schreiben Sie sie stattdessen im Fenster „Beobachtung“</translation>
        </message>
        <message>
            <source>The chart of %1 cannot be written as textual SFC (it is incomplete, or has macro steps, actions written in a step or conditions drawn as networks); it was left out.</source>
            <translation>Das Diagramm von %1 lässt sich nicht als textuelle AS schreiben (es ist unvollständig oder hat Makroschritte, in einem Schritt geschriebene Aktionen oder als Netzwerk gezeichnete Bedingungen); es wurde weggelassen.</translation>
        </message>
        <message>
            <source>%1 of %2: IEC 61131-3 shifts bit strings only; as in CODESYS, its bits are shifted as those of a %3.</source>
            <translation>%1 von %2: IEC 61131-3 schiebt nur Bitfolgen; wie in CODESYS werden seine Bits wie die eines %3 geschoben.</translation>
        </message>
        <message>
            <source>The file is not UTF-8: it was read as Windows-1252, the code page CoDeSys 2.3 writes, so that its umlauts and other special characters are kept.</source>
            <translation>Die Datei ist nicht in UTF-8: Sie wurde als Windows-1252 gelesen, die Codepage, in der CoDeSys 2.3 schreibt, damit ihre Umlaute und anderen Sonderzeichen erhalten bleiben.</translation>
        </message>
        <message>
            <source>%1 is a variable, not a constant: it has no value before the program runs.</source>
            <translation>%1 ist eine Variable, keine Konstante: Sie hat keinen Wert, bevor das Programm läuft.</translation>
        </message>
        <message>
            <source>declare it in VAR CONSTANT with an initial value</source>
            <translation>deklarieren Sie sie in VAR CONSTANT mit einem Anfangswert</translation>
        </message>
        <message>
            <source>CoDeSys 2.3 exported this %1 body in its own graphical form, which IEC Studio does not read; it is kept below as a comment. Export the POU from CoDeSys as PLCopen XML to open it as a diagram.</source>
            <translation>CoDeSys 2.3 hat diesen %1-Rumpf in seiner eigenen grafischen Form exportiert, die IEC Studio nicht liest; er bleibt unten als Kommentar erhalten. Exportieren Sie den Baustein aus CoDeSys als PLCopen XML, um ihn als Diagramm zu öffnen.</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Condition</name>
        <message>
            <source>The condition is nested too deeply.</source>
            <translation>Die Bedingung ist zu tief verschachtelt.</translation>
        </message>
        <message>
            <source>A condition can only read variables and compare them; it cannot call anything.</source>
            <translation>Eine Bedingung kann nur Variablen lesen und vergleichen, nichts aufrufen.</translation>
        </message>
        <message>
            <source>There is no variable called %1 here.</source>
            <translation>Hier gibt es keine Variable namens %1.</translation>
        </message>
        <message>
            <source>Text cannot be calculated with.</source>
            <translation>Mit Text kann nicht gerechnet werden.</translation>
        </message>
        <message>
            <source>AND, OR, XOR and NOT need TRUE or FALSE here.</source>
            <translation>AND, OR, XOR und NOT brauchen hier TRUE oder FALSE.</translation>
        </message>
        <message>
            <source>The condition divides by zero.</source>
            <translation>Die Bedingung teilt durch null.</translation>
        </message>
        <message>
            <source>The operator %1 cannot be used in a condition.</source>
            <translation>Der Operator %1 ist in einer Bedingung nicht erlaubt.</translation>
        </message>
        <message>
            <source>This is not an expression: %1</source>
            <translation>Das ist kein Ausdruck: %1</translation>
        </message>
        <message>
            <source>The condition must be TRUE or FALSE, not a number or a text.</source>
            <translation>Die Bedingung muss TRUE oder FALSE sein, keine Zahl und kein Text.</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Runtime</name>
        <message>
            <source>Integer division by zero.</source>
            <translation>Ganzzahldivision durch null.</translation>
        </message>
        <message>
            <source>Array index out of range.</source>
            <translation>Feldindex außerhalb des Bereichs.</translation>
        </message>
        <message>
            <source>The text does not fit into the string variable.</source>
            <translation>Der Text passt nicht in die String-Variable.</translation>
        </message>
        <message>
            <source>The program ran too long in one cycle; is there an endless loop?</source>
            <translation>Das Programm lief in einem Zyklus zu lange; gibt es eine Endlosschleife?</translation>
        </message>
        <message>
            <source>Calls are nested too deeply.</source>
            <translation>Aufrufe sind zu tief verschachtelt.</translation>
        </message>
        <message>
            <source>The program cannot run (it did not compile).</source>
            <translation>Das Programm kann nicht laufen (es wurde nicht übersetzt).</translation>
        </message>
        <message>
            <source>A value outside the subrange of its type was assigned.</source>
            <translation>Ein Wert außerhalb des Unterbereichs seines Typs wurde zugewiesen.</translation>
        </message>
        <message>
            <source>A pointer or reference that points nowhere (0) was used.</source>
            <translation>Ein Pointer oder eine Referenz, die ins Leere (0) zeigt, wurde verwendet.</translation>
        </message>
        <message>
            <source>A pointer that points outside the program's memory was used.</source>
            <translation>Ein Pointer, der außerhalb des Programmspeichers zeigt, wurde verwendet.</translation>
        </message>
        <message>
            <source>There is no variable called %1.</source>
            <translation>Es gibt keine Variable namens %1.</translation>
        </message>
        <message>
            <source>%1 is out of the range of %2 (%3..%4).</source>
            <translation>%1 liegt außerhalb des Wertebereichs von %2 (%3..%4).</translation>
        </message>
        <message>
            <source>%1 does not fit the %2 bits of %3.</source>
            <translation>%1 passt nicht in die %2 Bits von %3.</translation>
        </message>
        <message>
            <source>'%1' is not a valid %2.</source>
            <translation>'%1' ist kein gültiger Wert vom Typ %2.</translation>
        </message>
        <message>
            <source>The text is longer than the %1 characters of the string.</source>
            <translation>Der Text ist länger als die %1 Zeichen des Strings.</translation>
        </message>
        <message>
            <source>Only elementary variables and strings can be written.</source>
            <translation>Nur elementare Variablen und Strings können geschrieben werden.</translation>
        </message>
        <message>
            <source>%1 is out of the range of REAL (about ±3.4E38).</source>
            <translation>%1 liegt außerhalb des Wertebereichs von REAL (etwa ±3,4E38).</translation>
        </message>
        <message>
            <source>%1 is out of the range of LREAL (about ±1.8E308).</source>
            <translation>%1 liegt außerhalb des Wertebereichs von LREAL (etwa ±1,8E308).</translation>
        </message>
        <message>
            <source>The program halted.</source>
            <translation>Das Programm ist angehalten.</translation>
        </message>
        <message>
            <source>A STRING cannot hold %1 (it holds the characters of Windows-1252); use a WSTRING.</source>
            <translation>Ein STRING kann %1 nicht aufnehmen (er enthält die Zeichen von Windows-1252); verwenden Sie einen WSTRING.</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::Trace</name>
        <message>
            <source>%1 is a %2: only BOOL, numbers, bit strings, enumerations, times and dates can be traced. Trace its elements or members instead.</source>
            <translation>%1 ist ein %2: nur BOOL, Zahlen, Bitfolgen, Aufzählungen, Zeiten und Datumswerte können aufgezeichnet werden. Zeichnen Sie stattdessen seine Elemente oder Komponenten auf.</translation>
        </message>
    </context>
    <context>
        <name>iec::interp::TraceRecorder</name>
        <message>
            <source>There is no variable called %1.</source>
            <translation>Es gibt keine Variable namens %1.</translation>
        </message>
        <message>
            <source>The trigger variable %1 is not a BOOL or number of the program; the trace records without a trigger.</source>
            <translation>Die Trigger-Variable %1 ist kein BOOL und keine Zahl des Programms; der Trace zeichnet ohne Trigger auf.</translation>
        </message>
        <message>
            <source>The record condition is not an expression: %1</source>
            <translation>Die Aufzeichnungsbedingung ist kein Ausdruck: %1</translation>
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
        <name>iec::model::SaveFile</name>
        <message>
            <source>the folder %1 does not exist</source>
            <translation>der Ordner %1 existiert nicht</translation>
        </message>
        <message>
            <source>a folder of that name is in the way</source>
            <translation>ein Ordner mit diesem Namen ist im Weg</translation>
        </message>
        <message>
            <source>the folder %1 is read-only, or you may not write in it</source>
            <translation>der Ordner %1 ist schreibgeschützt, oder Sie dürfen darin nicht schreiben</translation>
        </message>
        <message>
            <source>the file is read-only</source>
            <translation>die Datei ist schreibgeschützt</translation>
        </message>
        <message>
            <source>the disk is full</source>
            <translation>der Datenträger ist voll</translation>
        </message>
        <message>
            <source>the file would be larger than the system allows</source>
            <translation>die Datei wäre größer, als das System erlaubt</translation>
        </message>
        <message>
            <source>%1 was not saved: %2. The file on the disk is unchanged.</source>
            <translation>%1 wurde nicht gespeichert: %2. Die Datei auf dem Datenträger ist unverändert.</translation>
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
        <name>iec::model::SetInstancesCommand</name>
        <message>
            <source>Change configurations</source>
            <translation>Konfigurationen ändern</translation>
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
        <name>iec::model::plcopen</name>
        <message>
            <source>It is not well-formed XML: %1.</source>
            <translation>Es ist kein wohlgeformtes XML: %1.</translation>
        </message>
        <message>
            <source>It is XML with a &lt;%1&gt; root, not elements copied in IEC Studio.</source>
            <translation>Es ist XML mit dem Wurzelelement &lt;%1&gt;, keine in IEC Studio kopierten Elemente.</translation>
        </message>
        <message>
            <source>It cannot be read: %1</source>
            <translation>Es kann nicht gelesen werden: %1</translation>
        </message>
        <message>
            <source>It holds something that is not an element of a body.</source>
            <translation>Es enthält etwas, das kein Element eines Rumpfs ist.</translation>
        </message>
    </context>
    <context>
        <name>iec::model::plcopen::Reader</name>
        <message>
            <source>The elements are nested too deeply; the content below is skipped.</source>
            <translation>Die Elemente sind zu tief verschachtelt; der Inhalt darunter wird übersprungen.</translation>
        </message>
        <message>
            <source>The attribute %1="%2" of &lt;%3&gt; has an invalid value; it is kept as written.</source>
            <translation>Das Attribut %1="%2" von &lt;%3&gt; hat einen ungültigen Wert; es bleibt wie geschrieben erhalten.</translation>
        </message>
        <message>
            <source>&lt;%1&gt; lacks the required attribute '%2'.</source>
            <translation>&lt;%1&gt; fehlt das erforderliche Attribut '%2'.</translation>
        </message>
        <message>
            <source>&lt;%1&gt; lacks the required element &lt;%2&gt;.</source>
            <translation>&lt;%1&gt; fehlt das erforderliche Element &lt;%2&gt;.</translation>
        </message>
        <message>
            <source>Unknown attribute '%1' on &lt;%2&gt; is kept as it is.</source>
            <translation>Das unbekannte Attribut '%1' an &lt;%2&gt; bleibt unverändert erhalten.</translation>
        </message>
        <message>
            <source>Unknown attribute '%1' on &lt;%2&gt; is ignored.</source>
            <translation>Das unbekannte Attribut '%1' an &lt;%2&gt; wird ignoriert.</translation>
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
            <source>The namespace '%1' is not PLCopen TC6 XML 2.01; the file is read anyway.</source>
            <translation>Der Namensraum '%1' ist nicht PLCopen TC6 XML 2.01; die Datei wird trotzdem gelesen.</translation>
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
        <message>
            <source>This &lt;action&gt; has no localId; it was given %1.</source>
            <translation>Diese &lt;action&gt; hat keine localId; sie erhielt %1.</translation>
        </message>
        <message>
            <source>This &lt;action&gt; has no position; it is placed at (0, 0).</source>
            <translation>Diese &lt;action&gt; hat keine Position; sie wird bei (0, 0) platziert.</translation>
        </message>
        <message>
            <source>&lt;pouInstance&gt; names its POU with 'type'; PLCopen calls it 'typeName', which it is written as.</source>
            <translation>&lt;pouInstance&gt; nennt seine POE mit 'type'; PLCopen nennt es 'typeName', und so wird es geschrieben.</translation>
        </message>
        <message>
            <source>creationDateTime '%1' has a space where XML wants a 'T'; it is written as '%2'.</source>
            <translation>creationDateTime '%1' hat ein Leerzeichen, wo XML ein 'T' verlangt; es wird als '%2' geschrieben.</translation>
        </message>
        <message>
            <source>Characters XML does not allow (control characters, U+FFFE or U+FFFF) were left out of the file, %1 in all, so that the project is saved as valid XML.</source>
            <translation>Zeichen, die XML nicht erlaubt (Steuerzeichen, U+FFFE oder U+FFFF), wurden aus der Datei weggelassen, insgesamt %1, damit das Projekt als gültiges XML gespeichert wird.</translation>
        </message>
        <message>
            <source>&lt;%1&gt; has the attribute %2 more than once; the first is kept.</source>
            <translation>&lt;%1&gt; hat das Attribut %2 mehrmals; das erste wird behalten.</translation>
        </message>
        <message>
            <source>&lt;%1&gt; in &lt;%2&gt; is more than the file format allows there; it is kept as it is, but not read.</source>
            <translation>&lt;%1&gt; in &lt;%2&gt; ist mehr, als das Dateiformat dort erlaubt; es wird unverändert behalten, aber nicht gelesen.</translation>
        </message>
        <message>
            <source>&lt;%1&gt; in &lt;%2&gt; is more than the file format allows there; it is ignored.</source>
            <translation>&lt;%1&gt; in &lt;%2&gt; ist mehr, als das Dateiformat dort erlaubt; es wird ignoriert.</translation>
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
