// Reading the modules' description files (module_text.h): the JSON of
// core/modules/*/*.module.json and core/modules/shared_fields.json,
// compiled in by core/builtin_data.cmake.
#include "modules/module_text.h"

#include "io/json_document.h"
#include "module_texts.h"  // generated: builtin::kModuleTexts

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace taiwa::form {

namespace {

using nlohmann::json;

[[noreturn]] void bad(std::string_view source, const std::string& what)
{
    throw std::logic_error(fmt::format("module description {}: {}", source, what));
}

std::string textAt(const json& entry, const char* key, std::string_view source, const std::string& where)
{
    const auto it = entry.find(key);
    if (it == entry.end()) return {};
    if (!it->is_string()) bad(source, fmt::format("{}: \"{}\" is not a text", where, key));
    return it->get<std::string>();
}

FieldText field(const json& entry, std::string_view source, const std::string& where, bool mayShare = true)
{
    static constexpr std::array kKnown{"key", "label", "bind", "checks", "placeholder", "codes", "symbol", "help", "shared"};
    if (!entry.is_object()) bad(source, where + " is not an object");
    for (const auto& [name, value] : entry.items())
        if (std::find(kKnown.begin(), kKnown.end(), name) == kKnown.end() || (name == "shared" && !mayShare))
            bad(source, fmt::format("{} has \"{}\", which a field does not have", where, name));
    FieldText f;
    f.key = textAt(entry, "key", source, where);
    f.label = textAt(entry, "label", source, where);
    f.bind = textAt(entry, "bind", source, where);
    f.placeholder = textAt(entry, "placeholder", source, where);
    f.symbol = textAt(entry, "symbol", source, where);
    f.help = textAt(entry, "help", source, where);
    if (const auto it = entry.find("checks"); it != entry.end()) {
        if (!it->is_array() || it->empty()) bad(source, where + ": \"checks\" is not a list of names");
        for (const json& c : *it) {
            if (!c.is_string()) bad(source, where + ": a check field is not a text");
            f.checks.push_back(c.get<std::string>());
        }
    }
    if (const auto it = entry.find("codes"); it != entry.end()) {
        if (!it->is_array() || it->empty()) bad(source, where + ": \"codes\" is not a list of codes");
        // [value, "meaning"], or a value alone: a shared field's code, its meaning the shared entry's.
        for (const json& c : *it) {
            if (c.is_number_integer())
                f.codes.emplace_back(c.get<int>(), std::string());
            else if (c.is_array() && c.size() == 2 && c[0].is_number_integer() && c[1].is_string())
                f.codes.emplace_back(c[0].get<int>(), c[1].get<std::string>());
            else
                bad(source, where + ": a code is not [value, \"meaning\"] nor a value");
            for (std::size_t k = 0; k + 1 < f.codes.size(); ++k)
                if (f.codes[k].first == f.codes.back().first)
                    bad(source, fmt::format("{}: code {} twice", where, f.codes.back().first));
        }
    }
    return f;
}

// The job file's parser (io/json_document.h): it also finds a key given
// twice in one object, which nlohmann alone would keep the last of. Its
// sentence for broken JSON is a job file's ("not a job file: …"): a broken
// description is said in nlohmann's words.
json parsed(std::string_view text, std::string_view source)
{
    io::ParsedDocument doc = io::parseDocument(text);
    if (!doc.root) {
        try {
            [[maybe_unused]] const json again = json::parse(text);
        } catch (const json::exception& e) {
            bad(source, e.what());
        }
        bad(source, doc.error);  // nested deeper than the job file's limit
    }
    if (!doc.repeatedKeys.empty()) {
        const io::JsonPath& twice = doc.repeatedKeys.front();
        bad(source, fmt::format("{} is given twice", io::joinPath(twice.begin(), twice.end())));
    }
    return std::move(*doc.root);
}

}  // namespace

ModuleText readModuleText(std::string_view text, std::string_view source, std::string_view sharedText)
{
    const json doc = parsed(text, source);
    const json shared = parsed(sharedText, "shared_fields.json");
    if (!doc.is_object() || !doc.contains("fields") || !doc["fields"].is_array())
        bad(source, "not an object with a list \"fields\"");
    for (const auto& [name, value] : doc.items())
        if (name != "palette" && name != "outline" && name != "fields")
            bad(source, fmt::format("\"{}\" is not a part of a module's description", name));
    ModuleText out;
    out.palette = textAt(doc, "palette", source, "the description");
    out.outlineField = textAt(doc, "outline", source, "the description");
    if (out.palette.empty() || out.outlineField.empty()) bad(source, "no \"palette\" or no \"outline\"");
    for (const json& entry : doc["fields"]) {
        const std::string where = fmt::format("field {}", out.fields.size() + 1);
        FieldText f = field(entry, source, where);
        if (const std::string name = textAt(entry, "shared", source, where); !name.empty()) {
            // The shared field with what the entry names put over it; a code
            // given by its value alone takes the shared field's meaning.
            const auto it = shared.find(name);
            if (it == shared.end()) bad(source, fmt::format("{}: no shared field \"{}\"", where, name));
            const FieldText base = field(*it, "shared_fields.json", name, false);
            json merged = *it;
            merged.update(entry);
            merged.erase("shared");
            f = field(merged, source, where);
            for (auto& [value, meaning] : f.codes)
                for (const auto& [baseValue, baseMeaning] : base.codes)
                    if (meaning.empty() && value == baseValue) meaning = baseMeaning;
        }
        if (f.key.empty() || f.label.empty()) bad(source, where + " has no key or no label");
        for (const auto& [value, meaning] : f.codes)
            if (meaning.empty()) bad(source, fmt::format("{} ({}): code {} has no meaning", where, f.key, value));
        for (const FieldText& g : out.fields)
            if (g.key == f.key) bad(source, fmt::format("{}: key \"{}\" twice", where, f.key));
        if (f.bind.empty()) f.bind = f.key;
        if (f.checks.empty()) f.checks = {f.key};
        out.fields.push_back(std::move(f));
    }
    return out;
}

std::vector<std::string> shippedModuleFolders()
{
    std::vector<std::string> folders;
    for (const builtin::ModuleTextFile& f : builtin::kModuleTexts)
        if (std::string_view(f.folder) != "modules") folders.emplace_back(f.folder);
    return folders;
}

ModuleText shippedModuleText(std::string_view folder)
{
    std::string_view shared = "{}";
    for (const builtin::ModuleTextFile& f : builtin::kModuleTexts)
        if (std::string_view(f.folder) == "modules") shared = f.text;
    for (const builtin::ModuleTextFile& f : builtin::kModuleTexts)
        if (f.folder == folder) return readModuleText(f.text, f.source, shared);
    throw std::logic_error(fmt::format("no module description core/modules/{0}/{0}.module.json", folder));
}

}  // namespace taiwa::form
