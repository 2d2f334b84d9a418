// What a module says to the operator, as data: its palette button's words,
// the field an overlap is reported on, and its form, each field's key,
// label, check fields, codes, help line and drawing symbol. Read from the
// module's description file (core/modules/<folder>/<folder>.module.json,
// compiled in; docs/modules.md "A module's description file"). Its door
// (ModuleKindOf, modules/module_kind.h) binds each field to the member it
// reads and writes (modules/form_binding.h). The palette words are source
// texts of the translation in context "taiwa::ui::ModulePalette"; labels,
// placeholders and help lines in "taiwa::ui::FieldSpec"; the codes'
// meanings in "taiwa::CoreTexts" (resources/i18n/update-ts.py reads them
// from the files).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace taiwa::form {

struct FieldText {
    std::string key;                // widget objectName suffix: "P1.x", "depth", "U"
    std::string label;              // "T (depth)"
    std::string bind;               // the job-file key it reads and writes ("corner.x": a point's X); default key
    std::vector<std::string> checks;  // the checks' field names shown on it; default {key}
    std::string placeholder;        // an optional number or a text: what empty means
    std::vector<std::pair<int, std::string>> codes;  // a code: each value and its meaning
    std::string symbol;             // the id of its symbol in the module's drawing, or empty
    std::string help;               // what the value is, in one line
};

struct ModuleText {
    std::string palette;       // "Add M4 pocket"
    std::string outlineField;  // "corners"
    std::vector<FieldText> fields;
};

// A description file's text: {"palette": …, "outline": …, "fields": […]}.
// A field {"shared": "pocketDepth", …} starts from the entry of that name
// in `sharedText` ({"pocketDepth": {…}, …}) and overrides what it names; its
// codes may be values alone, their meanings the shared entry's.
// Shipped data: a text that is not such a description is a bug, thrown as
// std::logic_error naming `source` and the entry.
ModuleText readModuleText(std::string_view text, std::string_view source, std::string_view sharedText = "{}");

// The shipped description of the module in core/modules/<folder>/ (folder
// "side"), its shared fields from core/modules/shared_fields.json.
ModuleText shippedModuleText(std::string_view folder);
// The folders of every shipped description (each module's: "area", "cp", …).
std::vector<std::string> shippedModuleFolders();

}  // namespace taiwa::form
