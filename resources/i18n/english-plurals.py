#!/usr/bin/env python3
"""Writes resources/i18n/taiwa_en.ts: the English forms of the station's
texts that count (tr("%n block(s)", "", n)), so that English reads
"1 block" and "1084 blocks" rather than "1084 block(s)". English is the
source language, so this catalogue holds the plural messages only; their
contexts and sources are taken from the Japanese catalogue, which
update-ts.py keeps complete. Run it after update-ts.py:

    python3 resources/i18n/english-plurals.py

"word(s)" becomes "word" for one and "words" for more; a source with no
"(s)" ("found %n faults") is given its singular by SINGULAR below.
"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

# Sources whose plural is written out: their singular, whole.
SINGULAR = {
    "The verification found %n faults (the first: %1).": "The verification found %n fault (the first: %1).",
}


def forms(source: str):
    if source in SINGULAR:
        return SINGULAR[source], source
    if "(s)" not in source:
        sys.exit(f"english-plurals: no '(s)' in '{source}': add its singular to SINGULAR")
    return source.replace("(s)", ""), source.replace("(s)", "s")


def main() -> int:
    here = Path(__file__).resolve().parent
    ja = ET.parse(here / "taiwa_ja.ts")
    root = ET.Element("TS", {"version": "2.1", "language": "en"})
    for ctx in ja.getroot().findall("context"):
        plural = [m for m in ctx.findall("message") if m.get("numerus") == "yes"]
        if not plural:
            continue
        out = ET.SubElement(root, "context")
        ET.SubElement(out, "name").text = ctx.find("name").text
        for m in plural:
            source = m.find("source").text
            one, many = forms(source)
            msg = ET.SubElement(out, "message", {"numerus": "yes"})
            ET.SubElement(msg, "source").text = source
            tr = ET.SubElement(msg, "translation")
            for text in (one, many):
                ET.SubElement(tr, "numerusform").text = text
    ET.indent(root, space="    ")
    text = '<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n' + ET.tostring(root, encoding="unicode") + "\n"
    (here / "taiwa_en.ts").write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
