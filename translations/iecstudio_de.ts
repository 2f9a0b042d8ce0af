<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>iec::app::MainWindow</name>
    <message>
        <source>IEC Studio</source>
        <translation>IEC Studio</translation>
    </message>
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
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
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
        <source>Open a POU from the project tree to edit it.</source>
        <translation>Öffnen Sie einen Baustein im Projektbaum, um ihn zu bearbeiten.</translation>
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
    <name>iec::model::AddPouCommand</name>
    <message>
        <source>Add POU %1</source>
        <translation>Baustein %1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>iec::model::RenamePouCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
</TS>
