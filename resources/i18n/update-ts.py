#!/usr/bin/env python3
"""Brings a translation file up to date with the sources: every tr() of ui/,
every TAIWA_TRANSLATE_NOOP of core/ (the core's message templates and words
in context "taiwa::msg"), the modules' description files
(core/modules/*/*.module.json and core/modules/shared_fields.json: the
palette words, context "taiwa::ui::ModulePalette"; the form's labels, help
lines and placeholders, context "taiwa::ui::FieldSpec"; its codes' meanings,
context "taiwa::CoreTexts" as ui/core_texts.cpp's) and every label of the
module drawings (core/modules/*/*.svg, context "taiwa::Drawing"),
translations kept, texts no longer in the sources dropped.

    python3 resources/i18n/update-ts.py resources/i18n/taiwa_ja.ts

lupdate 6.4 names the station's classes without their namespace while the
program looks them up as taiwa::ui::Class, so lupdate writes a fresh file,
its class contexts are qualified, and the translations of the old file are
carried over by context and source text. New texts come out as
type="unfinished"; tests/test_translations.cpp fails while any is left.
"""
import json
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

LUPDATE = "/usr/lib/qt6/bin/lupdate"


def messages(tree):
    for ctx in tree.getroot().findall("context"):
        name = ctx.find("name").text
        for m in ctx.findall("message"):
            yield name, m


def drawing_labels(root: Path):
    """The labels of the module drawings that have a word (symbols such as P1, r1, T have none), in file order."""
    seen = []
    for svg in sorted((root / "core" / "modules").glob("*/*.svg")):
        for e in ET.parse(svg).iter("{http://www.w3.org/2000/svg}text"):
            text = "".join(e.itertext()).strip()
            if re.search(r"[A-Za-z]{2}", text) and text not in seen:
                seen.append(text)
    return seen


def module_texts(root: Path):
    """The palette words, and the form's labels that have a word (P1 X, X1 have none), placeholders, help
    lines and code meanings that have a word (+X has none), of the module descriptions, in file order:
    {context: [texts]}."""
    found = {"taiwa::ui::ModulePalette": [], "taiwa::ui::FieldSpec": [], "taiwa::CoreTexts": []}
    modules = root / "core" / "modules"
    for path in [modules / "shared_fields.json"] + sorted(modules.glob("*/*.module.json")):
        data = json.loads(path.read_text(encoding="utf-8"))
        texts = [("taiwa::ui::ModulePalette", data.get("palette", ""))]
        for entry in data["fields"] if "fields" in data else data.values():
            for key in ("label", "placeholder", "help"):
                text = entry.get(key, "")
                if key != "label" or re.search(r"[A-Za-z]{2}", text):
                    texts.append(("taiwa::ui::FieldSpec", text))
            for code in entry.get("codes", []):
                if isinstance(code, list) and re.search(r"[A-Za-z]{2}", code[1]):
                    texts.append(("taiwa::CoreTexts", code[1]))
        for context, text in texts:
            if text and text not in found[context]:
                found[context].append(text)
    return found


def add_module_texts(tree, root: Path):
    """The module descriptions' texts into their contexts, beside what lupdate found there."""
    for name, texts in module_texts(root).items():
        ctx = next((c for c in tree.getroot().findall("context") if c.find("name").text == name), None)
        if ctx is None:
            ctx = ET.SubElement(tree.getroot(), "context")
            ET.SubElement(ctx, "name").text = name
        have = {m.find("source").text for m in ctx.findall("message")}
        for text in texts:
            if text in have:
                continue
            m = ET.SubElement(ctx, "message")
            ET.SubElement(m, "source").text = text
            ET.SubElement(m, "translation")


def add_drawing_labels(tree, root: Path):
    ctx = ET.SubElement(tree.getroot(), "context")
    ET.SubElement(ctx, "name").text = "taiwa::Drawing"
    for text in drawing_labels(root):
        m = ET.SubElement(ctx, "message")
        ET.SubElement(m, "source").text = text
        ET.SubElement(m, "translation")


def main(ts: str) -> int:
    root = Path(__file__).resolve().parents[2]
    target = Path(ts).resolve()
    old = ET.parse(target)
    language = old.getroot().get("language")
    with tempfile.TemporaryDirectory() as tmp:
        fresh = Path(tmp) / target.name
        fresh.write_text(f'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n<TS version="2.1" language="{language}"></TS>\n',
                         encoding="utf-8")
        run = subprocess.run([LUPDATE, "-no-obsolete", "-locations", "none", "-tr-function-alias",
                              "QT_TRANSLATE_NOOP+=TAIWA_TRANSLATE_NOOP", str(root / "ui"), str(root / "core"),
                              "-ts", str(fresh)], capture_output=True, text=True)
        if run.returncode != 0:
            sys.stderr.write(run.stdout + run.stderr)
            return run.returncode
        text = re.sub(r"<name>([A-Z][A-Za-z]+)</name>",
                      lambda m: m.group(0) if m.group(1) == "QObject" else f"<name>taiwa::ui::{m.group(1)}</name>",
                      fresh.read_text(encoding="utf-8"))
        new = ET.ElementTree(ET.fromstring(text))
    add_module_texts(new, root)
    add_drawing_labels(new, root)
    known = {(name, m.find("source").text): m.find("translation") for name, m in messages(old)}
    unfinished = 0
    for name, m in messages(new):
        was = known.get((name, m.find("source").text))
        tr = m.find("translation")
        if was is not None and was.get("type") != "unfinished":
            m.remove(tr)
            m.append(was)
        else:
            tr.set("type", "unfinished")
            unfinished += 1
    ET.indent(new, "    ")
    body = ET.tostring(new.getroot(), encoding="unicode")
    header = ('<?xml version="1.0" encoding="utf-8"?>\n<!-- Texts of the station window (lupdate from ui/ and core/, the '
              'module descriptions and the labels of the module drawings, by resources/i18n/update-ts.py, translated by hand); compiled to .qm by lrelease at build time. -->\n'
              '<!DOCTYPE TS>\n')
    target.write_text(header + body + "\n", encoding="utf-8")
    print(f"{target.name}: {sum(1 for _ in messages(new))} texts, {unfinished} untranslated")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
