// The core's messages in the station's language: a check's refusal, a
// warning, a tool's name ("T12 (flat end mill Ø6 mm)"), a module drawing's
// labels. The core writes English from fmt templates marked in context
// "taiwa::msg" (model/translate_noop.h); the station finds the template an
// English message was made from, translates it and puts the message's
// arguments back in, themselves translated when they are words or
// messages. docs/station.md, "Languages", explains the design.
#pragma once

#include "model/diagnostic.h"
#include "model/local_name.h"
#include "model/tool.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <functional>
#include <string>
#include <vector>

namespace taiwa::ui {

// The message in the station's language; as it is when the station speaks
// English or no template of the catalogue made it.
QString coreMessage(const std::string& english);
// A diagnostic as `taiwa check` prints it ("JOB: unit N (MODULE) field:
// message", model/diagnostic.h format()), in the station's language: its
// words, field and message translated; byte for byte format() in English.
QString diagnosticText(const std::string& job, const Diagnostic& d);
// The field a diagnostic names as the station shows it, in its language: a
// unit's field by its form's label ("T (depth)"), a turned profile's cell by
// its table, row and column ("allowance row 2, Width"), else fieldText().
QString diagnosticField(const Diagnostic& d);
// A tool as the messages name it ("T12 (フラットエンドミル Ø6 mm)") and a tool kind alone.
QString toolName(const Tool& tool);
QString toolKind(ToolType type);
// A name of the data (a material's description, a machine's or a tool's
// name) in the station's language: its names map's entry, else the text.
QString localName(const std::string& text, const LocalNames& names);
QString localToolName(const Tool& tool);
// The tools whose names the core's messages may quote ("T21 (Flat end mill
// 2 mm carbide) is the nearest"): each one's name is shown in the station's
// language there. The default library's tools are known from the start.
void knowToolNames(const std::vector<Tool>& tools);
// A module drawing (SVG) with its labels translated (context "taiwa::Drawing").
QByteArray translatedDrawing(const QByteArray& svg);

// The matching, exposed for the tests: `sources` are English templates
// (fmt's "{}" placeholders); `translate` gives a template's or a word's
// translation (the source itself when there is none).
QString translateMessage(const QString& english, const QStringList& sources,
                         const std::function<QString(const QString&)>& translate);
// The templates the station matches against: the sources of context
// "taiwa::msg" in the language's catalogue (resources/i18n/taiwa_xx.ts,
// compiled in); empty when the station speaks English.
const QStringList& messageSources();

} // namespace taiwa::ui
