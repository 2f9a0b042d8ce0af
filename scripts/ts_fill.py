#!/usr/bin/env python3
"""Fill translations into a Qt .ts file from a JSON object {source text: translation}.

A translation given as a list fills the plural forms of a %n message, in the order Qt uses for
the language (German: singular, plural; Chinese: one form).

Usage: scripts/ts_fill.py translations/iecstudio_de.ts MAPPING.json
Only messages whose source is in the mapping change; they lose type="unfinished".
Reports the messages of the file that are still unfinished afterwards.
"""
import json
import sys
import xml.etree.ElementTree as ET


def main() -> int:
    ts_path, mapping_path = sys.argv[1], sys.argv[2]
    with open(mapping_path, encoding="utf-8") as f:
        mapping = json.load(f)
    tree = ET.parse(ts_path)
    unfinished = []
    for message in tree.getroot().iter("message"):
        source = message.findtext("source")
        translation = message.find("translation")
        if translation is None:
            continue
        if source in mapping:
            value = mapping[source]
            if isinstance(value, list):
                for form in list(translation):
                    translation.remove(form)
                translation.text = None
                for text in value:
                    ET.SubElement(translation, "numerusform").text = text
            else:
                translation.text = value
            translation.attrib.pop("type", None)
        if translation.get("type") == "unfinished":
            unfinished.append(source)
    with open(ts_path, "w", encoding="utf-8") as f:
        f.write('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
        ET.indent(tree, space="    ")
        f.write(ET.tostring(tree.getroot(), encoding="unicode"))
        f.write("\n")
    for source in unfinished:
        print(f"unfinished: {source}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
